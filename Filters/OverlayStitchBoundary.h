// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// Internal to OverlayStitch::Filters (not installed): the boundary of the
// mesh (its edges of one triangle, the holes' included), which Triangle's
// boundary markers mark 1 where no segment marks them otherwise.
#ifndef OverlayStitchBoundary_h
#define OverlayStitchBoundary_h

#include <cstdint>
#include <vector>

namespace osm
{
struct TriMesh;
}

class OverlayStitchBoundary
{
public:
  explicit OverlayStitchBoundary(const osm::TriMesh& mesh);
  /// Whether mesh vertex v is on the boundary.
  bool HasVertex(int v) const;
  /// Whether the mesh edge between vertices a and b is a boundary edge.
  bool HasEdge(int a, int b) const;

private:
  std::vector<std::uint64_t> Edges; ///< (lower vertex << 32) | higher, sorted
  std::vector<unsigned char> Vertices;
};

#endif
