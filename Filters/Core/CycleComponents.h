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

} // namespace osm

#endif
