#include "LongEdges.h"

#include "Predicates.h"
#include "Series.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace osm
{
namespace
{

/// A pass splits each long side once (a triangle once): those meeting at a
/// triangle, or left long by a split, wait for the next.
constexpr int kPasses = 4;

/// The side of a kept triangle that is too long, by its ends (lo < hi).
struct Side
{
  int lo, hi, triangle;
  bool operator<(const Side& o) const
  {
    return lo != o.lo ? lo < o.lo : hi != o.hi ? hi < o.hi : triangle < o.triangle;
  }
};

/// Every too-long side of a kept triangle; the longest goes to found. Scan
/// pass of passes reports progress in its share of the phase.
Array<Side> longSides(const Array<Point>& points, const Array<Triangle>& triangles,
  const Array<int>& regionId, const Array<double>& regionMaxEdge, LongEdges& found, int pass,
  RunContext& run)
{
  Array<Side> sides;
  double worst2 = 0;
  found.remaining = 0;
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    run.tickWith(
      [&] { return (pass + double(t) / double(triangles.size())) / (kPasses + 1); }, 1u << 16);
    if (regionId[t] < 0 || regionMaxEdge[regionId[t]] == 0)
      continue;
    const double maxEdge2 = regionMaxEdge[regionId[t]] * regionMaxEdge[regionId[t]];
    const Triangle& tri = triangles[t];
    bool isLong = false;
    for (int k = 0; k < 3; ++k)
    {
      const int a = tri[k], b = tri[(k + 1) % 3];
      // The overlay compares squared lengths so too: an edge it allows passes.
      const double l2 = dist2(points[a], points[b]);
      if (!(l2 > maxEdge2))
        continue;
      isLong = true;
      sides.push_back({ std::min(a, b), std::max(a, b), static_cast<int>(t) });
      if (l2 / maxEdge2 > worst2)
      {
        worst2 = l2 / maxEdge2;
        found.at = { 0.5 * (points[a].x + points[b].x), 0.5 * (points[a].y + points[b].y) };
      }
    }
    found.remaining += isLong ? 1 : 0;
  }
  found.worst = std::sqrt(worst2);
  std::sort(sides.begin(), sides.end());
  return sides;
}

/// Per side (sorted), whether it lies on a segment: constrained edges stay.
Array<char> onSegments(const Array<Side>& sides, const Array<Segment>& constrained)
{
  Array<char> on(sides.size(), 0);
  for (const Segment& e : constrained)
  {
    const Side key{ std::min(e[0], e[1]), std::max(e[0], e[1]), -1 };
    for (auto it = std::lower_bound(sides.begin(), sides.end(), key);
         it != sides.end() && it->lo == key.lo && it->hi == key.hi; ++it)
      on[it - sides.begin()] = 1;
  }
  return on;
}

double largestAngleDeg(const Point& a, const Point& b, const Point& c)
{
  double lo = 0, hi = 0;
  angleRange(a, b, c, lo, hi);
  return hi * 180.0 / series::kPi;
}

/// The largest angle, in degrees, of the fan of triangles joining m to the
/// sides of the quadrilateral q (counter-clockwise); infinite where one of
/// them is not counter-clockwise or an edge from m is longer than the bound.
double fanCost(const Point (&q)[4], const Point& m, double maxEdge2)
{
  double worst = 0;
  for (int i = 0; i < 4; ++i)
  {
    const Point &p = q[i], &r = q[(i + 1) % 4];
    if (!(dist2(m, p) <= maxEdge2) || !(orient2d(p, r, m) > 0))
      return std::numeric_limits<double>::infinity();
    worst = std::max(worst, largestAngleDeg(p, r, m));
  }
  return worst;
}

/// The point of the quadrilateral q whose fan has the smallest largest angle,
/// by a pattern search from the midpoint of its diagonal q[0]-q[2] (on which
/// every fan is counter-clockwise).
Point bestCenter(const Point (&q)[4], double maxEdge2, double& cost)
{
  Point best{ 0.5 * (q[0].x + q[2].x), 0.5 * (q[0].y + q[2].y) };
  cost = fanCost(q, best, maxEdge2);
  double step = 0.25 * std::sqrt(dist2(q[0], q[2]));
  const double stop = step / 64;
  const double dirs[8][2] = { { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 }, { 0.7071, 0.7071 },
    { -0.7071, 0.7071 }, { 0.7071, -0.7071 }, { -0.7071, -0.7071 } };
  while (step > stop)
  {
    bool moved = false;
    for (const auto& d : dirs)
    {
      const Point m{ best.x + step * d[0], best.y + step * d[1] };
      if (const double c = fanCost(q, m, maxEdge2); c < cost)
      {
        best = m;
        cost = c;
        moved = true;
      }
    }
    if (!moved)
      step *= 0.5;
  }
  return best;
}

/// Replace the side a-b shared by triangles t (a, b, c) and u (b, a, d) by a
/// point joined to the four corners, if one keeps every angle within
/// maxAngleDeg and every new edge within the bound; returns whether it did.
bool splitSide(Array<Point>& points, Array<VertexOrigin>& origin, Array<Triangle>& triangles,
  Array<int>& regionId, int t, int u, double maxEdge2, double maxAngleDeg)
{
  // The long side is the one of t whose ends u holds the other way round.
  const Triangle tt = triangles[t], uu = triangles[u];
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
    {
      const int a = tt[k], b = tt[(k + 1) % 3];
      if (uu[j] != b || uu[(j + 1) % 3] != a)
        continue;
      const int c = tt[(k + 2) % 3], d = uu[(j + 2) % 3];
      const Point q[4] = { points[a], points[d], points[b], points[c] };
      double cost = 0;
      const Point m = bestCenter(q, maxEdge2, cost);
      if (!(cost <= maxAngleDeg))
        return false;
      const int v = static_cast<int>(points.size());
      points.push_back(m);
      origin.push_back(VertexOrigin::Other);
      triangles[t] = { c, a, v };
      triangles[u] = { d, b, v };
      triangles.push_back({ a, d, v });
      regionId.push_back(regionId[t]);
      triangles.push_back({ b, c, v });
      regionId.push_back(regionId[u]);
      return true;
    }
  return false;
}

} // namespace

LongEdges splitLongEdges(Array<Point>& points, Array<VertexOrigin>& origin,
  Array<Triangle>& triangles, Array<int>& regionId, const Array<Segment>& constrained,
  const Array<double>& regionMaxEdge, double maxAngleDeg, RunContext& run)
{
  LongEdges found;
  for (int pass = 0; pass < kPasses; ++pass)
  {
    Array<Side> sides = longSides(points, triangles, regionId, regionMaxEdge, found, pass, run);
    if (sides.empty())
      return found;
    const Array<char> onSegment = onSegments(sides, constrained);
    Array<char> changed(triangles.size(), 0); // split in this pass: their sides moved
    bool any = false;
    for (std::size_t i = 0; i + 1 < sides.size(); ++i)
    {
      const Side &s = sides[i], &next = sides[i + 1];
      if (onSegment[i] || next.lo != s.lo || next.hi != s.hi)
        continue;
      // One pair per side; a side of a triangle already split waits for the next pass.
      if (changed[s.triangle] || changed[next.triangle])
        continue;
      // Both lie in one region: no segment separates them.
      const double maxEdge = regionMaxEdge[regionId[s.triangle]];
      if (splitSide(points, origin, triangles, regionId, s.triangle, next.triangle,
            maxEdge * maxEdge, maxAngleDeg))
      {
        changed[s.triangle] = changed[next.triangle] = 1;
        ++found.split;
        any = true;
      }
      ++i;
    }
    if (!any)
      return found; // as the scan left it: nothing changed since
  }
  longSides(points, triangles, regionId, regionMaxEdge, found, kPasses, run);
  return found;
}

} // namespace osm
