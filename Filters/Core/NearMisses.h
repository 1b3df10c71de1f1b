// Segment ends that stop a hair short of another segment: a line meant to end
// on another (an isoline on its boundary, a road on a border) whose end was
// rounded off it. Such an end dangles: the regions it was to separate are one,
// and the gap takes many tiny triangles to mesh. A warning says so.
#ifndef osm_NearMisses_h
#define osm_NearMisses_h

#include "Geometry.h"
#include "HugePages.h"

#include <cstddef>

namespace osm
{

struct NearMisses
{
  std::size_t count = 0; ///< dangling ends within reach of a segment
  int point = -1;        ///< the example: the end farthest from its nearest segment
  int segment = -1;      ///< that segment (an index into segments)
  double distance = 0;   ///< the largest gap: the example's
};

/// The points that end exactly one segment and lie within reach of another
/// segment without being on it (exactly: those are split later). A bucket
/// grid over the dangling ends, and per segment the buckets along it: no
/// cost where no segment dangles (closed loops).
NearMisses findNearMisses(const Array<Point>& points, const Array<Segment>& segments, double reach);

} // namespace osm

#endif
