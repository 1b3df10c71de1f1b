// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
#include "OverlayStitchBoundary.h"

#include "Mesher.h"

#include <algorithm>

namespace
{
std::uint64_t Key(int a, int b)
{
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}
} // namespace

OverlayStitchBoundary::OverlayStitchBoundary(const osm::TriMesh& mesh)
  : Vertices(mesh.vertices.size(), 0)
{
  // Every triangle's edges, sorted: an edge listed once has one triangle.
  std::vector<std::uint64_t> all;
  all.reserve(3 * mesh.triangles.size());
  for (const osm::Triangle& t : mesh.triangles)
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
      this->Edges.push_back(all[i]);
      this->Vertices[all[i] >> 32] = 1;
      this->Vertices[all[i] & 0xffffffffu] = 1;
    }
    i = j;
  }
}

bool OverlayStitchBoundary::HasVertex(int v) const
{
  return v >= 0 && static_cast<std::size_t>(v) < this->Vertices.size() &&
    this->Vertices[static_cast<std::size_t>(v)] != 0;
}

bool OverlayStitchBoundary::HasEdge(int a, int b) const
{
  return a >= 0 && b >= 0 && std::binary_search(this->Edges.begin(), this->Edges.end(), Key(a, b));
}
