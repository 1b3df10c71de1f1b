#include "Triangulation.h"

#include "Predicates.h"

#include <algorithm>
#include <cstdint>

namespace osm
{

int Triangulation::addPoint(const Point& p)
{
  points.push_back(p);
  vtri.push_back(-1);
  return static_cast<int>(points.size()) - 1;
}

int Triangulation::newTriangle(int a, int b, int c)
{
  int t;
  if (!freeSlots.empty())
  {
    t = freeSlots.back();
    freeSlots.pop_back();
  }
  else
  {
    // push_back is inline; resize() is an out-of-line call at every new slot.
    t = slots();
    for (int k = 0; k < 3; ++k)
    {
      tv.push_back(-1);
      tn.push_back(-1);
    }
    mark.push_back(0);
  }
  tv[3 * t] = a;
  tv[3 * t + 1] = b;
  tv[3 * t + 2] = c;
  tn[3 * t] = tn[3 * t + 1] = tn[3 * t + 2] = -1;
  vtri[a] = vtri[b] = vtri[c] = t;
  return t;
}

void Triangulation::reserve(std::size_t pointCount, std::size_t triangleCount)
{
  points.reserve(pointCount);
  vtri.reserve(pointCount);
  tv.reserve(3 * triangleCount);
  tn.reserve(3 * triangleCount);
  mark.reserve(triangleCount);
}

void Triangulation::releaseTriangles()
{
  std::vector<int>().swap(tv);
  std::vector<int>().swap(tn);
  std::vector<int>().swap(vtri);
  std::vector<int>().swap(freeSlots);
  std::vector<std::uint32_t>().swap(mark);
}

void Triangulation::freeTriangle(int t)
{
  tv[3 * t] = tv[3 * t + 1] = tv[3 * t + 2] = -1;
  freeSlots.push_back(t);
}

int Triangulation::localIndex(int t, int v) const
{
  for (int i = 0; i < 3; ++i)
    if (tv[3 * t + i] == v)
      return i;
  return -1;
}

void Triangulation::link(int t, int u)
{
  // The shared edge is opposite the one vertex of t that u does not have.
  for (int i = 0; i < 3; ++i)
  {
    if (localIndex(u, tv[3 * t + i]) < 0)
    {
      tn[3 * t + i] = u;
      break;
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    if (localIndex(t, tv[3 * u + i]) < 0)
    {
      tn[3 * u + i] = t;
      break;
    }
  }
}

int Triangulation::locate(const Point& p, int t, int* exitEdge) const
{
  // Visibility walk. It terminates on Delaunay triangulations; the step
  // counter rotates the first edge tried, which keeps it deterministic. A walk
  // longer than the number of triangles can only mean a broken mesh: give up
  // (-2) rather than hang.
  const auto maxSteps = static_cast<unsigned>(slots()) + 3;
  for (unsigned step = 0;; ++step)
  {
    if (step > maxSteps)
      return -2;
    bool moved = false;
    for (int k = 0; k < 3; ++k)
    {
      const int i = static_cast<int>((k + step) % 3);
      const Point& a = points[tv[3 * t + (i + 1) % 3]];
      const Point& b = points[tv[3 * t + (i + 2) % 3]];
      if (orient2d(a, b, p) < 0)
      {
        const int next = tn[3 * t + i];
        if (next < 0)
        {
          if (exitEdge)
            *exitEdge = 3 * t + i;
          return -1;
        }
        t = next;
        moved = true;
        break;
      }
    }
    if (!moved)
      return t;
  }
}

bool Triangulation::cavityOf(const Point& p, int start, Cavity& cavity) const
{
  cavity.triangles.clear();
  cavity.boundary.clear();
  for (int i = 0; i < 3; ++i)
    if (vertex(start, i) == p)
      return false;
  // Two stamps per search: in the cavity, and tested and found outside it.
  if (markStamp > UINT32_MAX - 2)
  {
    std::fill(mark.begin(), mark.end(), 0);
    markStamp = 0;
  }
  const std::uint32_t in = ++markStamp, out = ++markStamp;
  // p lies in the closure of start, hence strictly inside its circumcircle.
  cavity.triangles.push_back(start);
  mark[start] = in;
  // Each edge is classified when its cavity triangle is searched, so the
  // boundary comes out in cavity order, edge by edge.
  for (std::size_t k = 0; k < cavity.triangles.size(); ++k)
  {
    const int t = cavity.triangles[k];
    for (int i = 0; i < 3; ++i)
    {
      const int u = tn[3 * t + i];
      if (u >= 0 && mark[u] == in)
        continue;
      if (u >= 0 && mark[u] != out)
      {
        if (incircle(vertex(u, 0), vertex(u, 1), vertex(u, 2), p) > 0)
        {
          mark[u] = in;
          cavity.triangles.push_back(u);
          continue;
        }
        mark[u] = out;
      }
      cavity.boundary.push_back(3 * t + i);
    }
  }
  return true;
}

bool Triangulation::insertIntoCavity(int v, const Cavity& cavity, std::vector<int>& created)
{
  created.clear();
  const Point& p = points[v];
  // Record the outside neighbours before the cavity slots are recycled.
  fan.clear();
  for (int e : cavity.boundary)
  {
    const int t = e / 3, i = e % 3;
    const int u = tn[e];
    const double o = orient2d(vertex(t, (i + 1) % 3), vertex(t, (i + 2) % 3), p);
    if (o < 0 || (o == 0 && u >= 0))
      return false; // not star-shaped: refuse rather than tangle the mesh
    if (o == 0)
      continue; // p splits this hull edge: it stays open
    // Two triangles share at most one edge, so the outside triangle's link
    // back to t is the one across (a, b). Found now, before slots are recycled.
    int link = -1;
    if (u >= 0)
      for (int j = 0; j < 3; ++j)
        if (tn[3 * u + j] == t)
          link = 3 * u + j;
    fan.push_back({ tv[3 * t + (i + 1) % 3], tv[3 * t + (i + 2) % 3], u, link });
  }
  for (int t : cavity.triangles)
    freeTriangle(t);
  if (fanByVertex.size() < points.size())
    fanByVertex.resize(2 * points.size(), -1); // not at every new point
  for (const FanTriangle& f : fan)
  {
    const int t = newTriangle(f.a, f.b, v);
    created.push_back(t);
    // Edge (a, b) is opposite v (local index 2).
    tn[3 * t + 2] = f.outside;
    if (f.outsideLink >= 0)
      tn[f.outsideLink] = t;
    fanByVertex[f.a] = t; // triangle whose edge (v, a) ... found via vertex a
  }
  // Link fan neighbours: triangle (a, b, v) meets (b, c, v) across edge (b, v).
  for (int t : created)
  {
    const int b = tv[3 * t + 1];
    const int u = b < static_cast<int>(fanByVertex.size()) ? fanByVertex[b] : -1;
    if (u >= 0 && tv[3 * u] == b && tv[3 * u + 2] == v)
    {
      tn[3 * t] = u;     // opposite a: edge (b, v)
      tn[3 * u + 1] = t; // opposite b in u=(b, c, v): edge (v, b)
    }
  }
  for (const FanTriangle& f : fan)
    fanByVertex[f.a] = -1;
  // Order the fan counter-clockwise around v (chain a -> b).
  if (created.size() > 2)
  {
    int first = created.front();
    for (int t : created)
      if (tn[3 * t + 1] < 0) // no predecessor: the fan is open here (v on the hull)
        first = t;
    ordered.clear();
    for (int t = first; t >= 0 && ordered.size() < created.size(); t = tn[3 * t])
      ordered.push_back(t);
    created.swap(ordered);
  }
  return true;
}

Point circumcenterOffset(const Point& a, const Point& b, const Point& c)
{
  const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const double d = 2.0 * (bx * cy - by * cx);
  return { (cy * b2 - by * c2) / d, (bx * c2 - cx * b2) / d };
}

} // namespace osm
