// Phase 3: completing the stitched planar graph into a triangulation.
// Every bounded face is triangulated to minimise its largest angle, by
// dynamic programming over its diagonals (exact tests decide which diagonals
// lie inside, so no zero-area or inverted triangle is ever produced).
#ifndef osm_Complete_h
#define osm_Complete_h

#include "HugePages.h"
#include "RunContext.h"
#include "Statistics.h"
#include "Stitch.h"

#include <vector>

namespace osm
{

struct Completion
{
  Array<Triangle> triangles;
  /// Edges of the planar graph that are input subsegments, as vertex pairs (lo, hi).
  Array<Segment> constrainedEdges;
};

/// Takes graph.intact as the first triangles, then triangulates every other face.
Completion complete(PlanarGraph& graph, Statistics& stats, RunContext& run);

/// Min-max-angle triangulation of a simple polygon given counter-clockwise.
/// Appends triangles (indices into ids) and returns false if none exists.
bool triangulateMinMaxAngle(
  const Array<Point>& polygon, const Array<int>& ids, Array<Triangle>& out);

/// Largest angle of a triangle, in radians.
double maxAngle(const Point& a, const Point& b, const Point& c);

} // namespace osm

#endif
