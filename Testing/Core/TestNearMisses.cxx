#include "Mesher.h"
#include "NearMisses.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>

using namespace osm;

namespace
{

/// The unit square's boundary (points 0-3, segments 0-3) and a line from
/// (0.5, 0.5) up to (0.5, top) (points 4, 5; segment 4).
Pslg squareWithLineTo(double top)
{
  Pslg p;
  p.points = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 }, { 0.5, 0.5 }, { 0.5, top } };
  p.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 } };
  return p;
}

std::string warningWith(const Result& r, const std::string& what)
{
  for (const std::string& w : r.warnings)
    if (w.find(what) != std::string::npos)
      return w;
  return {};
}

} // namespace

TEST(NearMisses, AnEndAHairShortOfASegmentIsFound)
{
  const Pslg p = squareWithLineTo(1 - 1e-9);
  const NearMisses m = findNearMisses(p.points, p.segments, 1e-6);
  EXPECT_EQ(m.count, 1u);
  EXPECT_EQ(m.point, 5);
  EXPECT_EQ(m.segment, 2);
  EXPECT_NEAR(m.distance, 1e-9, 1e-15);
  // The other end, at the middle, is far from every segment.
}

TEST(NearMisses, EndsOnASegmentBeyondReachOrOnLoopsAreNot)
{
  for (const double top : { 1.0, 1 - 1e-3, 1 + 1e-3 })
  {
    const Pslg p = squareWithLineTo(top);
    EXPECT_EQ(findNearMisses(p.points, p.segments, 1e-6).count, 0u) << top;
  }
  Pslg loop = squareWithLineTo(1);
  loop.segments.pop_back();
  EXPECT_EQ(findNearMisses(loop.points, loop.segments, 1e-6).count, 0u);
  EXPECT_EQ(findNearMisses(loop.points, {}, 1e-6).count, 0u);
}

TEST(NearMisses, TwoChainsWhoseEndsNearlyMeetAreBothFound)
{
  // (0, 0)-(1, 0) and (1 + 1e-9, 0)-(2, 1): each end near the other's segment.
  const Array<Point> points = { { 0, 0 }, { 1, 0 }, { 1 + 1e-9, 0 }, { 2, 1 } };
  const Array<Segment> segments = { { 0, 1 }, { 2, 3 } };
  const NearMisses m = findNearMisses(points, segments, 1e-6);
  EXPECT_EQ(m.count, 2u);
  EXPECT_NEAR(m.distance, 1e-9, 1e-15);
}

TEST(NearMisses, ManyEndsOnAGridFindOnlyTheShortOnes)
{
  // 200 vertical lines under a horizontal one at y = 1: the even ones stop
  // 1e-9 short of it, the odd ones 0.1 short.
  Array<Point> points = { { -1, 1 }, { 201, 1 } };
  Array<Segment> segments = { { 0, 1 } };
  for (int i = 0; i < 200; ++i)
  {
    points.push_back({ double(i), 0 });
    points.push_back({ double(i), i % 2 ? 0.9 : 1 - 1e-9 });
    segments.push_back({ 2 + 2 * i, 3 + 2 * i });
  }
  const NearMisses m = findNearMisses(points, segments, 1e-6 * 202);
  EXPECT_EQ(m.count, 100u);
  EXPECT_EQ(m.segment, 0);
}

TEST(NearMisses, TheMesherWarnsAndAMergeToleranceAboveTheGapJoins)
{
  // The line splits the square in two only if it reaches the top.
  Pslg p = squareWithLineTo(1 - 1e-9);
  p.points.push_back({ 0.5, 0 });
  p.segments.back() = { 6, 5 };
  const Result r = mesh(p);
  ASSERT_TRUE(r.ok) << r.error;
  const std::string w = warningWith(r, "stop short");
  EXPECT_NE(w.find("1 segment end(s) stop short of another segment"), std::string::npos) << w;
  EXPECT_NE(w.find("point 5 at (0.5, 0.999999999), 1e-09 from segment 2"), std::string::npos) << w;
  EXPECT_NE(w.find("e.g. 2e-09"), std::string::npos) << w;
  EXPECT_EQ(std::set<int>(r.regionId.begin(), r.regionId.end()).size(), 1u);

  Options joined;
  joined.mergeTolerance = 2e-9;
  const Result j = mesh(p, joined);
  ASSERT_TRUE(j.ok) << j.error;
  EXPECT_TRUE(warningWith(j, "stop short").empty());
  EXPECT_EQ(std::set<int>(j.regionId.begin(), j.regionId.end()).size(), 2u);
}

TEST(NearMisses, CoordinatesNearTheDoublesLimitGiveNoNaN)
{
  // A segment whose length overflows, and an end 1 from it.
  const Array<Point> points = { { -1e308, 0 }, { 1e308, 0 }, { 0, 1e300 }, { 0, 1 } };
  const Array<Segment> segments = { { 0, 1 }, { 2, 3 } };
  // Its extent overflows too: no reach.
  EXPECT_EQ(findNearMisses(points, segments, std::numeric_limits<double>::infinity()).count, 0u);
  const NearMisses m = findNearMisses(points, segments, 1e302);
  EXPECT_TRUE(m.count == 0 || std::isfinite(m.distance)) << m.distance;
}
