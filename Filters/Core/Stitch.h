// Phase 2: stitching the input segments into the overlay.
//
// Each segment is walked through the overlay from one endpoint to the other,
// listing the overlay edges it crosses and the vertices it passes through
// (which split it into pieces). A crossing is good when the segment meets the
// edge at an angle above θ1. An overlay edge is kept if it is uncrossed or has
// a good crossing, discarded otherwise; every crossing on a kept edge becomes a
// stitch vertex splitting both. The walks also find segments that cross each
// other (they share an overlay triangle) or overlap.
#ifndef osm_Stitch_h
#define osm_Stitch_h

#include "Domain.h"
#include "HugePages.h"
#include "Mesher.h"
#include "Overlay.h"
#include "RunContext.h"

#include <array>
#include <cstdint>
#include <vector>

namespace osm
{

/// The overlay in compact form: live triangles and their neighbours. An edge
/// is named by a half-edge, 3c + i for edge i (opposite vertex i, from vertex
/// i+1 to i+2) of c, the smaller of its two triangles: increasing ids list
/// every edge once, with no array over the edges.
struct OverlayEdges
{
  Array<Triangle> tris;
  Array<std::array<int, 3>> nbr; ///< across the edge opposite vertex i, or -1
  Array<int> vtri;               ///< one triangle per vertex

  /// Whether half-edge h is an edge id (its triangle is the smaller one).
  bool isEdge(int h) const
  {
    const int u = nbr[h / 3][h % 3];
    return u < 0 || h / 3 < u;
  }
  /// The half-edge of the neighbour across edge i of triangle c that faces
  /// back, or -1 on the box's boundary.
  int twin(int c, int i) const;
  /// The id of edge i of triangle c.
  int edgeId(int c, int i) const
  {
    const int u = nbr[c][i];
    return u < 0 || c < u ? 3 * c + i : twin(c, i);
  }
  /// The ends of an edge, in the order of the triangle its id names.
  Segment ends(int id) const
  {
    const Triangle& t = tris[id / 3];
    return { t[(id % 3 + 1) % 3], t[(id % 3 + 2) % 3] };
  }
  /// Ids are below this bound.
  std::size_t idBound() const { return 3 * tris.size(); }
  /// Calls f(t, i) for the triangles t around vertex v (its corner i),
  /// counter-clockwise from vtri[v], until f returns true (then returns t),
  /// the turn closes or meets the boundary (then returns -1).
  template <typename F>
  int aroundVertex(int v, F&& f) const
  {
    int t = vtri[v];
    for (std::size_t k = 0; k <= tris.size() && t >= 0; ++k)
    {
      const int i = cornerOf(tris[t], v);
      if (f(t, i))
        return t;
      t = nbr[t][(i + 1) % 3];
      if (t == vtri[v])
        break;
    }
    return -1;
  }
  /// Calls f(u) for each neighbour u of vertex v.
  template <typename F>
  void forEachNeighbour(int v, F&& f) const
  {
    aroundVertex(v, [&](int t, int i) {
      f(tris[t][(i + 1) % 3]);
      return false;
    });
  }
};

/// The overlay's live triangles in compact form. Releases the mesh's
/// triangles and vertex links (its points stay): nothing after this walks or
/// inserts into the overlay.
OverlayEdges compactOverlay(Triangulation& mesh, RunContext& run = RunContext::silent());

/// A maximal part of a segment between two overlay vertices.
struct Piece
{
  int v0 = -1, v1 = -1;
  int segment = -1;     ///< index of the (clean) segment it belongs to
  int overlayEdge = -1; ///< the overlay edge it runs along, if any
  int firstCrossing = 0;
  int crossingCount = 0;
  bool duplicate = false; ///< the same piece came from an overlapping segment
};

struct Crossing
{
  int edge = -1;
  int piece = -1;
  double s = 0; ///< position along the overlay edge, from ends(edge)[0] to [1]
  Point p;
  bool good = false;
  /// p is within rounding of where it should be, relative to the edge's
  /// length (false where the segment's coordinates are too large for it).
  bool resolved = true;
};

/// A dangling segment end (overlay vertex) near a segment it does not touch.
struct NearMiss
{
  int end = -1;
  int endSegment = -1; ///< the one segment that ends there
  int segment = -1;
  double distance = 0;
};

/// Two clean segments that cross at p.
struct SegmentCrossing
{
  int a = -1, b = -1;
  Point p;
};

/// Sorts the crossings by their pair of segments and keeps the first record
/// of each: stable, so that reducing them on the way keeps the same ones.
void keepFirstOfEachPair(Array<SegmentCrossing>& sc);

/// The walks' results. Segments are walked in spatial order, not in index
/// order, so pieces and crossings come in that order; firstPiece gives each
/// segment's pieces (contiguous, along the segment) so that every use that
/// affects the output can visit them in segment order, as if walked so.
struct Walk
{
  Array<Piece> pieces;
  Array<Crossing> crossings;
  Array<int> firstPiece; ///< per segment: where its pieces start (none if it has none)
  Array<SegmentCrossing> segmentCrossings;
  std::size_t segmentCrossingsReduced = 0; ///< times reduced to one per pair on the way
  std::size_t splitsAtInputVertices = 0;
  /// Per duplicate piece: the segment whose piece is kept, the duplicate's
  /// segment (the later in rank), and the overlay vertices the piece runs between.
  Array<std::array<int, 4>> overlaps;
  /// Segment ends that meet no other segment (none ends or passes there) yet
  /// lie within the search's reach of one they do not touch, as isolines cut
  /// in floats end short of their boundary: they dangle, and the regions they
  /// were to part stay one. Once per end, with the nearest such segment.
  Array<NearMiss> nearMisses;
};

/// What the walks look for besides crossings: segment ends that dangle
/// within reach of a segment they do not reach. Segments from inputSegments
/// on (the convex hull's edges) are not the user's: no near miss names them.
/// The reach (scaled) is the larger of reach and perMagnitude times the
/// end's largest user coordinate, origin + p (float rounding, for input in
/// floats). reach 0: none looked for.
struct NearMissSearch
{
  std::size_t inputSegments = 0;
  double reach = 0;
  double perMagnitude = 0;
  Point origin;

  double at(const Point& p) const
  {
    return std::max(
      reach, perMagnitude * std::max(std::fabs(p.x + origin.x), std::fabs(p.y + origin.y)));
  }
};

/// Walk every segment (endpoints given as overlay vertices) through the overlay,
/// in the given order (a permutation of the segment indices) or, by default,
/// in the spatial order of their smaller vertex. The stitched graph does not
/// depend on the order. Where pieces of segments overlap, the piece of the
/// segment with the smallest rank is kept (ranks per segment; by default the
/// index), so that it carries that segment's data. Where the segments
/// cross more overlay edges than memoryBytes holds points in a mesh, or more
/// pairs of segments cross than a quarter of that (0: no limit; by default
/// this machine's, asked only beyond kPointsUncheckedAgainstMemory crossings),
/// throws a Stop naming a segment and a point.
Walk walkSegments(const OverlayEdges& ov, const Overlay& overlay, const Array<Segment>& segments,
  double sinTheta1, RunContext& run, const Array<int>* order = nullptr,
  const Array<int>* rank = nullptr, NearMissSearch nearMisses = {}, double memoryBytes = -1);

/// Sides of a planar-graph edge that lie in a face still to be completed.
enum OpenSide : std::uint8_t
{
  OpenLeft = 1,  ///< left of edges[e][0] -> edges[e][1]
  OpenRight = 2, ///< right of it
  OpenBoth = 3
};

/// The stitched planar graph: overlay vertices, then stitch vertices. Overlay
/// triangles with no crossed edge are faces of it already and are listed as
/// such; the edges are those of the other faces (the ones completion must
/// trace) and every input subsegment.
struct PlanarGraph
{
  Array<Point> points;
  Array<VertexOrigin> origin;
  /// Per stitch vertex (the points after the overlay's, from firstStitch on;
  /// splitting long edges appends more): the segment (index in the walked
  /// segments) whose crossing it is.
  Array<int> stitchSegment;
  std::size_t firstStitch = 0;
  Array<Triangle> intact;         ///< overlay triangles that no segment crosses
  KnownAdjacency intactAdjacency; ///< their neighbours among them, for carveDomain
  Array<Segment> edges;
  Array<char> constrained;       ///< per edge: part of an input segment
  Array<std::uint8_t> openSides; ///< per edge: OpenSide bits, 0 if only constrained
};

/// Keep or discard overlay edges and insert the kept crossings. When inspect is
/// given, it receives every overlay edge and input subsegment with its flags.
/// The graph is built in the arrays of ov and of the overlay's points (isInput
/// per point): move them in, or copy what must outlive the call.
PlanarGraph stitch(OverlayEdges ov, Array<Point> points, const Array<char>& isInput,
  const Walk& walk, Array<Edge>* inspect, Statistics& stats,
  RunContext& run = RunContext::silent());

} // namespace osm

#endif
