// Which input polygon holds each region (RegionPolygons.h), checked against
// the polygons' coordinates, triangle by triangle.
#include "RegionPolygons.h"

#include <gtest/gtest.h>

#include <functional>

using namespace osm;

namespace
{

// Three squares of segments: A (0..10), B (2..6, inside A) and C (12..16,
// beside A), and a bow-tie D whose lobes lie inside A, right of B.
struct Squares
{
  Pslg pslg;
  Result result;
  PolygonLoops loops;

  Squares()
  {
    pslg.points = { { 0, 0 }, { 10, 0 }, { 10, 10 }, { 0, 10 }, // A: 0-3
      { 2, 2 }, { 6, 2 }, { 6, 6 }, { 2, 6 },                   // B: 4-7
      { 12, 0 }, { 16, 0 }, { 16, 4 }, { 12, 4 },               // C: 8-11
      { 7, 2 }, { 9, 2 }, { 7, 4 }, { 9, 4 } };                 // D: 12-15, crossing at (8, 3)
    pslg.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 6 }, { 6, 7 },
      { 7, 4 }, { 8, 9 }, { 9, 10 }, { 10, 11 }, { 11, 8 }, { 12, 13 }, { 13, 14 }, { 14, 15 },
      { 15, 12 } };
    Options o;
    o.domain = Domain::Enclosed;
    result = mesh(pslg, o);
  }
};

const int kA[] = { 0, 1, 2, 3 }, kB[] = { 4, 5, 6, 7 }, kD[] = { 12, 13, 14, 15 };

/// The innermost of A, B and D (as loops 0, 1, 2) around point p, or -1.
int expectedLoop(const Point& p)
{
  const bool inA = p.x > 0 && p.x < 10 && p.y > 0 && p.y < 10;
  const bool inB = p.x > 2 && p.x < 6 && p.y > 2 && p.y < 6;
  // The bow-tie's lobes: triangles (7,2)-(9,2)-(8,3) and (7,4)-(9,4)-(8,3).
  const double d = std::fabs(p.x - 8);
  const bool inD = p.x > 7 && p.x < 9 && ((p.y > 2 && p.y < 3 - d) || (p.y < 4 && p.y > 3 + d));
  return inB ? 1 : inD ? 2 : inA ? 0 : -1;
}

const std::function<bool(double)> kNeverStop = [](double) { return false; };

} // namespace

TEST(RegionPolygons, EachRegionTakesTheInnermostLoopAroundIt)
{
  Squares s;
  ASSERT_TRUE(s.result.ok) << s.result.error;
  s.loops.add(kA, 4);
  s.loops.add(kB, 4);
  s.loops.add(kD, 4); // a self-crossing loop: both lobes are inside it
  std::vector<int> of;
  ASSERT_TRUE(innermostPolygons(s.pslg, s.result, s.loops, of, kNeverStop));
  const auto& v = s.result.mesh.vertices;
  int seen[4] = { 0, 0, 0, 0 };
  for (std::size_t t = 0; t < s.result.mesh.triangles.size(); ++t)
  {
    const Triangle& tri = s.result.mesh.triangles[t];
    const Point c{ (v[tri[0]].x + v[tri[1]].x + v[tri[2]].x) / 3,
      (v[tri[0]].y + v[tri[1]].y + v[tri[2]].y) / 3 };
    const int region = s.result.regionId[t];
    ASSERT_GE(region, 0);
    ASSERT_LT(static_cast<std::size_t>(region), of.size());
    EXPECT_EQ(of[static_cast<std::size_t>(region)], expectedLoop(c))
      << "triangle " << t << " at (" << c.x << ", " << c.y << ")";
    ++seen[expectedLoop(c) + 1];
  }
  // Every case met: outside every loop (C), A only, B inside A, D's lobes.
  for (int k = 0; k < 4; ++k)
    EXPECT_GT(seen[k], 0) << "no triangle for loop " << k - 1;
}

TEST(RegionPolygons, NestingIsByAreaInsideNotByOrder)
{
  // B given before A: B is still the innermost around its regions.
  Squares s;
  ASSERT_TRUE(s.result.ok) << s.result.error;
  s.loops.add(kB, 4);
  s.loops.add(kA, 4);
  std::vector<int> of;
  ASSERT_TRUE(innermostPolygons(s.pslg, s.result, s.loops, of, kNeverStop));
  const auto& v = s.result.mesh.vertices;
  for (std::size_t t = 0; t < s.result.mesh.triangles.size(); ++t)
  {
    const Triangle& tri = s.result.mesh.triangles[t];
    const Point c{ (v[tri[0]].x + v[tri[1]].x + v[tri[2]].x) / 3,
      (v[tri[0]].y + v[tri[1]].y + v[tri[2]].y) / 3 };
    const int loop = expectedLoop(c);
    const int expected = loop == 1 ? 0 : loop == 0 || loop == 2 ? 1 : -1;
    EXPECT_EQ(of[static_cast<std::size_t>(s.result.regionId[t])], expected)
      << "triangle " << t << " at (" << c.x << ", " << c.y << ")";
  }
}

TEST(RegionPolygons, WithoutLoopsNoRegionHasAPolygon)
{
  Squares s;
  ASSERT_TRUE(s.result.ok) << s.result.error;
  std::vector<int> of{ 7 };
  ASSERT_TRUE(innermostPolygons(s.pslg, s.result, s.loops, of, kNeverStop));
  EXPECT_FALSE(of.empty());
  for (int o : of)
    EXPECT_EQ(o, -1);
}

TEST(RegionPolygons, ATieKeepsTheFirstLoopWhicheverWayItRuns)
{
  // A mutation test: the same square given twice went to the second copy
  // when ties (equal area inside, equal own area) kept the last, and a
  // clockwise copy beat a counter-clockwise one given first when the own
  // area was signed.
  Pslg pslg;
  pslg.points = { { 0, 0 }, { 10, 0 }, { 10, 10 }, { 0, 10 } };
  Result r;
  r.mesh.vertices = pslg.points;
  r.mesh.triangles = { { 0, 1, 2 }, { 0, 2, 3 } };
  r.regionId = { 0, 0 };
  const int ccw[] = { 0, 1, 2, 3 }, shifted[] = { 1, 2, 3, 0 }, cw[] = { 3, 2, 1, 0 };
  for (const auto& [first, second] :
    { std::pair{ ccw, shifted }, std::pair{ ccw, cw }, std::pair{ cw, ccw } })
  {
    PolygonLoops loops;
    loops.add(first, 4);
    loops.add(second, 4);
    std::vector<int> of;
    ASSERT_TRUE(innermostPolygons(pslg, r, loops, of, kNeverStop));
    ASSERT_EQ(of.size(), 1u);
    EXPECT_EQ(of[0], 0);
  }
}

TEST(RegionPolygons, PollIsAskedEvery2To16LoopPoints)
{
  // 20,000 copies of one square: 80,000 loop points but few orientation
  // tests, so only the poll by loop points can stop the work (a mutation
  // test: without it poll was never asked).
  Pslg pslg;
  pslg.points = { { 0, 0 }, { 10, 0 }, { 10, 10 }, { 0, 10 } };
  pslg.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
  Options o;
  o.domain = Domain::Enclosed;
  const Result result = mesh(pslg, o);
  ASSERT_TRUE(result.ok) << result.error;
  PolygonLoops loops;
  const int square[] = { 0, 1, 2, 3 };
  for (int k = 0; k < 20000; ++k)
    loops.add(square, 4);
  std::vector<int> of;
  int polls = 0;
  const auto count = [&](double) { return ++polls, false; };
  ASSERT_TRUE(innermostPolygons(pslg, result, loops, of, count));
  EXPECT_GE(polls, 1); // at loop 16,384 (the first to start at 2^16)
  polls = 0;
  EXPECT_FALSE(innermostPolygons(pslg, result, loops, of, [&](double) { return ++polls, true; }));
  EXPECT_GE(polls, 1);
}
