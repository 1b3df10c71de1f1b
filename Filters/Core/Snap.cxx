#include "Snap.h"

#include "Geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace osm
{

namespace
{

/// A k-d tree of the points: each node a range of them, split at its median
/// along the wider side of its bounds, down to leaves of at most 8. A
/// segment finds the points within tol of it by descending only into nodes
/// whose bounds come that close to it, so the work follows the points near
/// each segment. (A grid fails on inputs that mix lengths: cells as wide as
/// the mean segment put a cluster of 40,000 short segments in a few cells,
/// 8.6 s; cells per length made every point near a long segment visit it.)
class PointTree
{
public:
  explicit PointTree(const Array<Point>& points)
    : P(points)
    , order(points.size())
  {
    for (std::size_t i = 0; i < order.size(); ++i)
      order[i] = static_cast<int>(i);
    std::size_t leaves = 1;
    while (leaves * kLeaf < points.size())
      leaves *= 2;
    box.resize(2 * leaves - 1);
    build(0, 0, order.size());
  }

  /// Visits every point within tol of segment ab (and some a little beyond).
  template <typename Visit>
  void near(const Point& a, const Point& b, double tol, Visit visit) const
  {
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const double ux = (b.x - a.x) / length, uy = (b.y - a.y) / length;
    Bounds reach{ { std::min(a.x, b.x) - tol, std::min(a.y, b.y) - tol },
      { std::max(a.x, b.x) + tol, std::max(a.y, b.y) + tol } };
    // Nodes as (node, first point, end).
    Array<std::array<std::size_t, 3>> stack{ { 0, 0, order.size() } };
    while (!stack.empty())
    {
      const auto [node, lo, hi] = stack.back();
      stack.pop_back();
      if (lo == hi || !meets(box[node], reach) || !nearLine(box[node], a, ux, uy, tol))
        continue;
      if (hi - lo <= kLeaf || 2 * node + 2 >= box.size())
      {
        for (std::size_t k = lo; k < hi; ++k)
          visit(order[k]);
        continue;
      }
      const std::size_t mid = lo + (hi - lo) / 2;
      stack.push_back({ 2 * node + 1, lo, mid });
      stack.push_back({ 2 * node + 2, mid, hi });
    }
  }

private:
  static constexpr std::size_t kLeaf = 8;

  void build(std::size_t node, std::size_t lo, std::size_t hi)
  {
    Bounds b = emptyBounds();
    for (std::size_t k = lo; k < hi; ++k)
      extend(b, P[order[k]]);
    box[node] = b;
    if (hi - lo <= kLeaf || 2 * node + 2 >= box.size())
      return;
    const std::size_t mid = lo + (hi - lo) / 2;
    const bool byX = b.width() >= b.height();
    std::nth_element(order.begin() + lo, order.begin() + mid, order.begin() + hi,
      [&](int i, int j) { return byX ? P[i].x < P[j].x : P[i].y < P[j].y; });
    build(2 * node + 1, lo, mid);
    build(2 * node + 2, mid, hi);
  }

  static bool meets(const Bounds& b, const Bounds& r)
  {
    return b.lo.x <= r.hi.x && r.lo.x <= b.hi.x && b.lo.y <= r.hi.y && r.lo.y <= b.hi.y;
  }

  /// Whether the line through a with unit direction u comes within tol of
  /// box b: not all of its corners beyond tol on one side.
  static bool nearLine(const Bounds& b, const Point& a, double ux, double uy, double tol)
  {
    double least = 0, most = 0;
    bool first = true;
    for (const double x : { b.lo.x, b.hi.x })
      for (const double y : { b.lo.y, b.hi.y })
      {
        const double off = (y - a.y) * ux - (x - a.x) * uy;
        least = first ? off : std::min(least, off);
        most = first ? off : std::max(most, off);
        first = false;
      }
    return least <= tol && most >= -tol;
  }

  const Array<Point>& P;
  Array<int> order;
  Array<Bounds> box; ///< per node, its points' bounds
};

/// The end of a segment that its snaps are ordered from: the lower in (x, y)
/// order, so that the order does not depend on how the segment is numbered.
int lowerEnd(const Array<Point>& points, const Segment& e)
{
  return points[e[1]] < points[e[0]] ? e[1] : e[0];
}

struct Snap
{
  int segment; ///< index into the segments
  double t;    ///< where along it from its lower end
  Point at;    ///< the point's, for ties: the order of points equally far along
  int point;
  bool operator<(const Snap& o) const
  {
    return segment != o.segment ? segment < o.segment
      : t != o.t                ? t < o.t
      : !(at == o.at)           ? at < o.at
                                : point < o.point;
  }
  bool operator==(const Snap& o) const { return segment == o.segment && point == o.point; }
};

/// The points within tol of each segment, strictly between its ends, sorted
/// along each segment from its lower end, and points equally far along (on
/// either side of it: a zigzag) by their coordinates.
Array<Snap> findSnaps(const Array<Point>& points, const Array<OriginSegment>& segments, double tol)
{
  const PointTree tree(points);
  Array<Snap> snaps;
  for (std::size_t s = 0; s < segments.size(); ++s)
  {
    const Segment& e = segments[s].first;
    const int lower = lowerEnd(points, e);
    const Point &a = points[lower], &b = points[lower == e[0] ? e[1] : e[0]];
    const SegmentFrame frame(a, b);
    if (!std::isfinite(frame.length))
      continue; // beyond the coordinates the mesher accepts
    tree.near(a, b, tol, [&](int i) {
      if (i == e[0] || i == e[1])
        return;
      const double along = frame.along(points[i]);
      if (along > 0 && along < frame.length && std::fabs(frame.off(points[i])) <= tol)
        snaps.push_back({ static_cast<int>(s), along / frame.length, points[i], i });
    });
  }
  std::sort(snaps.begin(), snaps.end());
  snaps.erase(std::unique(snaps.begin(), snaps.end()), snaps.end());
  return snaps;
}

} // namespace

std::size_t snapPointsOntoSegments(const Array<Point>& points, Array<OriginSegment>& segments,
  double tol, SnapExample& example, Array<OriginSegment>* split)
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
    if (split)
      split->push_back(segments[s]);
    const auto [ends, origin] = segments[s];
    // Along the segment from its lower end: the first piece replaces the
    // segment, the others are appended.
    auto piece = [origin = origin](int u, int v) {
      return OriginSegment{ { std::min(u, v), std::max(u, v) }, origin };
    };
    int from = lowerEnd(points, ends);
    const int to = from == ends[0] ? ends[1] : ends[0];
    for (const std::size_t first = k; k < snaps.size() && snaps[k].segment == s; ++k)
    {
      if (k == first)
        segments[s] = piece(from, snaps[k].point);
      else
        segments.push_back(piece(from, snaps[k].point));
      from = snaps[k].point;
    }
    segments.push_back(piece(from, to));
  }
  return snaps.size();
}

} // namespace osm
