// Snapping points onto segments within the merge tolerance: the other half
// of what a tolerance means for data digitised twice (a border two polygons
// share, with a vertex on one copy only, lies a tiny gap off the other copy).
#ifndef osm_Snap_h
#define osm_Snap_h

#include "HugePages.h"
#include "Pslg.h"

#include <cmath>
#include <cstddef>
#include <utility>

namespace osm
{

/// A segment (its points in index order) with the input segment it came from.
using OriginSegment = std::pair<Segment, int>;

struct SnapExample
{
  int point = -1;   ///< an index into points
  int segment = -1; ///< the input segment (origin) it split
};

/// Where points lie from segment ab: how far along it from a, and how far
/// off it (left positive), in units of the coordinates. Taken along the unit
/// direction, with no square of a coordinate difference, which overflows near
/// the coordinates' limit (an infinite length: beyond them). Made once per
/// segment, asked per point.
struct SegmentFrame
{
  SegmentFrame(const Point& a, const Point& b)
    : a(a)
    , length(std::hypot(b.x - a.x, b.y - a.y))
    , ux((b.x - a.x) / length)
    , uy((b.y - a.y) / length)
  {}
  double along(const Point& p) const { return (p.x - a.x) * ux + (p.y - a.y) * uy; }
  double off(const Point& p) const { return (p.y - a.y) * ux - (p.x - a.x) * uy; }

  Point a;
  double length, ux, uy;
};

/// Split every segment at the points within tol of it that lie strictly
/// between its ends, in order along it: the segment then bends by at most tol
/// to pass through them. The points are those left after merging within tol
/// (pairwise further apart than tol). Each piece keeps its segment's origin.
/// Returns how many (point, segment) pairs were snapped; example names one.
/// O(n log n) for a k-d tree of the points, then per segment a descent into
/// the nodes that come within tol of it: the work follows the points near
/// each segment. split, if given, receives the segments that were split, as
/// they were.
std::size_t snapPointsOntoSegments(const Array<Point>& points, Array<OriginSegment>& segments,
  double tol, SnapExample& example, Array<OriginSegment>* split = nullptr);

} // namespace osm

#endif
