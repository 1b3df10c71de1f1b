// Triangle's boundary markers (triangle.markers.html), for the filter's
// PointMarker and SegmentMarker and for the .node and .edge files. A vertex:
// its own nonzero marker, else a nonzero marker of a segment it lies on,
// else 1 on the mesh's boundary (the holes' included), else 0. An edge: a
// nonzero marker of the segment it is part of, else 1 on the boundary, else 0.
#ifndef osm_TriangleMarkers_h
#define osm_TriangleMarkers_h

#include "Mesher.h"

#include <cstdint>
#include <vector>

namespace osm
{

/// Triangle's rule for what has no nonzero marker of its own: 1 on the
/// boundary, else 0.
inline int boundaryMarker(int marker, bool onBoundary)
{
  return marker != 0 ? marker : onBoundary ? 1 : 0;
}

/// The edges of a mesh, each once, sorted by (lower vertex, higher vertex),
/// and which lie on its boundary: those of one triangle (the holes' included).
class MeshEdges
{
public:
  /// Boundary keeps only the boundary's edges (grouping the sides takes 12
  /// bytes per triangle and 16 per vertex either way, given back; the keys
  /// take 9 bytes per edge kept).
  enum class Keep
  {
    All,
    Boundary
  };
  explicit MeshEdges(const TriMesh& mesh, Keep keep = Keep::All);

  std::size_t size() const { return keys_.size(); }
  int lower(std::size_t k) const { return static_cast<int>(keys_[k] >> 32); }
  int higher(std::size_t k) const { return static_cast<int>(keys_[k] & 0xffffffffu); }
  bool onBoundary(std::size_t k) const { return boundary_[k] != 0; }
  bool vertexOnBoundary(int v) const;
  /// Whether (a, b), either way round, is an edge of the boundary.
  bool edgeOnBoundary(int a, int b) const;
  /// The index of edge (a, b) either way round, or size() if none is kept.
  std::size_t find(int a, int b) const;

private:
  std::vector<std::uint64_t> keys_; ///< (lower << 32) | higher
  std::vector<char> boundary_;      ///< per key
  std::vector<char> boundaryVertex_;
};

/// Triangle's markers of a mesh, from its input's segment markers.
class TriangleMarkers
{
public:
  /// result: pslg's, with its edges (Options::keepEdges). segmentMarkers:
  /// per Pslg segment, or empty (every segment 0). Segments given twice
  /// share a nonzero marker, as Triangle overwrites a 0 with the other's.
  TriangleMarkers(const Pslg& pslg, const Result& result, std::vector<int> segmentMarkers);
  /// It keeps a reference to result, which must outlive it.
  TriangleMarkers(const Pslg&, Result&&, std::vector<int>) = delete;

  /// Mesh vertex v's marker, own being its own marker (0: none).
  int vertex(int v, int own) const;
  /// The marker of result.edges[e].
  int edge(std::size_t e) const;

private:
  int inMesh(int edgeVertex) const;
  /// The marker of result.edges[e]'s segment if it is an input subsegment, else 0.
  int segmentOf(std::size_t e) const;

  const Result& result_;
  MeshEdges edges_;
  std::vector<int> segmentMarker_; ///< per Pslg segment
  std::vector<int> onSegment_;     ///< per mesh vertex: a nonzero marker of a segment through it
};

} // namespace osm

#endif
