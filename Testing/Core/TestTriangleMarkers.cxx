// Triangle's boundary markers (TriangleMarkers.h), checked against the rules
// of Triangle's documentation on a mesh whose every vertex and edge is
// classified here independently, by its coordinates.
#include "TriangleMarkers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

using namespace osm;

namespace
{

// A square (sides marked 0, 0, 3, 0) with a slit from (0.2, 0.5) to (0.8,
// 0.5) through an input point at (0.5, 0.5), given twice: first marked 0
// (the mesher keeps that one), then 5 (so the slit is 5). And a point
// inside, on no segment.
struct Marked
{
  Pslg pslg;
  std::vector<int> markers;
  Result result;

  Marked()
  {
    pslg.points = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 }, { 0.2, 0.5 }, { 0.8, 0.5 },
      { 0.5, 0.5 }, { 0.5, 0.2 } };
    pslg.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 4 } };
    markers = { 0, 0, 3, 0, 0, 5 };
    Options o;
    o.maxEdgeLength = 0.2;
    result = mesh(pslg, o);
  }
};

bool onSquare(const Point& p)
{
  return p.x == 0 || p.x == 1 || p.y == 0 || p.y == 1;
}

bool onSlit(const Point& p)
{
  return p.y == 0.5 && p.x >= 0.2 && p.x <= 0.8;
}

} // namespace

TEST(TriangleMarkers, VerticesTakeTheirOwnThenTheirSegmentsThenTheBoundarysMarker)
{
  const Marked m;
  ASSERT_TRUE(m.result.ok) << m.result.error;
  const TriangleMarkers markers(m.pslg, m.result, m.markers);
  std::size_t top = 0, slit = 0, inside = 0;
  for (std::size_t v = 0; v < m.result.mesh.vertices.size(); ++v)
  {
    const Point& p = m.result.mesh.vertices[v];
    const int expected = p.y == 1 ? 3 : onSquare(p) ? 1 : onSlit(p) ? 5 : 0;
    top += expected == 3, slit += expected == 5, inside += expected == 0;
    EXPECT_EQ(markers.vertex(static_cast<int>(v), 0), expected)
      << "vertex " << v << " at (" << p.x << ", " << p.y << ")";
    // A vertex's own nonzero marker wins.
    EXPECT_EQ(markers.vertex(static_cast<int>(v), 9), 9);
  }
  // The top's corners lie on sides marked 0 too: either marker is Triangle's.
  EXPECT_GT(top, 2u);
  EXPECT_GT(slit, 3u);
  EXPECT_GT(inside, 3u);
}

TEST(TriangleMarkers, EdgesTakeTheirSegmentsThenTheBoundarysMarker)
{
  const Marked m;
  ASSERT_TRUE(m.result.ok) << m.result.error;
  const TriangleMarkers markers(m.pslg, m.result, m.markers);
  std::size_t counted[4] = {};
  for (std::size_t e = 0; e < m.result.edges.size(); ++e)
  {
    const Edge& edge = m.result.edges[e];
    const Point &a = m.result.edgeVertices[edge.a], &b = m.result.edgeVertices[edge.b];
    const bool input = edge.flags & EdgeInput;
    const int expected = input && a.y == 1 && b.y == 1 ? 3
      : input && onSlit(a) && onSlit(b)                ? 5
      : onSquare(a) && onSquare(b) && (a.x == b.x || a.y == b.y) &&
        m.result.edgeVertexInMesh[edge.a] >= 0
      ? 1
      : 0;
    counted[expected == 0 ? 0 : expected == 1 ? 1 : expected == 3 ? 2 : 3] += 1;
    EXPECT_EQ(markers.edge(e), expected)
      << "edge (" << a.x << ", " << a.y << ") - (" << b.x << ", " << b.y << ")";
  }
  for (const std::size_t c : counted)
    EXPECT_GT(c, 0u);
}

TEST(TriangleMarkers, WithoutSegmentMarkersTheBoundaryIsOne)
{
  const Marked m;
  ASSERT_TRUE(m.result.ok) << m.result.error;
  const TriangleMarkers markers(m.pslg, m.result, {});
  for (std::size_t v = 0; v < m.result.mesh.vertices.size(); ++v)
    EXPECT_EQ(markers.vertex(static_cast<int>(v), 0), onSquare(m.result.mesh.vertices[v]) ? 1 : 0);
}

TEST(TriangleMarkers, AHolesBoundaryIsBoundary)
{
  // The square of Marked with a hole (0.6..0.8)² whose sides are marked 0
  // and 4, 0, 0: its sides are boundary, 1 where unmarked.
  Marked m;
  const int first = static_cast<int>(m.pslg.points.size());
  m.pslg.points.insert(
    m.pslg.points.end(), { { 0.6, 0.6 }, { 0.8, 0.6 }, { 0.8, 0.8 }, { 0.6, 0.8 } });
  for (int k = 0; k < 4; ++k)
    m.pslg.segments.push_back({ first + k, first + (k + 1) % 4 });
  m.markers.insert(m.markers.end(), { 4, 0, 0, 0 });
  m.pslg.holes = { { 0.7, 0.7 } };
  Options o;
  o.maxEdgeLength = 0.1;
  m.result = mesh(m.pslg, o);
  ASSERT_TRUE(m.result.ok) << m.result.error;
  const TriangleMarkers markers(m.pslg, m.result, m.markers);
  auto onHole = [](const Point& p) {
    const bool x = p.x >= 0.6 && p.x <= 0.8, y = p.y >= 0.6 && p.y <= 0.8;
    return (x && (p.y == 0.6 || p.y == 0.8)) || (y && (p.x == 0.6 || p.x == 0.8));
  };
  std::size_t holeVertices = 0, holeEdges = 0;
  for (std::size_t v = 0; v < m.result.mesh.vertices.size(); ++v)
  {
    const Point& p = m.result.mesh.vertices[v];
    if (!onHole(p))
      continue;
    ++holeVertices;
    EXPECT_EQ(markers.vertex(static_cast<int>(v), 0), p.y == 0.6 ? 4 : 1)
      << "(" << p.x << ", " << p.y << ")";
  }
  for (std::size_t e = 0; e < m.result.edges.size(); ++e)
  {
    const Edge& edge = m.result.edges[e];
    const Point &a = m.result.edgeVertices[edge.a], &b = m.result.edgeVertices[edge.b];
    if (!(edge.flags & EdgeInput) || !onHole(a) || !onHole(b) || (a.x != b.x && a.y != b.y))
      continue;
    ++holeEdges;
    EXPECT_EQ(markers.edge(e), a.y == 0.6 && b.y == 0.6 ? 4 : 1)
      << "(" << a.x << ", " << a.y << ") - (" << b.x << ", " << b.y << ")";
  }
  EXPECT_GE(holeVertices, 8u);
  EXPECT_GE(holeEdges, 8u);
}

TEST(MeshEdges, EveryEdgeOnceAndTheBoundaryThoseOfOneTriangle)
{
  const Marked m;
  ASSERT_TRUE(m.result.ok) << m.result.error;
  const TriMesh& mesh = m.result.mesh;
  const MeshEdges all(mesh), boundary(mesh, MeshEdges::Keep::Boundary);
  // Euler for a disc: E = V + F - 1.
  EXPECT_EQ(all.size(), mesh.vertices.size() + mesh.triangles.size() - 1);
  std::size_t onBoundary = 0;
  for (std::size_t k = 0; k < all.size(); ++k)
  {
    const Point &a = mesh.vertices[all.lower(k)], &b = mesh.vertices[all.higher(k)];
    const bool side = onSquare(a) && onSquare(b) && (a.x == b.x || a.y == b.y);
    EXPECT_LT(all.lower(k), all.higher(k));
    if (k > 0) // in order, which find's binary search needs
      EXPECT_LT(std::make_pair(all.lower(k - 1), all.higher(k - 1)),
        std::make_pair(all.lower(k), all.higher(k)));
    EXPECT_EQ(all.onBoundary(k), side);
    EXPECT_EQ(all.find(all.higher(k), all.lower(k)), k);
    EXPECT_EQ(boundary.edgeOnBoundary(all.lower(k), all.higher(k)), side);
    onBoundary += side;
  }
  EXPECT_EQ(boundary.size(), onBoundary);
  EXPECT_EQ(all.find(-1, 0), all.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    EXPECT_EQ(boundary.vertexOnBoundary(static_cast<int>(v)), onSquare(mesh.vertices[v]));
}
