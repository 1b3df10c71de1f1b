// Which segments lie on a cycle of the segment graph, grouped by the cycles
// they share: only such segments can bound an enclosed region.
#ifndef osm_CycleComponents_h
#define osm_CycleComponents_h

#include "Geometry.h"
#include "HugePages.h"

#include <cstddef>

namespace osm
{

struct CycleComponents
{
  /// Per segment: its 2-edge-connected component (segments joined by cycles),
  /// numbered from 0 in the order of their first segment, or -1 for a segment
  /// on no cycle (a dangling one, or a bridge: a path between cycles).
  Array<int> component;
  std::size_t count = 0;
};

/// Linear in the points and segments (an iterative depth-first search for the
/// bridges). Two segments with the same ends form a cycle.
CycleComponents cycleComponents(std::size_t pointCount, const Array<Segment>& segments);

/// Per component of cycles: the bounds of its segments.
Array<Bounds> cycleBounds(
  const Array<Point>& points, const Array<Segment>& segments, const CycleComponents& cycles);

/// Per component of cycles: the area its segments enclose when they form one
/// simple cycle (each of its points on two of its segments), else -1.
Array<double> simpleCycleAreas(
  const Array<Point>& points, const Array<Segment>& segments, const CycleComponents& cycles);

} // namespace osm

#endif
