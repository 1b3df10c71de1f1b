// Plain Delaunay triangulation of a point set by bulk insertion: Hilbert order,
// walking point location, Bowyer-Watson insertion. Used by Interpolation.cxx
// (the triangle of known points around each other vertex), by the tests as an
// independent check of the triangulation layer, and by benchmarks as the
// "triangulation alone" reference.
#ifndef osm_Delaunay_h
#define osm_Delaunay_h

#include "Triangulation.h"

#include <vector>

namespace osm
{

/// Delaunay triangulation of distinct finite points inside a padded box whose
/// corners are vertices 0..3, `padding` times the points' extent from their
/// centre; point i becomes vertex vertexOf[i]. The farther the corners, the
/// nearer the triangles without a corner come to the points' own Delaunay
/// triangulation, hull edges included.
Triangulation delaunayTriangulation(
  const Array<Point>& points, Array<int>& vertexOf, double padding = 2.0);

} // namespace osm

#endif
