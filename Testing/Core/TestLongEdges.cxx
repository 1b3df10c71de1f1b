// splitLongEdges on two triangles sharing a long side.
#include "LongEdges.h"
#include "Predicates.h"

#include <gtest/gtest.h>

using namespace osm;

namespace
{

/// Triangles (a, b, c) and (b, a, d) sharing the side a-b, of length `length`
/// along the x axis, with c above and d below it.
struct Pair
{
  Array<Point> points;
  Array<VertexOrigin> origin;
  Array<Triangle> triangles{ { 0, 1, 2 }, { 1, 0, 3 } };
  Array<int> regionId{ 7, 7 };
  Array<Segment> constrained;

  explicit Pair(double length, double height = 0.5)
    : points{ { 0, 0 }, { length, 0 }, { 0.5 * length, height }, { 0.45 * length, -height } }
    , origin(4, VertexOrigin::Overlay)
  {}
  /// With maxEdge the bound of region 7 (and none elsewhere).
  LongEdges split(double maxEdge, double maxAngleDeg = 170)
  {
    Array<double> regionMaxEdge(8, 0.0);
    regionMaxEdge[7] = maxEdge;
    return splitLongEdges(points, origin, triangles, regionId, constrained, regionMaxEdge,
      maxAngleDeg, RunContext::silent());
  }
};

double longest(const Pair& p)
{
  double l2 = 0;
  for (const Triangle& t : p.triangles)
    for (int k = 0; k < 3; ++k)
      l2 = std::max(l2, dist2(p.points[t[k]], p.points[t[(k + 1) % 3]]));
  return std::sqrt(l2);
}

} // namespace

TEST(LongEdges, ASideOverTheBoundIsSplitIntoAFanOfFour)
{
  Pair p(1.1);
  const LongEdges r = p.split(1.0);
  EXPECT_EQ(r.split, 1u);
  EXPECT_EQ(r.remaining, 0u);
  ASSERT_EQ(p.triangles.size(), 4u);
  ASSERT_EQ(p.points.size(), 5u);
  EXPECT_EQ(p.origin.back(), VertexOrigin::Other);
  EXPECT_LE(longest(p), 1.0);
  double area = 0;
  for (const Triangle& t : p.triangles)
  {
    EXPECT_GT(orient2d(p.points[t[0]], p.points[t[1]], p.points[t[2]]), 0);
    area += 0.5 * orient2d(p.points[t[0]], p.points[t[1]], p.points[t[2]]);
    EXPECT_NE(std::find(t.begin(), t.end(), 4), t.end()) << "every triangle meets the new point";
  }
  EXPECT_NEAR(area, 1.1 * 0.5, 1e-15);
  for (int id : p.regionId)
    EXPECT_EQ(id, 7);
}

TEST(LongEdges, EdgesWithinTheBoundAndDroppedTrianglesAreLeft)
{
  Pair within(0.9);
  EXPECT_EQ(within.split(1.0).split, 0u);
  EXPECT_EQ(within.triangles.size(), 2u);
  // Outside the domain (region -1): not output, so not split.
  Pair outside(1.1);
  outside.regionId = { -1, -1 };
  const LongEdges r = outside.split(1.0);
  EXPECT_EQ(r.split, 0u);
  EXPECT_EQ(r.remaining, 0u);
  // A region without a bound (0) keeps its edges.
  Pair unbounded(1.1);
  unbounded.regionId = { 3, 3 };
  EXPECT_EQ(unbounded.split(1.0).remaining, 0u);
  EXPECT_EQ(unbounded.triangles.size(), 2u);
}

TEST(LongEdges, WhatCannotBeSplitIsCountedWithTheLongestEdge)
{
  // A side on a segment would leave it: it stays, and is counted.
  Pair onSegment(1.1);
  onSegment.constrained = { { 0, 1 } };
  LongEdges r = onSegment.split(1.0);
  EXPECT_EQ(r.split, 0u);
  EXPECT_EQ(r.remaining, 2u);
  EXPECT_DOUBLE_EQ(r.worst, 1.1);
  EXPECT_EQ(r.at.x, 0.55);
  EXPECT_EQ(r.at.y, 0.0);
  // More than twice the bound: no point is within it of both ends.
  Pair tooLong(2.5, 0.3);
  r = tooLong.split(1.0);
  EXPECT_EQ(r.split, 0u);
  EXPECT_GT(r.remaining, 0u);
  // No fan keeps its angles within an impossible 80 degrees.
  Pair strict(1.1);
  EXPECT_EQ(strict.split(1.0, 80.0).split, 0u);
  EXPECT_EQ(strict.triangles.size(), 2u);
}

// From a mutation test of LongEdges: the bound itself, a side that must wait
// for a second pass, and the search for a split point within the angle bound.
TEST(LongEdges, ASideAtTheBoundIsLeft)
{
  Pair at(1.0);
  EXPECT_EQ(at.split(1.0).split, 0u);
  EXPECT_EQ(at.triangles.size(), 2u);
}

TEST(LongEdges, ASideSplitAfterItsNeighbourIsSplitInALaterPass)
{
  // Two long sides in a chain: splitting one first leaves the other's
  // triangle changed, so it waits for the next pass.
  Array<Point> points{ { 0, 0 }, { 1.1, 0 }, { 0.55, 0.5 }, { 0.3, -0.9 }, { 1.2, -0.9 } };
  Array<VertexOrigin> origin(5, VertexOrigin::Overlay);
  Array<Triangle> triangles{ { 0, 1, 2 }, { 1, 0, 3 }, { 1, 3, 4 } };
  Array<int> regionId{ 7, 7, 7 };
  Array<double> regionMaxEdge(8, 0.0);
  regionMaxEdge[7] = 1.0;
  const LongEdges r = splitLongEdges(
    points, origin, triangles, regionId, {}, regionMaxEdge, 170, RunContext::silent());
  EXPECT_EQ(r.split, 2u);
  EXPECT_EQ(r.remaining, 0u);
}

TEST(LongEdges, TheSplitPointIsSearchedFinelyEnoughForATightAngleBound)
{
  // Below the bound's 97 degrees only a point found by the finer steps keeps
  // every new angle within it.
  for (double maxAngle : { 93.0, 96.0 })
  {
    Pair p(1.1);
    p.points[3] = { 0.495, -0.5 };
    EXPECT_EQ(p.split(1.0, maxAngle).split, 1u) << maxAngle;
  }
}

TEST(LongEdges, NoNewTriangleIsFlatWhereTheSearchMeetsACorner)
{
  // c and d a quarter of |ab| above and below the midpoint of a-b: the
  // search's first steps land exactly on them, where two fan triangles have
  // no area (a mutation test: allowed there, d was taken, a second vertex on it).
  Pair p(1.1);
  p.points[2] = { 0.55, 0.275 };
  p.points[3] = { 0.55, -0.275 };
  EXPECT_EQ(p.split(1.0).split, 1u);
  for (const Triangle& t : p.triangles)
    EXPECT_GT(orient2d(p.points[t[0]], p.points[t[1]], p.points[t[2]]), 0);
  for (int k = 0; k < 4; ++k)
    EXPECT_NE(p.points.back(), p.points[k]);
}

TEST(LongEdges, WhatRemainsIsCountedInTheMeshAsLeft)
{
  // Twelve random points (a fuzz case) whose splits go on into the fourth
  // and last pass: the count, the worst ratio and its place must be those of
  // the mesh as left, not as the last pass found it (a mutation test: without
  // the final scan, remaining was 5 and worst an edge already split).
  Array<Point> points{ { 0.28913680080342807, 0.1250688484161914 },
    { 0.49574918881220764, 0.15024463939389771 }, { 0.56269796725460508, 0.10272106645978708 },
    { 0.19784425560464511, 0.38099418057140139 }, { 0.23963927326531345, 0.48311828149251312 },
    { 0.31408787041582387, 0.4997381324730083 }, { 0.39162715967042688, 0.94070972532729147 },
    { 0.55307869311773705, 0.8896070288816228 }, { 0.85781635922673227, 0.67711974602658298 },
    { 0.97662333540188251, 0.60625703158588218 }, { 0.9635379332301286, 0.58189815412546919 },
    { 0.71696131003677122, 0.040878518063870398 } };
  Array<Triangle> triangles{ { 1, 0, 2 }, { 0, 1, 3 }, { 10, 2, 11 }, { 4, 5, 6 }, { 4, 3, 5 },
    { 3, 1, 5 }, { 6, 5, 7 }, { 7, 5, 8 }, { 5, 1, 8 }, { 9, 8, 10 }, { 8, 1, 10 }, { 1, 2, 10 },
    { 2, 0, 11 } };
  Array<VertexOrigin> origin(points.size(), VertexOrigin::Overlay);
  Array<int> regionId(triangles.size(), 0);
  const double maxEdge = 0.43624650583114666;
  Array<double> regionMaxEdge(1, maxEdge);
  const LongEdges r = splitLongEdges(points, origin, triangles, regionId, {}, regionMaxEdge,
    123.59861667517072, RunContext::silent());
  EXPECT_EQ(r.split, 4u);
  std::size_t remaining = 0;
  double worst = 0;
  for (const Triangle& t : triangles)
  {
    bool isLong = false;
    for (int k = 0; k < 3; ++k)
    {
      const double l = std::sqrt(dist2(points[t[k]], points[t[(k + 1) % 3]]));
      isLong = isLong || l > maxEdge;
      worst = std::max(worst, l / maxEdge);
    }
    remaining += isLong ? 1 : 0;
  }
  EXPECT_EQ(r.remaining, remaining);
  EXPECT_DOUBLE_EQ(r.worst, worst);
}
