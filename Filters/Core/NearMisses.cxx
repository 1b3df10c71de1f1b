#include "NearMisses.h"

#include "Predicates.h"

#include <algorithm>
#include <cmath>

namespace osm
{

namespace
{

/// Whether p lies on the closed segment ab, exactly.
bool onSegment(const Point& p, const Point& a, const Point& b)
{
  return orient2d(a, b, p) == 0 && std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) &&
    std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

/// The dangling ends in buckets of a grid of about one end per cell.
struct EndGrid
{
  EndGrid(const Array<Point>& points, const Array<int>& ends)
  {
    box = { points[ends[0]], points[ends[0]] };
    for (int e : ends)
      extend(box, points[e]);
    const double side = std::ceil(std::sqrt(double(ends.size())));
    cell = std::max(box.width(), box.height()) / side;
    if (!(cell > 0) || !std::isfinite(cell))
      cell = 1.0; // one point, or ends on one axis-parallel line
    nx = static_cast<int>(std::min(side, std::floor(box.width() / cell)) + 1);
    ny = static_cast<int>(std::min(side, std::floor(box.height() / cell)) + 1);
    start.assign(std::size_t(nx) * std::size_t(ny) + 1, 0);
    for (int e : ends)
      ++start[bucket(points[e]) + 1];
    for (std::size_t c = 1; c < start.size(); ++c)
      start[c] += start[c - 1];
    Array<int> next(start.begin(), start.end() - 1);
    members.resize(ends.size());
    for (int e : ends)
      members[next[bucket(points[e])]++] = e;
  }
  int column(double x) const
  {
    return static_cast<int>(std::clamp(std::floor((x - box.lo.x) / cell), 0.0, double(nx - 1)));
  }
  int row(double y) const
  {
    return static_cast<int>(std::clamp(std::floor((y - box.lo.y) / cell), 0.0, double(ny - 1)));
  }
  std::size_t bucket(const Point& p) const
  {
    return std::size_t(row(p.y)) * std::size_t(nx) + std::size_t(column(p.x));
  }

  Bounds box;
  double cell = 1.0;
  int nx = 1, ny = 1;
  Array<int> start;   ///< per cell, its first entry in members (CSR)
  Array<int> members; ///< the ends, by cell
};

} // namespace

NearMisses findNearMisses(const Array<Point>& points, const Array<Segment>& segments, double reach)
{
  NearMisses out;
  Array<int> degree(points.size(), 0);
  for (const Segment& s : segments)
    ++degree[s[0]], ++degree[s[1]];
  Array<int> ends;
  for (std::size_t p = 0; p < points.size(); ++p)
    if (degree[p] == 1)
      ends.push_back(static_cast<int>(p));
  // An extent beyond the doubles' range gives no reach to judge by.
  if (ends.empty() || !(reach > 0) || !std::isfinite(reach))
    return out;
  const EndGrid grid(points, ends);
  // Per end, its nearest segment within reach (distance, segment).
  Array<double> nearest(points.size(), -1.0);
  Array<int> nearestSegment(points.size(), -1);
  for (std::size_t s = 0; s < segments.size(); ++s)
  {
    const Point &a = points[segments[s][0]], &b = points[segments[s][1]];
    if (std::max(a.x, b.x) + reach < grid.box.lo.x || std::min(a.x, b.x) - reach > grid.box.hi.x ||
      std::max(a.y, b.y) + reach < grid.box.lo.y || std::min(a.y, b.y) - reach > grid.box.hi.y)
      continue;
    // Row by row, the cells within reach of the part of the segment in that row.
    const double ylo = std::min(a.y, b.y), yhi = std::max(a.y, b.y);
    auto xAt = [&](double y) {
      return a.y == b.y ? a.x : a.x + std::clamp((y - a.y) / (b.y - a.y), 0.0, 1.0) * (b.x - a.x);
    };
    for (int r = grid.row(ylo - reach), last = grid.row(yhi + reach); r <= last; ++r)
    {
      const double y0 = std::clamp(grid.box.lo.y + r * grid.cell - reach, ylo, yhi);
      const double y1 = std::clamp(grid.box.lo.y + (r + 1) * grid.cell + reach, ylo, yhi);
      double x0 = a.y == b.y ? std::min(a.x, b.x) : xAt(y0);
      double x1 = a.y == b.y ? std::max(a.x, b.x) : xAt(y1);
      if (x0 > x1)
        std::swap(x0, x1);
      for (int c = grid.column(x0 - reach), lastColumn = grid.column(x1 + reach); c <= lastColumn;
           ++c)
      {
        const std::size_t cell = std::size_t(r) * std::size_t(grid.nx) + std::size_t(c);
        for (int k = grid.start[cell]; k < grid.start[cell + 1]; ++k)
        {
          const int e = grid.members[k];
          if (e == segments[s][0] || e == segments[s][1])
            continue;
          const double d = distanceToSegment(points[e], a, b);
          if (!(d <= reach) || onSegment(points[e], a, b)) // NaN: lengths overflow
            continue;
          if (nearest[e] < 0 || d < nearest[e])
            nearest[e] = d, nearestSegment[e] = static_cast<int>(s);
        }
      }
    }
  }
  for (int e : ends)
  {
    if (nearest[e] < 0)
      continue;
    ++out.count;
    if (out.point < 0 || nearest[e] > out.distance)
      out.point = e, out.segment = nearestSegment[e], out.distance = nearest[e];
  }
  return out;
}

} // namespace osm
