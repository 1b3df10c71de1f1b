#include "CycleComponents.h"

#include <gtest/gtest.h>

#include <random>

using namespace osm;

namespace
{

/// Whether a and b are joined by segments other than skip (a search).
bool joined(std::size_t n, const Array<Segment>& segments, int a, int b, std::size_t skip,
  const Array<char>& allowed)
{
  Array<char> seen(n, 0);
  Array<int> stack{ a };
  seen[a] = 1;
  while (!stack.empty())
  {
    const int v = stack.back();
    stack.pop_back();
    if (v == b)
      return true;
    for (std::size_t k = 0; k < segments.size(); ++k)
      if (k != skip && allowed[k] && (segments[k][0] == v || segments[k][1] == v))
      {
        const int u = segments[k][0] == v ? segments[k][1] : segments[k][0];
        if (!seen[u])
          seen[u] = 1, stack.push_back(u);
      }
  }
  return false;
}

} // namespace

TEST(CycleComponents, SquaresJoinedByAPathAreTwoGroups)
{
  // 0-3 a square, 4-7 another, 8 a point on the path from 2 to 4, 9 a dangling end.
  const Array<Segment> s{ { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 6 }, { 6, 7 },
    { 7, 4 }, { 2, 8 }, { 8, 4 }, { 5, 9 } };
  const CycleComponents c = cycleComponents(10, s);
  EXPECT_EQ(c.count, 2u);
  const Array<int> expected{ 0, 0, 0, 0, 1, 1, 1, 1, -1, -1, -1 };
  EXPECT_EQ(c.component, expected);
}

TEST(CycleComponents, TwoSegmentsWithTheSameEndsAreACycle)
{
  const CycleComponents c = cycleComponents(3, { { 0, 1 }, { 1, 0 }, { 1, 2 } });
  EXPECT_EQ(c.count, 1u);
  EXPECT_EQ(c.component, (Array<int>{ 0, 0, -1 }));
  EXPECT_EQ(cycleComponents(4, {}).count, 0u);
}

TEST(CycleComponents, AgreeWithRemovingEachSegmentOnRandomGraphs)
{
  // A segment is on a cycle iff its ends stay joined without it; two such
  // segments share a group iff their ends are joined by segments on cycles.
  std::mt19937 rng(7);
  for (int trial = 0; trial < 300; ++trial)
  {
    const int n = 2 + static_cast<int>(rng() % 30);
    const std::size_t m = rng() % (n + 10);
    Array<Segment> s;
    for (std::size_t k = 0; k < m; ++k)
    {
      const int a = static_cast<int>(rng() % n), b = static_cast<int>(rng() % n);
      if (a != b)
        s.push_back({ a, b });
    }
    const CycleComponents c = cycleComponents(n, s);
    const Array<char> all(s.size(), 1);
    Array<char> onCycle(s.size(), 0);
    for (std::size_t k = 0; k < s.size(); ++k)
    {
      onCycle[k] = joined(n, s, s[k][0], s[k][1], k, all);
      ASSERT_EQ(c.component[k] >= 0, onCycle[k] != 0) << "trial " << trial << " segment " << k;
    }
    for (std::size_t i = 0; i < s.size(); ++i)
      for (std::size_t j = i + 1; j < s.size(); ++j)
        if (onCycle[i] && onCycle[j])
          ASSERT_EQ(
            c.component[i] == c.component[j], joined(n, s, s[i][0], s[j][0], s.size(), onCycle))
            << "trial " << trial << " segments " << i << " " << j;
  }
}

TEST(CycleComponents, SimpleCyclesHaveTheirAreas)
{
  // A unit square with segments in either direction, a triangle of area 2
  // hanging off it by a bridge, and a square with a diagonal (not simple).
  const Array<Point> points{ { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 }, { 3, 0 }, { 5, 0 }, { 3, 2 },
    { 10, 0 }, { 11, 0 }, { 11, 1 }, { 10, 1 } };
  const Array<Segment> s{ { 0, 1 }, { 2, 1 }, { 2, 3 }, { 0, 3 }, { 1, 4 }, { 4, 5 }, { 6, 5 },
    { 4, 6 }, { 7, 8 }, { 8, 9 }, { 9, 10 }, { 10, 7 }, { 7, 9 } };
  const CycleComponents c = cycleComponents(points.size(), s);
  ASSERT_EQ(c.count, 3u);
  const Array<double> area = simpleCycleAreas(points, s, c);
  EXPECT_DOUBLE_EQ(area[c.component[0]], 1.0);
  EXPECT_DOUBLE_EQ(area[c.component[5]], 2.0);
  EXPECT_EQ(area[c.component[8]], -1.0);
  // Two segments with the same ends enclose nothing.
  const Array<Segment> twice{ { 0, 1 }, { 1, 0 } };
  EXPECT_EQ(
    simpleCycleAreas(points, twice, cycleComponents(points.size(), twice)), (Array<double>{ 0.0 }));
}
