#include "Triangulation.h"

#include "HugePages.h"
#include "Predicates.h"

#include <algorithm>
#include <cstdint>

namespace osm
{

int Triangulation::addPoint(const Point& p)
{
  points.push_back(p);
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
    t = slots();
    tri.push_back(Slot{ { -1, -1, -1 }, { -1, -1, -1 }, 0, -1 });
  }
  tri[t].v = { a, b, c };
  tri[t].n = { -1, -1, -1 };
  tri[t].info = -1;
  return t;
}

void Triangulation::reserve(std::size_t pointCount, std::size_t triangleCount)
{
  points.reserve(pointCount);
  tri.reserve(triangleCount);
}

void Triangulation::releaseTriangles()
{
  Array<Slot>().swap(tri);
  Array<int>().swap(freeSlots);
  releaseInsertionScratch();
}

void Triangulation::releaseInsertionScratch()
{
  Array<int>().swap(fanByVertex);
  Array<FanTriangle>().swap(fan);
  Array<int>().swap(ordered);
}

void Triangulation::freeTriangle(int t)
{
  tri[t].v = { -1, -1, -1 };
  freeSlots.push_back(t);
}

int Triangulation::localIndex(int t, int v) const
{
  for (int i = 0; i < 3; ++i)
    if (tri[t].v[i] == v)
      return i;
  return -1;
}

void Triangulation::link(int t, int u)
{
  // The shared edge is opposite the one vertex of t that u does not have.
  for (int i = 0; i < 3; ++i)
  {
    if (localIndex(u, tri[t].v[i]) < 0)
    {
      tri[t].n[i] = u;
      break;
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    if (localIndex(t, tri[u].v[i]) < 0)
    {
      tri[u].n[i] = t;
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
      const Point& a = vertex(t, (i + 1) % 3);
      const Point& b = vertex(t, (i + 2) % 3);
      if (orient2d(a, b, p) < 0)
      {
        const int next = tri[t].n[i];
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
    for (const Slot& s : tri)
      s.mark = 0;
    markStamp = 0;
  }
  const std::uint32_t in = ++markStamp, out = ++markStamp;
  // p lies in the closure of start, hence strictly inside its circumcircle.
  cavity.triangles.push_back(start);
  tri[start].mark = in;
  // Each edge is classified when its cavity triangle is searched, so the
  // boundary comes out in cavity order, edge by edge.
  for (std::size_t k = 0; k < cavity.triangles.size(); ++k)
  {
    const int t = cavity.triangles[k];
    for (int i = 0; i < 3; ++i)
    {
      const int u = tri[t].n[i];
      if (u >= 0 && tri[u].mark == in)
        continue;
      if (u >= 0 && tri[u].mark != out)
      {
        if (incircle(vertex(u, 0), vertex(u, 1), vertex(u, 2), p) > 0)
        {
          tri[u].mark = in;
          cavity.triangles.push_back(u);
          continue;
        }
        tri[u].mark = out;
      }
      cavity.boundary.push_back(3 * t + i);
    }
  }
  return true;
}

bool Triangulation::insertIntoCavity(int v, const Cavity& cavity, Array<int>& created)
{
  created.clear();
  const Point& p = points[v];
  // Record the outside neighbours before the cavity slots are recycled.
  fan.clear();
  for (int e : cavity.boundary)
  {
    const int t = e / 3, i = e % 3;
    const int u = tri[t].n[i];
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
        if (tri[u].n[j] == t)
          link = 3 * u + j;
    fan.push_back({ tri[t].v[(i + 1) % 3], tri[t].v[(i + 2) % 3], u, link });
  }
  for (int t : cavity.triangles)
    freeTriangle(t);
  for (const FanTriangle& f : fan)
  {
    const int t = newTriangle(f.a, f.b, v);
    created.push_back(t);
    // Edge (a, b) is opposite v (local index 2).
    tri[t].n[2] = f.outside;
    if (f.outsideLink >= 0)
      tri[f.outsideLink / 3].n[f.outsideLink % 3] = t;
  }
  // Link fan neighbours: triangle (a, b, v) meets (b, c, v) across edge (b, v).
  // Each boundary vertex starts one fan edge (a, b) at most.
  const auto link = [&](std::size_t i, std::size_t j) {
    tri[created[i]].n[0] = created[j]; // opposite a: edge (b, v)
    tri[created[j]].n[1] = created[i]; // opposite b in (b, c, v): edge (v, b)
  };
  if (fan.size() <= kSmallFan)
  {
    // Typical fans have 4 to 8 triangles: comparing their ends beats
    // looking them up in an array over all the vertices (a cache miss each).
    for (std::size_t i = 0; i < fan.size(); ++i)
      for (std::size_t j = 0; j < fan.size(); ++j)
        if (fan[j].a == fan[i].b)
        {
          link(i, j);
          break;
        }
  }
  else
  {
    // Not at every new point; every entry is -1 between insertions.
    if (fanByVertex.size() < points.size())
      fanByVertex.assign(2 * points.size(), -1);
    for (std::size_t j = 0; j < fan.size(); ++j)
      fanByVertex[fan[j].a] = static_cast<int>(j);
    for (std::size_t i = 0; i < fan.size(); ++i)
      if (const int j = fanByVertex[fan[i].b]; j >= 0)
        link(i, static_cast<std::size_t>(j));
    for (const FanTriangle& f : fan)
      fanByVertex[f.a] = -1;
  }
  // Order the fan counter-clockwise around v (chain a -> b).
  if (created.size() > 2)
  {
    int first = created.front();
    for (int t : created)
      if (tri[t].n[1] < 0) // no predecessor: the fan is open here (v on the hull)
        first = t;
    ordered.clear();
    for (int t = first; t >= 0 && ordered.size() < created.size(); t = tri[t].n[0])
      ordered.push_back(t);
    created.swap(ordered);
  }
  return true;
}

} // namespace osm
