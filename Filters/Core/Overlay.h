// Phase 1: the overlay mesh of the input points by Sparse Voronoi Refinement.
#ifndef osm_Overlay_h
#define osm_Overlay_h

#include "Geometry.h"
#include "HugePages.h"
#include "RunContext.h"
#include "SizeBoxes.h"
#include "Triangulation.h"

#include <string>
#include <vector>

namespace osm
{

struct OverlayOptions
{
  double gamma = 1.0; ///< radius / shortest-edge bound Γ (with gapRatio, the gap-ratio bound)
  /// Bound the gap ratio instead (the paper's Definition 2, the premise of
  /// its Lemma 2): every triangle's circumradius at most Γ times the
  /// distance from each of its corners to that corner's nearest neighbour,
  /// which may be a vertex of another triangle.
  bool gapRatio = false;
  double maxEdgeLength = 0.0; ///< 0: no size bound
  std::size_t maxSteinerPoints = 0;
  /// Skinny triangles are refined at their off-center instead of their
  /// circumcenter: fewer Steiner points, the same guarantees (Overlay.cxx).
  bool offCenters = true;
  /// Where the mesh is wanted: a triangle entirely outside these bounds that
  /// holds no waiting input point is left as it is (no output triangle comes
  /// from it). Off: every triangle of the box is refined.
  bool limitRefinement = false;
  Bounds refineWithin;
  /// With limitRefinement, the maximum edge length applies to the triangles
  /// that meet these bounds (within refineWithin: where output can be);
  /// beyond them only quality counts.
  Bounds sizeWithin;
  /// Instead, maxEdgeLength applies only where the size boxes put it (the
  /// mesher's boxes around separate cycles of segments carry it).
  bool sizeInBoxesOnly = false;
  /// Triangles that meet one of these boxes have no edge longer than its
  /// bound (whatever maxEdgeLength and sizeWithin say).
  Array<SizeBox> sizeBoxes;
  /// Some size boxes carry a region's maximum triangle area (for messages).
  bool sizeFromAreas = false;
};

struct Overlay
{
  /// Delaunay triangulation of a padded box, the input points and Steiner points,
  /// with every triangle of radius/edge ratio (or gap ratio) at most Γ (with limitRefinement,
  /// every triangle that meets refineWithin). Vertices 0..3 are the box corners
  /// (counter-clockwise from the lower left).
  Triangulation mesh;
  Array<int> inputVertex; ///< input point index -> mesh vertex
  Array<char> isInput;    ///< per mesh vertex
  /// Steiner points inserted, not counting the kBoxCorners corners.
  std::size_t steinerPoints = 0;
  std::size_t refinementsSkipped = 0; ///< triangles that could not be refined (numerics)
};

/// The padded box's corners, the overlay's first Steiner points: a cap on
/// Steiner points (OverlayOptions::maxSteinerPoints) counts them.
constexpr std::size_t kBoxCorners = 4;

/// The machine's physical memory in bytes, or its control group's limit
/// where lower (a container), or 0 where unknown: a size bound asking for a
/// mesh beyond it is refused before refining. Not the memory free now, which
/// changes from run to run. Read at the first call, once per process.
double physicalMemoryBytes();

/// The tightest memory limit on this process's control group and its
/// ancestors (cgroup v2's memory.max, v1's memory.limit_in_bytes; a
/// container, a systemd scope or a batch job limits the process there), or
/// 0: none, or not Linux. root is prepended to /proc and /sys: "" for the
/// system's, a directory of files laid out alike for the tests.
double cgroupMemoryLimit(const std::string& root);

/// What a process holding a mesh takes per output triangle, at most, as
/// measured: the core's own peak 75 bytes, osm-mesh's whole process 99 to
/// 159 (a review measured 150 on la.poly with a size bound).
constexpr double kBytesPerTriangle = 150;

/// The points a mesh may have in memoryBytes (kBytesPerTriangle, 2 triangles
/// per point): the overlay's cap and the stitching walk's limits.
inline double meshPointsMemoryHolds(double memoryBytes)
{
  return memoryBytes / (2 * kBytesPerTriangle);
}

/// Meshes of at most so many points are not checked against the memory:
/// reading its limits (physicalMemoryBytes) takes 0.2 to 0.7 ms at a
/// process's first call, more than meshing a small input, and they take
/// 20 MB. Larger ones ask when they get there.
constexpr double kPointsUncheckedAgainstMemory = 65536;

/// The memory a mesh of kPointsUncheckedAgainstMemory points takes.
constexpr double kBytesUncheckedAgainstMemory =
  kPointsUncheckedAgainstMemory * 2 * kBytesPerTriangle;

/// The memory to check a mesh needing `bytes` against: physicalMemoryBytes(),
/// or 0 (no check) for a mesh of at most kPointsUncheckedAgainstMemory points.
inline double memoryToCheck(double bytes)
{
  return bytes > kBytesUncheckedAgainstMemory ? physicalMemoryBytes() : 0;
}

/// Mesh the points (distinct, finite) alone; segments are ignored here.
Overlay buildOverlay(const Array<Point>& points, const OverlayOptions& options, RunContext& run);

/// Gap ratio Γ for an overlay minimum angle θ1 (degrees): sin θ1 = 1 / (2Γ).
/// For 0 < θ1 <= 90, the range Options allows (1 to 35) and more.
double gammaForMinAngle(double minAngleDeg);

/// The inverse: θ1 in degrees for a gap ratio Γ >= 1/2 (osm-mesh's --gamma).
double minAngleForGamma(double gamma);

} // namespace osm

#endif
