// Splitting the completed edges that exceed the maximum edge length.
#ifndef osm_LongEdges_h
#define osm_LongEdges_h

#include "Geometry.h"
#include "HugePages.h"
#include "Mesher.h"
#include "RunContext.h"

namespace osm
{

/// What splitLongEdges did and left.
struct LongEdges
{
  std::size_t split = 0;     ///< edges split at their midpoint
  std::size_t remaining = 0; ///< kept triangles with an edge still longer than their bound
  double worst = 0;          ///< the largest ratio of such an edge's length to its bound
  Point at;                  ///< that edge's midpoint
};

/// The size bound caps the overlay's edges, and stitching splits them, but
/// completion joins the vertices of a face with diagonals that can be a little
/// longer (up to 17% on the real inputs). Each such edge between two kept
/// triangles, not part of a segment, is split at its midpoint, which joins
/// the two opposite corners, when the four triangles are counter-clockwise
/// and none has an angle above maxAngleDeg (as long as halves stay too long,
/// a few passes). Meshing again with a tighter overlay around them does not
/// serve: the refinement's order changes and long diagonals appear elsewhere.
/// New points get VertexOrigin::Other; new triangles come last and share the
/// region of the one they split. constrained: (lo, hi) vertex pairs;
/// regionMaxEdge: per region (regionId), the bound there, 0 for none.
LongEdges splitLongEdges(Array<Point>& points, Array<VertexOrigin>& origin,
  Array<Triangle>& triangles, Array<int>& regionId, const Array<Segment>& constrained,
  const Array<double>& regionMaxEdge, double maxAngleDeg, RunContext& run);

} // namespace osm

#endif
