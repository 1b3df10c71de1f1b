// The benchmark suite's own output check (Testing/Benchmarks/BenchCommon.h),
// which judges every tool's mesh alike: it must see what it claims to see.
#include "../Benchmarks/BenchCommon.h"

#include <gtest/gtest.h>

namespace
{

osmbench::MeshOut square(std::initializer_list<osm::Triangle> triangles)
{
  osmbench::MeshOut m;
  for (osm::Point p : { osm::Point{ 0, 0 }, osm::Point{ 1, 0 }, osm::Point{ 1, 1 },
         osm::Point{ 0, 1 }, osm::Point{ 0.9, 0.2 } })
    m.vertices.push_back(p);
  for (const osm::Triangle& t : triangles)
    m.triangles.push_back(t);
  return m;
}

osm::Pslg squareInput()
{
  osm::Pslg in;
  in.points = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  in.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
  return in;
}

} // namespace

TEST(BenchInspect, AGoodMeshHasNoOverlapEdgesWhateverItsOrientation)
{
  const osm::Pslg in = squareInput();
  // One triangle clockwise, one counterclockwise: the tools differ in this.
  const osmbench::Quality q = osmbench::inspect(in, square({ { 0, 1, 2 }, { 0, 3, 2 } }), {});
  EXPECT_EQ(q.nonManifoldEdges, 0u);
  EXPECT_EQ(q.foldedEdges, 0u);
  EXPECT_EQ(q.missingSegments, 0u);
  EXPECT_EQ(q.missingVertices, 0u);
}

TEST(BenchInspect, TrianglesOnTheSameSideOfTheirEdgeAreAFold)
{
  // 0-1-2 and 0-4-2 both lie below the diagonal 0-2: they overlap.
  const osmbench::Quality q =
    osmbench::inspect(squareInput(), square({ { 0, 1, 2 }, { 0, 4, 2 }, { 0, 2, 3 } }), {});
  EXPECT_EQ(q.foldedEdges, 0u);
  EXPECT_EQ(q.nonManifoldEdges, 1u); // the diagonal is in three triangles
  const osmbench::Quality folded =
    osmbench::inspect(squareInput(), square({ { 0, 1, 2 }, { 0, 4, 2 } }), {});
  EXPECT_EQ(folded.foldedEdges, 1u);
  EXPECT_EQ(folded.nonManifoldEdges, 0u);
  EXPECT_EQ(folded.missingSegments, 2u); // 2-3 and 3-0
  EXPECT_EQ(folded.missingVertices, 1u); // point 3 is in no triangle
}
