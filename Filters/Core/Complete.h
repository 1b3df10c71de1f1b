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

#include <utility>
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

/// The arrays of that search (k^2 entries each for k vertices), kept from
/// one face to the next: most faces are quadrilaterals, whose few
/// allocations cost as much as their search.
struct MinMaxScratch
{
  Array<char> ok;
  Array<double> cost;
  Array<int> apex;
  Array<std::pair<int, int>> stack;
};
bool triangulateMinMaxAngle(
  const Array<Point>& polygon, const Array<int>& ids, Array<Triangle>& out, MinMaxScratch& scratch);

/// The same search by the dynamic program alone, which triangulateMinMaxAngle
/// unrolls for quadrilaterals (the tests compare the two).
bool triangulateMinMaxAngleByProgram(
  const Array<Point>& polygon, const Array<int>& ids, Array<Triangle>& out, MinMaxScratch& scratch);

/// Largest angle of a triangle, in radians.
double maxAngle(const Point& a, const Point& b, const Point& c);

} // namespace osm

#endif
