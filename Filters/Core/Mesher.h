// The single entry point of Overlay Stitch Meshing: osm::mesh().
#ifndef osm_Mesher_h
#define osm_Mesher_h

#include "HugePages.h"
#include "Pslg.h"
#include "Statistics.h"

#include <cstdint>
#include <string>
#include <vector>

namespace osm
{

/// What part of the plane the returned triangles cover.
enum class Domain
{
  Auto,     ///< Enclosed if a region's boundary has input points, else Hull (Mesher.cxx).
  Enclosed, ///< Regions enclosed by segments (the exterior removed, like Triangle's -p).
  Hull,     ///< The convex hull of the input points (Box, warned, where it has no area).
  Box       ///< The whole padded bounding box of the overlay.
};

/// The range of θ1 (Options::minAngleDeg) the mesher takes, in degrees; the
/// command-line tool and the VTK filter check or clamp to the same.
inline constexpr double kMinAngleDegLowest = 1.0;
inline constexpr double kMinAngleDegHighest = 35.0;

struct Options
{
  /// θ1: the smallest angle of the overlay mesh, in degrees (Γ = 1 / (2 sin θ1)).
  /// 30° gives Γ = 1 and the bound 180° − θ2 ≈ 169.95°.
  double minAngleDeg = 30.0;
  /// The overlay's quality. The paper proves the largest-angle bound for an
  /// overlay of gap-ratio quality Γ (Definition 2: every triangle's
  /// circumradius at most Γ times the distance from each corner to its
  /// nearest neighbour, Lemma 2's premise). By default the overlay bounds
  /// radius / shortest edge only (the corners' own triangle), as Delaunay
  /// refinement does: up to 12.5 times fewer triangles on the real inputs, whose
  /// meshes all stay below 150°, but no proof; a mesh from it with an angle
  /// above the bound (or remeshAboveDeg) is made again from a gap-ratio
  /// overlay, with a warning. True: the gap-ratio overlay at once.
  bool gapRatioOverlay = false;
  /// The largest angle above which a mesh from the radius-edge overlay is
  /// made again from a gap-ratio one; 0: the bound 180° − θ2; at most 180.
  /// (Not with minAngleDeg above 30, where nothing is proven, nor where the
  /// second mesh, at 13 times the first's triangles, would not fit in this
  /// machine's memory: a warning says so.) The statistics are the second
  /// mesh's, but SecondsTotal counts both.
  double remeshAboveDeg = 0.0;
  /// If > 0, no output edge is longer: overlay triangles with a longer edge
  /// are refined further, and the few longer diagonals that completion makes
  /// are split (a warning names any that cannot be; LongEdges.h).
  double maxEdgeLength = 0.0;
  Domain domain = Domain::Auto;
  /// Split crossing segments at their intersection (true) or refuse them (false).
  bool resolveCrossings = true;
  /// Points at most this far apart (absolute distance) are merged into the
  /// first of them, and segments split at the points within this of them (they
  /// bend by at most this much; Snap.h). Crossings split in the rounds join
  /// a point or crossing within this, if it lies within this of the
  /// pieces of the input through the crossing: a segment bends through it by
  /// at most this much too, however many rounds its pieces cross again in.
  /// 0 merges only exact duplicates.
  double mergeTolerance = 0.0;
  /// Stop with an error when the overlay of a meshing round would need more
  /// Steiner points than this (0: no cap), counted as
  /// Statistics::overlaySteinerPoints counts the last round's: the 4 corners of its
  /// padding box and the points refining it, in the padding too; not the
  /// points stitching and completion put on segments.
  std::size_t maxSteinerPoints = 0;
  /// Apply the regions' maximum areas (Pslg::regions; Triangle's -a): off,
  /// they are ignored with a warning, as Triangle ignores them without -a
  /// (a region line of 4 numbers gives its attribute as its area too).
  bool regionAreas = false;
  /// Keep the phase-1 overlay and the classified edges in the result (for inspection).
  bool keepOverlay = true;
  bool keepEdges = true;
  /// Fill Result::vertexSegment (for carrying data along the segments).
  bool keepVertexSegments = false;
  /// Writes the coordinates of points named in warnings and errors (input
  /// points, crossings, seeds); empty: "(x, y)" in the input's coordinates.
  PointFormat pointFormat;
};

/// Receives progress and may ask the mesher to stop.
class Progress
{
public:
  virtual ~Progress() = default;
  /// fraction in [0, 1] over the whole run; phase names the current phase.
  /// Where the mesh is made again from a gap-ratio overlay (Options::
  /// gapRatioOverlay), the second run reports from 0 again.
  virtual void report(double fraction, const char* phase) = 0;
  /// Polled regularly; returning true makes mesh() stop with the error kAbortedByTheUser
  /// (RunContext.h).
  virtual bool aborted() { return false; }
};

/// Where an output vertex comes from (values match the VertexOrigin array).
enum class VertexOrigin : std::uint8_t
{
  Input = 0,   ///< an input vertex
  Overlay = 1, ///< a Steiner point of the phase-1 overlay
  Stitch = 2,  ///< an intersection of an input segment with a kept overlay edge
  Other = 3    ///< a crossing of input segments, or the point splitting a long completed edge
};

/// Bit flags of an edge in Result::edges.
enum EdgeFlag : std::uint8_t
{
  EdgeOverlay = 1,   ///< an edge of the phase-1 overlay
  EdgeKept = 2,      ///< an overlay edge that survived stitching
  EdgeDiscarded = 4, ///< an overlay edge crossed only at bad (small) angles
  EdgeInput = 8,     ///< an input subsegment
  EdgeCrossed = 16   ///< an overlay edge crossed by at least one segment
};

/// Category of an edge, derived from its flags (values of the EdgeClass array).
enum class EdgeClass : std::uint8_t
{
  Uncrossed = 0, ///< overlay edge no segment crosses
  Kept = 1,      ///< overlay edge crossed at a good angle: split and kept
  Discarded = 2, ///< overlay edge crossed only at bad angles: removed
  Input = 3      ///< input subsegment (possibly also an overlay edge)
};

struct Edge
{
  int a = -1;
  int b = -1;
  std::uint8_t flags = 0;
  /// An input subsegment's input segment (-1: a hull edge, or any other edge).
  int segment = -1;
};

EdgeClass edgeClass(std::uint8_t flags);

/// The class's name: "Uncrossed", "Kept", "Discarded" or "Input".
const char* edgeClassName(EdgeClass c);

/// A triangle mesh: vertices and counter-clockwise triangles.
struct TriMesh
{
  Array<Point> vertices;
  Array<Triangle> triangles;
};

struct Result
{
  bool ok = false;
  std::string error;                 ///< why ok is false (names the offending items)
  std::vector<std::string> warnings; ///< repairs made and input that was ignored

  TriMesh mesh; ///< the conforming triangulation
  /// The domain the mesh covers: Enclosed, Hull or Box (what Auto chose, and
  /// Box where a hull without area fell back to it); Auto where nothing was
  /// meshed (no points, or an error).
  Domain domain = Domain::Auto;
  Array<VertexOrigin> vertexOrigin; ///< per mesh vertex
  Array<int> regionId;              ///< per mesh triangle
  /// Per mesh triangle when the input has regional attributes (else empty): the
  /// attribute of the last region seed in its region, as Triangle's -A gives,
  /// 0 in regions no seed lies in.
  Array<double> regionAttribute;
  /// For each input point (by its index in the Pslg), its vertex in mesh, or -1 if
  /// it lies outside the returned domain (e.g. inside a hole).
  Array<int> inputVertex;
  /// When Options::keepVertexSegments: per mesh vertex, an input segment that
  /// the walks found it on (a stitch vertex, a crossing, an overlay vertex a
  /// segment passes through, the ends of segments), else -1 (hull edges are
  /// no input segment). With a merge tolerance it lies on that segment's
  /// bent chain, within the tolerance of the segment.
  Array<int> vertexSegment;

  /// Overlay edges (uncrossed, kept, discarded) and input subsegments; indices
  /// refer to edgeVertices. Filled when Options::keepEdges.
  Array<Point> edgeVertices;
  Array<Edge> edges;
  /// Per edge vertex, the mesh vertex it is, or -1 outside the domain.
  /// Filled when Options::keepEdges.
  Array<int> edgeVertexInMesh;

  /// The phase-1 overlay triangulation. Filled when Options::keepOverlay. Of
  /// quality θ1 within the bounds of the segments (enclosed domain) or of the
  /// points (hull domain), and all over for Domain::Box.
  TriMesh overlay;

  Statistics stats;
};

/// Mesh a PSLG with Overlay Stitch Meshing. Never throws for bad input: returns
/// ok = false with a message instead. Deterministic: same input, same output.
Result mesh(const Pslg& input, const Options& options = {}, Progress* progress = nullptr);

/// The bound 180° − θ2 on every output angle, for an overlay angle θ1
/// (degrees), 0 < θ1 <= 60: the range Options allows (1 to 35) and more.
double predictedMaxAngleDeg(double minAngleDeg);

} // namespace osm

#endif
