// The input model: a Planar Straight Line Graph.
#ifndef osm_Pslg_h
#define osm_Pslg_h

#include "Geometry.h"
#include "HugePages.h"

#include <vector>

namespace osm
{

/// Points plus segments (pairs of point indices) plus hole seed points.
/// Segments must not cross, unless the mesher is allowed to split crossings.
struct Pslg
{
  Array<Point> points;
  Array<Segment> segments;
  /// Seeds: the region (bounded by segments) containing each one is removed.
  Array<Point> holes;
};

} // namespace osm

#endif
