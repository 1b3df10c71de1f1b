// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// Internal to OverlayStitch::Filters (not installed): Triangle's boundary
// markers on the mesh, by the rules of Triangle's documentation
// (triangle.markers.html). A vertex: its own nonzero marker, else a nonzero
// marker of a segment it lies on, else 1 on the mesh's boundary (the holes'
// included), else 0. An edge: a nonzero marker of the segment it is part of,
// else 1 on the boundary, else 0.
#ifndef OverlayStitchMarkers_h
#define OverlayStitchMarkers_h

#include "vtkType.h" // for vtkIdType

#include <cstdint>
#include <vector>

class vtkDataArray;

namespace osm
{
struct Pslg;
struct Result;
}

class OverlayStitchMarkers
{
public:
  /// result must come with its edges (Options::keepEdges); segmentMarkers (the
  /// cells' "SegmentMarker", or null: every segment 0) is indexed by
  /// segmentCells, each Pslg segment's input cell.
  OverlayStitchMarkers(const osm::Pslg& pslg, const osm::Result& result,
    vtkDataArray* segmentMarkers, const std::vector<vtkIdType>& segmentCells);

  /// Mesh vertex v's marker, own being its own marker (0: none).
  int Vertex(int v, int own) const;
  /// The marker of result.edges[e].
  int Edge(std::size_t e) const;

private:
  bool BoundaryEdge(int a, int b) const;

  const osm::Result& Result;
  std::vector<int> SegmentMarker; ///< per Pslg segment; repeated ones share a nonzero one
  std::vector<int> OnSegment;     ///< per mesh vertex: a nonzero marker of a segment through it
  std::vector<std::uint64_t> Boundary; ///< boundary edges: (lower vertex << 32) | higher, sorted
  std::vector<unsigned char> BoundaryVertex;
};

#endif
