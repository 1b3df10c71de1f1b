// The input model: a Planar Straight Line Graph.
#ifndef osm_Pslg_h
#define osm_Pslg_h

#include "Geometry.h"
#include "HugePages.h"

#include <functional>
#include <string>
#include <vector>

namespace osm
{

/// A regional attribute (a region line of Triangle's .poly format): every
/// triangle of the region (bounded by segments) that holds `seed` gets
/// `attribute`. maxArea, when positive, bounds the area of each of the
/// region's triangles (as Triangle's -a); negative or 0 when none.
struct RegionAttribute
{
  Point seed;
  double attribute = 0.0;
  double maxArea = -1.0;
};

/// Writes a point's coordinates into a message. A caller that mapped its
/// input into the plane (the VTK filter, for points in a tilted plane) passes
/// one that writes the input's own coordinates; empty: "(x, y)".
using PointFormat = std::function<std::string(const Point&)>;

/// Points plus segments (pairs of point indices) plus hole seed points.
/// Segments must not cross, unless the mesher is allowed to split crossings.
struct Pslg
{
  Array<Point> points;
  Array<Segment> segments;
  /// Seeds: the region (bounded by segments) containing each one is removed.
  Array<Point> holes;
  /// Regional attributes; with any, the mesh has an attribute per triangle.
  Array<RegionAttribute> regions;
};

} // namespace osm

#endif
