#include "TriangleMarkers.h"

#include <algorithm>
#include <unordered_map>

namespace osm
{

namespace
{
std::uint64_t key(int a, int b)
{
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}
} // namespace

MeshEdges::MeshEdges(const TriMesh& mesh, Keep keep)
  : boundaryVertex_(mesh.vertices.size(), 0)
{
  // The triangles' sides grouped by their lower end (a counting sort), then
  // each group's higher ends sorted: the order of sorting the keys, without
  // std::sort's passes over 3 keys per triangle (2.5 s at 8 million
  // triangles, with no progress; a review).
  const std::size_t n = mesh.vertices.size();
  std::vector<std::size_t> first(n + 1, 0); // group v: [first[v], first[v + 1])
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
      ++first[static_cast<std::size_t>(std::min(t[i], t[(i + 1) % 3])) + 1];
  for (std::size_t v = 0; v < n; ++v)
    first[v + 1] += first[v];
  std::vector<std::uint32_t> higher(3 * mesh.triangles.size());
  {
    std::vector<std::size_t> next(first.begin(), first.end() - 1);
    for (const Triangle& t : mesh.triangles)
      for (int i = 0; i < 3; ++i)
      {
        const int a = t[i], b = t[(i + 1) % 3];
        higher[next[static_cast<std::size_t>(std::min(a, b))]++] =
          static_cast<std::uint32_t>(std::max(a, b));
      }
  }
  // An edge listed once is on the boundary. The groups sorted and their
  // edges counted first, so that the keys take their size at once.
  std::size_t edges = 0;
  for (std::size_t v = 0; v < n; ++v)
  {
    const auto begin = higher.begin() + first[v], end = higher.begin() + first[v + 1];
    std::sort(begin, end); // a few each, about 3 on average
    for (auto i = begin; i != end; ++i)
      edges += (i + 1 == end || i[1] != *i) && (keep == Keep::All || i == begin || i[-1] != *i);
  }
  keys_.reserve(edges);
  boundary_.reserve(edges);
  for (std::size_t v = 0; v < n; ++v)
  {
    const auto begin = higher.begin() + first[v], end = higher.begin() + first[v + 1];
    for (auto i = begin; i != end;)
    {
      auto j = i + 1;
      while (j != end && *j == *i)
        ++j;
      const bool once = j - i == 1;
      if (once)
        boundaryVertex_[v] = boundaryVertex_[*i] = 1;
      if (once || keep == Keep::All)
      {
        keys_.push_back(static_cast<std::uint64_t>(v) << 32 | *i);
        boundary_.push_back(once);
      }
      i = j;
    }
  }
}

bool MeshEdges::vertexOnBoundary(int v) const
{
  return v >= 0 && static_cast<std::size_t>(v) < boundaryVertex_.size() &&
    boundaryVertex_[static_cast<std::size_t>(v)] != 0;
}

std::size_t MeshEdges::find(int a, int b) const
{
  if (a < 0 || b < 0)
    return size();
  const auto it = std::lower_bound(keys_.begin(), keys_.end(), key(a, b));
  return it != keys_.end() && *it == key(a, b) ? static_cast<std::size_t>(it - keys_.begin())
                                               : size();
}

bool MeshEdges::edgeOnBoundary(int a, int b) const
{
  const std::size_t k = find(a, b);
  return k < size() && onBoundary(k);
}

TriangleMarkers::TriangleMarkers(
  const Pslg& pslg, const Result& result, std::vector<int> segmentMarkers)
  : result_(result)
  , edges_(result.mesh, MeshEdges::Keep::Boundary)
  , segmentMarker_(std::move(segmentMarkers))
  , onSegment_(result.mesh.vertices.size(), 0)
{
  segmentMarker_.resize(pslg.segments.size(), 0);
  // Segments given twice (the mesher keeps one) share a nonzero marker.
  std::unordered_map<std::uint64_t, int> nonzero;
  for (std::size_t s = 0; s < pslg.segments.size(); ++s)
    if (segmentMarker_[s] != 0)
      nonzero.emplace(key(pslg.segments[s][0], pslg.segments[s][1]), segmentMarker_[s]);
  for (std::size_t s = 0; s < pslg.segments.size() && !nonzero.empty(); ++s)
  {
    const auto found = nonzero.find(key(pslg.segments[s][0], pslg.segments[s][1]));
    if (segmentMarker_[s] == 0 && found != nonzero.end())
      segmentMarker_[s] = found->second;
  }
  // The vertices on a marked segment: the ends of its subsegments (input
  // vertices inside it, crossings and points merged into others included).
  for (std::size_t e = 0; e < result.edges.size(); ++e)
  {
    const int marker = segmentOf(e);
    for (const int end : { inMesh(result.edges[e].a), inMesh(result.edges[e].b) })
      if (marker != 0 && end >= 0 && onSegment_[static_cast<std::size_t>(end)] == 0)
        onSegment_[static_cast<std::size_t>(end)] = marker;
  }
}

int TriangleMarkers::inMesh(int edgeVertex) const
{
  return edgeVertex >= 0 && static_cast<std::size_t>(edgeVertex) < result_.edgeVertexInMesh.size()
    ? result_.edgeVertexInMesh[static_cast<std::size_t>(edgeVertex)]
    : -1;
}

int TriangleMarkers::segmentOf(std::size_t e) const
{
  const Edge& edge = result_.edges[e];
  return (edge.flags & EdgeInput) && edge.segment >= 0 &&
      static_cast<std::size_t>(edge.segment) < segmentMarker_.size()
    ? segmentMarker_[static_cast<std::size_t>(edge.segment)]
    : 0;
}

int TriangleMarkers::vertex(int v, int own) const
{
  if (own != 0 || v < 0 || static_cast<std::size_t>(v) >= onSegment_.size())
    return own;
  return boundaryMarker(onSegment_[static_cast<std::size_t>(v)], edges_.vertexOnBoundary(v));
}

int TriangleMarkers::edge(std::size_t e) const
{
  const Edge& edge = result_.edges[e];
  return boundaryMarker(segmentOf(e), edges_.edgeOnBoundary(inMesh(edge.a), inMesh(edge.b)));
}

} // namespace osm
