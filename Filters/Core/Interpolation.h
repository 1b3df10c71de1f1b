// Values at the mesh's vertices from values at the input points: how data on
// the input (elevation at a coastline's points, a .node file's attributes)
// reaches the points the mesher adds, as Triangle interpolates its vertex
// attributes.
//
// An input vertex takes its own value. A point the mesher put on an input
// segment (a stitch vertex, a crossing of two segments) takes the value
// linear along that segment, between its two ends. Every other point (an
// overlay Steiner point, a point on the hull's edges,
// a point splitting a long edge) takes the value linear within the triangle
// that holds it in the Delaunay triangulation of the points of the first two
// kinds. Those on the segments make that triangulation follow the segments,
// so that values are seldom averaged across one (no vertex was, of the
// 7,369 in the tests' kinked fields). Beyond the hull of those points (only
// with the box domain) a point takes the value where it projects onto the
// hull edge nearest it in that triangulation. A field linear over the input
// points is reproduced at every vertex within their hull, to rounding.
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
  int segment = -1;    ///< else the input segment it lies on (within the tolerance), else -1
  int count = 0;       ///< 1 to 6 terms (0 only where no vertex is an input point or on a segment)
  int point[6];        ///< input points (indices in the Pslg)
  double weight[6];

  void add(int p, double w);
};

/// Returns false to stop the visit.
using TermsVisitor = std::function<bool(const VertexTerms&)>;

/// Visits every vertex of result's mesh of input (the same Pslg given to
/// mesh(), and its Result) once, in no set order, with its terms. A vertex
/// within tolerance of an input segment (at least rounding at the
/// coordinates' magnitude and 1e-9 of the extent; pass the merge tolerance)
/// lies on it. Returns false if the visitor stopped it.
bool visitInputWeights(
  const Pslg& input, const Result& result, double tolerance, const TermsVisitor& visit);

/// For each point, the input segment it lies on (within tolerance, as
/// visitInputWeights decides it), else -1: the segment under the midpoint
/// of an input subsegment, say.
Array<int> segmentsUnder(const Pslg& input, const Array<Point>& points, double tolerance = 0.0);

} // namespace osm

#endif
