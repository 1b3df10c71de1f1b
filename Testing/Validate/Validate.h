// An independent checker of a mesher's output, used by the tests.
// It re-derives everything from the input PSLG and the triangles, sharing no
// code with the mesher but the exact predicates.
#ifndef osm_Validate_h
#define osm_Validate_h

#include "Pslg.h"

#include <string>
#include <vector>

namespace osm
{

/// What the mesh's boundary may run along (check 9).
enum class DomainBoundary
{
  Unchecked,      ///< anything
  Segments,       ///< input segments only (the enclosed domain)
  SegmentsOrHull, ///< input segments or the convex hull of the input points
  SegmentsOrBox   ///< input segments or the mesh's own bounding rectangle
};

struct ValidationOptions
{
  /// Every angle must be at most this. Angles are measured in double precision
  /// (atan2 of a cross and a dot product): within about 1e-13 degrees, so an
  /// angle closer than that to the bound may be judged either way (a review
  /// found 455 of 200,000 triangles within 1e-13 rad of 170 misjudged). The
  /// mesher's bound, 169.95 degrees at 30, lies far from such a margin.
  double maxAngleDeg = 170.0;
  double maxEdgeLength = 0.0; ///< if > 0, every edge must be at most this long
  /// Require the triangles to cover the whole region enclosed by their boundary
  /// without overlap. Brute-force pairwise overlap check up to this many triangles.
  std::size_t bruteForceOverlapLimit = 3000;
  /// Also check conformity (every input segment is a chain of mesh edges) for
  /// segments whose endpoints are both mesh vertices.
  bool checkConformity = true;
  /// If > 0, the merge tolerance the mesh was made with: before checking
  /// conformity, each input segment is split at the input points within this
  /// distance of it (strictly between its ends, by brute force over every
  /// point and segment: O(points x segments)), and each piece must be a chain.
  double snapTolerance = 0.0;
  /// If > 0, how far off its input segment's line a vertex of the segment's
  /// chain may lie (after the split above): where a merge tolerance joined
  /// the crossings of segments, the chains bend through the joined points.
  /// A chain passes if it is straight (within the rounding allowance: 1e-9
  /// of the length plus 17 times the coordinates' magnitude times epsilon)
  /// between bends, each bend a vertex within this offset of the segment and
  /// within twice it of another input segment (a crossing joined there; a
  /// later round's crossing of two bent pieces may lie twice as far). Weaker
  /// than the check without a tolerance only where segments pass that close:
  /// flipping mesh edges on segments of freely crossing segments meshed at
  /// 1e-3 of the extent breaks conformity, and 115 of 12,829 such flips
  /// still pass, where segments pass that close (355 when any vertex within
  /// the offset could complete a chain; Properties.FlippedEdgesOnSegments...).
  double chainOffset = 0.0;
  /// Also check that every input point is a mesh vertex. Off when holes may remove some.
  bool requireAllInputVertices = true;
  /// Check 9, the domain: every boundary edge of the mesh lies along what this allows
  /// (within the rounding allowance, plus snapTolerance and chainOffset): a triangle
  /// missing inside a region bounded by segments, or one beyond them, leaves such an edge.
  /// A whole region missing, bounded by segments all round, is not seen (the hole seeds
  /// below and the tests' areas are what see it).
  DomainBoundary boundary = DomainBoundary::Unchecked;
  /// Check 9, the holes: no hole seed (Pslg::holes) lies in a closed triangle, unless it
  /// lies on an input segment (within the rounding allowance, plus snapTolerance and
  /// chainOffset), where the mesher removes one side and keeps the other.
  bool checkHoles = false;
  /// Keep at most this many messages in ValidationReport::errors (all are still counted).
  std::size_t maxErrorMessages = 50;
};

struct ValidationReport
{
  bool ok = true;
  std::vector<std::string> errors; ///< at most a few dozen, each naming the element
  std::size_t errorCount = 0;      ///< every failure found, kept in errors or not
  double minAngleDeg = 0.0;
  double maxAngleDeg = 0.0;
  std::size_t triangles = 0;
};

/// Checks, independently of the mesher: index validity, exact positive
/// orientation, manifold and consistently oriented edges, a non-overlapping cover (vertex fans,
/// boundary edges, vertices inside triangles, pairwise overlap for small meshes), no coincident
/// mesh vertices, input points present, input segments conforming, the angle bound, the
/// edge length bound if one is given, and if asked the domain's boundary and holes.
/// O(n log n) beyond the brute-force limit; ok is false iff errorCount > 0.
ValidationReport validate(const Pslg& input, const Array<Point>& vertices,
  const Array<Triangle>& triangles, const ValidationOptions& options = {});

} // namespace osm

#endif
