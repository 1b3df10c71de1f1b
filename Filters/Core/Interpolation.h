// Values at the mesh's vertices from values at the input points: how data on
// the input (elevation at a coastline's points, a .node file's attributes)
// reaches the points the mesher adds, as Triangle interpolates its vertex
// attributes.
//
// An input vertex takes its own value. A point the mesher found on an input
// segment (a stitch vertex, a crossing of two segments, an overlay vertex a
// segment passes through; Result::vertexSegment) takes the value linear
// along that segment, between its two ends. Every other point (an overlay
// Steiner point, a point on the hull's edges,
// a point splitting a long edge) takes the value linear within the triangle
// that holds it in the Delaunay triangulation of the points of the first two
// kinds. Those on the segments make that triangulation follow the segments,
// so that values are seldom averaged across one: none of the 7,369 vertices
// of the tests' kinked fields is; of 14 real inputs meshed in 3 domains, one
// vertex of la.poly takes 3% of its value (11% in the box domain) from a
// point across a segment. Beyond the hull of those points (only with the
// box domain) the triangulation's corners are very far away: a point in a
// triangle of a hull edge and a corner takes the value where it projects
// onto that edge, one in a triangle of a hull vertex and two corners that
// vertex's value (continuous, but not the nearest hull point's value). A
// field linear over the input points is reproduced at every vertex within
// their hull, to rounding.
#ifndef osm_Interpolation_h
#define osm_Interpolation_h

#include "Mesher.h"

#include <functional>

namespace osm
{

/// One mesh vertex's value as a weighted sum of input points' values: weights
/// > 0 that sum to 1, on distinct input points.
struct VertexTerms
{
  std::size_t vertex = 0;
  int inputPoint = -1; ///< the input point it is (the first merged into it), else -1
  int segment = -1;    ///< else the input segment the mesher put it on, else -1
  int count = 0;       ///< 1 to 6 terms (0 only where no vertex is an input point or on a segment)
  int point[6];        ///< input points (indices in the Pslg)
  double weight[6];

  void add(int p, double w);
};

/// Returns false to stop the visit.
using TermsVisitor = std::function<bool(const VertexTerms&)>;

/// Visits every vertex of result's mesh of input (the same Pslg given to
/// mesh(), and its Result, meshed with Options::keepVertexSegments so that
/// the segment of each vertex on one is known; else no vertex but the input
/// ones is known) once, in no set order, with its terms. Returns false if
/// the visitor stopped it.
bool visitInputWeights(const Pslg& input, const Result& result, const TermsVisitor& visit);

} // namespace osm

#endif
