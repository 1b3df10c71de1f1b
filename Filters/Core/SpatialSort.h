// Ordering points along a Hilbert curve, so that consecutive points are close:
// bulk insertion then walks only a few triangles per point, and memory is
// touched locally.
#ifndef osm_SpatialSort_h
#define osm_SpatialSort_h

#include "Geometry.h"
#include "HugePages.h"

#include <vector>

namespace osm
{

/// Indices of points[0..n) in Hilbert-curve order (ties keep input order).
Array<int> hilbertOrder(const Point* points, std::size_t n);

inline Array<int> hilbertOrder(const Array<Point>& points)
{
  return hilbertOrder(points.data(), points.size());
}

} // namespace osm

#endif
