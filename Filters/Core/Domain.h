// Choosing the part of the triangulated box that is returned: the regions
// enclosed by segments (exterior removed, like Triangle's -p), or everything,
// minus holes grown from seed points; each remaining triangle gets a region id.
#ifndef osm_Domain_h
#define osm_Domain_h

#include "Geometry.h"
#include "HugePages.h"
#include "RunContext.h"

#include <array>
#include <cstdint>
#include <vector>

namespace osm
{

/// Adjacency known in advance for the first triangles of a carving (the
/// overlay triangles that no segment crosses): per edge i, opposite vertex i,
/// the neighbouring triangle, -1 for none, or kUnknownNeighbour to find it by
/// matching edges (on both sides of the edge: a side matched alone finds no
/// partner); and whether the edge is constrained (bit i).
struct KnownAdjacency
{
  static constexpr int kUnknownNeighbour = -2;
  Array<std::array<int, 3>> nbr;
  Array<std::uint8_t> constrained;
};

struct Carving
{
  Array<int> regionId; ///< per input triangle: its region, or -1 if removed
  std::size_t regions = 0;
  /// Hole seeds outside the domain, or in a region an earlier seed names.
  Array<int> unusedHoles;
  /// Hole seeds on a segment or at a segment's end (within rounding) where
  /// regions of the domain meet. The region taken is the same in every mesh
  /// of the input: the one the direction +x from the seed enters, the one
  /// above where a segment runs along +x (at a segment's end, the first
  /// counter-clockwise from +x if +x leads out of the domain).
  /// Seeds on the domain's boundary or on a dangling segment are not listed:
  /// only one region is there to take.
  Array<int> seedsOnSegments;
  /// Hole seeds on the domain's boundary (within rounding): they remove the
  /// region inside, the only one there.
  Array<int> seedsOnBoundary;
  /// Per region seed (carveDomain's regionSeeds): its region, or -1 if it lies
  /// outside the remaining triangles.
  Array<int> seedRegion;
  /// Region seeds on a segment or at a segment's end (within rounding) where
  /// two regions meet: they give their attribute to a region chosen as for
  /// seedsOnSegments.
  Array<int> regionSeedsOnSegments;
  /// Removing the exterior left no triangle (before any hole): the segments'
  /// cycles enclose no area (collinear segments over each other).
  bool enclosedNothing = false;
  /// Constrained edges with no remaining triangle on either side: pieces of
  /// segments outside every enclosed region, or in a hole.
  Array<Segment> droppedConstrained;
};

/// Up to this many hole seeds, carveDomain finds the triangle under each one
/// by a scan of the triangles; beyond it, by a grid of their bounding boxes
/// (linear in the triangles and seeds). Both give the same triangle.
constexpr std::size_t kHoleSeedsScanned = 8;

/// removeExterior: drop triangles reachable from the box boundary without
/// crossing a constrained edge. constrained holds (lo, hi) vertex pairs.
/// known, the adjacency of the first triangles, must agree with them; it spares
/// matching those edges, and its arrays are reused (move it in). regionSeeds
/// are located after the holes are removed (Carving::seedRegion).
Carving carveDomain(const Array<Point>& points, const Array<Triangle>& triangles,
  const Array<Segment>& constrained, bool removeExterior, const Array<Point>& holes,
  KnownAdjacency known = {}, const Array<Point>& regionSeeds = {},
  RunContext& run = RunContext::silent());

/// Convex hull of the points, counter-clockwise, without collinear vertices.
Array<int> convexHull(const Array<Point>& points);

/// The convex hull as the boundary of the hull domain: with, in order, every
/// point that lies on a hull edge within rounding. The hull segments must pass
/// through such points: missing one by an ulp would leave the hull segment
/// and the segments at that point closer than double precision separates.
/// Empty when the hull has no area, or none at double precision (a point
/// within rounding of both chains, or a corner within rounding of the other
/// chain, as in a zigzag 1e-15 high on a unit length).
Array<int> hullBoundary(const Array<Point>& points);

/// True if the segments contain a cycle (so they enclose some region).
bool segmentsEncloseRegion(std::size_t pointCount, const Array<Segment>& segments);

} // namespace osm

#endif
