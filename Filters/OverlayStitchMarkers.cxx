// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
#include "OverlayStitchMarkers.h"

#include "vtkDataArray.h"

#include "Mesher.h"
#include "Pslg.h"

#include <algorithm>
#include <unordered_map>

namespace
{
std::uint64_t Key(int a, int b)
{
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

/// A mesh vertex of edge vertex i, or -1.
int InMesh(const osm::Result& result, int i)
{
  return i >= 0 && static_cast<std::size_t>(i) < result.edgeVertexInMesh.size()
    ? result.edgeVertexInMesh[static_cast<std::size_t>(i)]
    : -1;
}
} // namespace

OverlayStitchMarkers::OverlayStitchMarkers(const osm::Pslg& pslg, const osm::Result& result,
  vtkDataArray* segmentMarkers, const std::vector<vtkIdType>& segmentCells)
  : Result(result)
  , SegmentMarker(pslg.segments.size(), 0)
  , OnSegment(result.mesh.vertices.size(), 0)
  , BoundaryVertex(result.mesh.vertices.size(), 0)
{
  // Segments given twice (the core keeps one) share a nonzero marker, as
  // Triangle overwrites a 0 with the other's.
  std::unordered_map<std::uint64_t, int> nonzero;
  for (std::size_t s = 0; segmentMarkers && s < pslg.segments.size(); ++s)
  {
    const int marker = static_cast<int>(segmentMarkers->GetComponent(segmentCells[s], 0));
    this->SegmentMarker[s] = marker;
    if (marker != 0)
    {
      nonzero.emplace(Key(pslg.segments[s][0], pslg.segments[s][1]), marker);
    }
  }
  for (std::size_t s = 0; s < pslg.segments.size() && !nonzero.empty(); ++s)
  {
    const auto found = nonzero.find(Key(pslg.segments[s][0], pslg.segments[s][1]));
    if (this->SegmentMarker[s] == 0 && found != nonzero.end())
    {
      this->SegmentMarker[s] = found->second;
    }
  }
  // The vertices on a marked segment: the ends of its subsegments (input
  // vertices inside it, crossings, points merged into others included).
  for (const osm::Edge& e : result.edges)
  {
    const int marker =
      e.segment >= 0 && static_cast<std::size_t>(e.segment) < this->SegmentMarker.size()
      ? this->SegmentMarker[static_cast<std::size_t>(e.segment)]
      : 0;
    for (const int end : { InMesh(result, e.a), InMesh(result, e.b) })
    {
      if (marker != 0 && end >= 0 && this->OnSegment[static_cast<std::size_t>(end)] == 0)
      {
        this->OnSegment[static_cast<std::size_t>(end)] = marker;
      }
    }
  }
  // The boundary: the edges of one triangle.
  std::vector<std::uint64_t> all;
  all.reserve(3 * result.mesh.triangles.size());
  for (const osm::Triangle& t : result.mesh.triangles)
  {
    all.push_back(Key(t[0], t[1]));
    all.push_back(Key(t[1], t[2]));
    all.push_back(Key(t[2], t[0]));
  }
  std::sort(all.begin(), all.end());
  for (std::size_t i = 0; i < all.size();)
  {
    std::size_t j = i + 1;
    while (j < all.size() && all[j] == all[i])
    {
      ++j;
    }
    if (j - i == 1)
    {
      this->Boundary.push_back(all[i]);
      this->BoundaryVertex[all[i] >> 32] = 1;
      this->BoundaryVertex[all[i] & 0xffffffffu] = 1;
    }
    i = j;
  }
}

int OverlayStitchMarkers::Vertex(int v, int own) const
{
  if (own != 0 || v < 0 || static_cast<std::size_t>(v) >= this->OnSegment.size())
  {
    return own;
  }
  const auto i = static_cast<std::size_t>(v);
  return this->OnSegment[i] != 0 ? this->OnSegment[i] : this->BoundaryVertex[i] ? 1 : 0;
}

int OverlayStitchMarkers::Edge(std::size_t e) const
{
  const osm::Edge& edge = this->Result.edges[e];
  const int marker = (edge.flags & osm::EdgeInput) && edge.segment >= 0 &&
      static_cast<std::size_t>(edge.segment) < this->SegmentMarker.size()
    ? this->SegmentMarker[static_cast<std::size_t>(edge.segment)]
    : 0;
  return marker != 0                                                                 ? marker
    : this->BoundaryEdge(InMesh(this->Result, edge.a), InMesh(this->Result, edge.b)) ? 1
                                                                                     : 0;
}

bool OverlayStitchMarkers::BoundaryEdge(int a, int b) const
{
  return a >= 0 && b >= 0 &&
    std::binary_search(this->Boundary.begin(), this->Boundary.end(), Key(a, b));
}
