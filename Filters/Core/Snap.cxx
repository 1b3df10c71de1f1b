#include "Snap.h"

#include "Geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace osm
{

namespace
{

/// A uniform grid over the points' bounds in which each segment is listed in
/// the cells of samples along it at most half a cell apart. A point within
/// tol <= cell / 2 of a segment is then within 3 / 4 of a cell of a sample,
/// so in the 3 x 3 cells around its own. Cells as wide as the segments'
/// mean length keep the samples to about 3 per segment, and few segments in
/// a cell where their lengths are alike (cells a fraction of the extent put
/// hundreds of a coastline's segments in each).
class SegmentGrid
{
public:
  SegmentGrid(const Array<Point>& points, const Array<OriginSegment>& segments, double tol)
    : bounds(boundsOf(points))
  {
    double mean = 0; // as a running mean: a sum could overflow
    for (std::size_t k = 0; k < segments.size(); ++k)
    {
      const Point &a = points[segments[k].first[0]], &b = points[segments[k].first[1]];
      mean += (std::hypot(b.x - a.x, b.y - a.y) - mean) / double(k + 1);
    }
    // At most 2^40 cells across: their indices stay far inside 64 bits.
    const double extent = std::max(bounds.width(), bounds.height());
    cell = std::max({ 2 * tol, mean, std::ldexp(extent, -40) });
    if (!usable())
      return;
    for (std::size_t s = 0; s < segments.size(); ++s)
      addSamples(points[segments[s].first[0]], points[segments[s].first[1]], int(s));
    std::sort(entries.begin(), entries.end());
    entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
  }

  /// False where the extent overflows (coordinates near the double limit,
  /// which the mesher refuses as too large): nothing is listed.
  bool usable() const { return std::isfinite(cell) && std::isfinite(2 * cell); }

  /// The segments listed in the 3 x 3 cells around p (with repeats).
  template <typename Visit>
  void around(const Point& p, Visit visit) const
  {
    const std::int64_t cx = index(p.x, bounds.lo.x), cy = index(p.y, bounds.lo.y);
    // The three cells of a column are consecutive in the sorted entries.
    for (std::int64_t x = cx - 1; x <= cx + 1; ++x)
      for (auto it = std::lower_bound(entries.begin(), entries.end(), Entry{ x, cy - 1, -1 });
           it != entries.end() && it->x == x && it->y <= cy + 1; ++it)
        visit(it->segment);
  }

private:
  struct Entry
  {
    std::int64_t x, y; ///< the cell
    int segment;
    bool operator<(const Entry& o) const
    {
      return x != o.x ? x < o.x : y != o.y ? y < o.y : segment < o.segment;
    }
    bool operator==(const Entry& o) const { return x == o.x && y == o.y && segment == o.segment; }
  };

  std::int64_t index(double v, double lo) const
  {
    return static_cast<std::int64_t>(std::floor((v - lo) / cell));
  }

  void addSamples(const Point& a, const Point& b, int s)
  {
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const auto steps = static_cast<std::int64_t>(std::ceil(length / (cell / 2)));
    for (std::int64_t k = 0; k <= steps; ++k)
    {
      const double t = steps == 0 ? 0.0 : double(k) / double(steps);
      const Entry e{ index(a.x + t * (b.x - a.x), bounds.lo.x),
        index(a.y + t * (b.y - a.y), bounds.lo.y), s };
      if (k == 0 || e.x != entries.back().x || e.y != entries.back().y)
        entries.push_back(e);
    }
  }

  Bounds bounds;
  double cell = 1;
  Array<Entry> entries; ///< sorted
};

struct Snap
{
  int segment; ///< index into the segments
  double t;    ///< where along it
  int point;
  bool operator<(const Snap& o) const
  {
    return segment != o.segment ? segment < o.segment : t != o.t ? t < o.t : point < o.point;
  }
  bool operator==(const Snap& o) const { return segment == o.segment && point == o.point; }
};

/// The points within tol of each segment, strictly between its ends, sorted
/// along each segment.
Array<Snap> findSnaps(const Array<Point>& points, const Array<OriginSegment>& segments, double tol)
{
  const SegmentGrid grid(points, segments, tol);
  Array<Snap> snaps;
  if (!grid.usable())
    return snaps;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const Point& p = points[i];
    grid.around(p, [&](int s) {
      const Segment& e = segments[s].first;
      if (e[0] == int(i) || e[1] == int(i))
        return;
      // Along and off the segment's unit direction: no square of a
      // coordinate difference, which overflows near the coordinates' limit.
      const Point &a = points[e[0]], &b = points[e[1]];
      const double length = std::hypot(b.x - a.x, b.y - a.y);
      const double ux = (b.x - a.x) / length, uy = (b.y - a.y) / length;
      const double along = (p.x - a.x) * ux + (p.y - a.y) * uy;
      const double off = (p.y - a.y) * ux - (p.x - a.x) * uy;
      if (along > 0 && along < length && std::fabs(off) <= tol)
        snaps.push_back({ s, along / length, int(i) });
    });
  }
  std::sort(snaps.begin(), snaps.end());
  snaps.erase(std::unique(snaps.begin(), snaps.end()), snaps.end());
  return snaps;
}

} // namespace

std::size_t snapPointsOntoSegments(
  const Array<Point>& points, Array<OriginSegment>& segments, double tol, SnapExample& example)
{
  if (!(tol > 0) || segments.empty())
    return 0;
  const Array<Snap> snaps = findSnaps(points, segments, tol);
  if (snaps.empty())
    return 0;
  example = { snaps.front().point, segments[snaps.front().segment].second };
  for (std::size_t k = 0; k < snaps.size();)
  {
    const int s = snaps[k].segment;
    const auto [ends, origin] = segments[s];
    // Along the segment from ends[0] (t is measured from it): the first piece
    // replaces the segment, the others are appended.
    auto piece = [origin = origin](int u, int v) {
      return OriginSegment{ { std::min(u, v), std::max(u, v) }, origin };
    };
    int from = ends[0];
    for (const std::size_t first = k; k < snaps.size() && snaps[k].segment == s; ++k)
    {
      if (k == first)
        segments[s] = piece(from, snaps[k].point);
      else
        segments.push_back(piece(from, snaps[k].point));
      from = snaps[k].point;
    }
    segments.push_back(piece(from, ends[1]));
  }
  return snaps.size();
}

} // namespace osm
