#include "Snap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

using namespace osm;

namespace
{

/// Per input segment, the points splitting it in order along it: read back
/// from the pieces by walking them from the segment's first end.
std::vector<int> chainOf(const Array<OriginSegment>& pieces, int origin, int from, int to)
{
  std::vector<int> chain{ from };
  for (std::size_t guard = 0; chain.back() != to && guard <= pieces.size(); ++guard)
    for (const auto& [s, o] : pieces)
      if (o == origin && (s[0] == chain.back() || s[1] == chain.back()))
      {
        const int next = s[0] == chain.back() ? s[1] : s[0];
        if (chain.size() < 2 || next != chain[chain.size() - 2])
        {
          chain.push_back(next);
          break;
        }
      }
  return chain;
}

} // namespace

TEST(Snap, SplitsASegmentAtThePointsWithinTheToleranceInOrder)
{
  const Array<Point> points = { { 0, 0 }, { 10, 0 }, { 7, 1e-7 }, { 3, -1e-7 }, { 5, 2e-6 },
    { -1e-8, 0 }, { 12, 0 } };
  Array<OriginSegment> segments = { { { 0, 1 }, 4 } };
  SnapExample example;
  EXPECT_EQ(snapPointsOntoSegments(points, segments, 1e-6, example), 2u);
  // Points 3 and 2, in that order along it; 4 is too far, 5 and 6 beyond its ends.
  EXPECT_EQ(chainOf(segments, 4, 0, 1), (std::vector<int>{ 0, 3, 2, 1 }));
  EXPECT_EQ(segments.size(), 3u);
  EXPECT_EQ(example.segment, 4);
  EXPECT_EQ(example.point, 3);
  // No tolerance: nothing.
  Array<OriginSegment> untouched = { { { 0, 1 }, 0 } };
  EXPECT_EQ(snapPointsOntoSegments(points, untouched, 0.0, example), 0u);
  EXPECT_EQ(untouched.size(), 1u);
}

TEST(Snap, FindsWhatEveryPairOfPointAndSegmentWouldFind)
{
  // Random segments of all lengths (one across the whole extent crosses many
  // grid cells) and points near them, against the pairwise search.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::size_t snapped = 0;
  for (int round = 0; round < 20; ++round)
  {
    const double tol = std::pow(10.0, -1 - 5 * U(rng));
    Array<Point> points;
    Array<OriginSegment> segments;
    const int n = 5 + static_cast<int>(rng() % 60);
    for (int k = 0; k < n; ++k)
    {
      const Point a{ 100 * U(rng), 100 * U(rng) };
      const double length = k == 0 ? 150.0 : std::pow(10.0, 2.3 * U(rng) - 0.3);
      // Every fourth one along an axis: the points near it then lie beyond
      // its bounds by up to the tolerance.
      const double angle =
        k % 4 == 1 ? 1.5707963267948966 * double(rng() % 4) : 6.283185307179586 * U(rng);
      const Point b{ a.x + length * std::cos(angle), a.y + length * std::sin(angle) };
      const int i = static_cast<int>(points.size());
      points.insert(points.end(), { a, b });
      segments.push_back({ { i, i + 1 }, k });
      // Points near it, within or just beyond the tolerance of its line.
      for (int near = 0; near < 3; ++near)
      {
        const double t = U(rng), off = tol * (2 * U(rng) - 1) * 1.2;
        points.push_back({ a.x + t * (b.x - a.x) - off * std::sin(angle),
          a.y + t * (b.y - a.y) + off * std::cos(angle) });
      }
    }
    std::vector<std::tuple<int, int>> expected; // (origin, point)
    for (const auto& [s, origin] : segments)
      for (int p = 0; p < static_cast<int>(points.size()); ++p)
      {
        const Point &a = points[s[0]], &b = points[s[1]], &q = points[p];
        if (p == s[0] || p == s[1])
          continue;
        const double len2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
        const double t = ((q.x - a.x) * (b.x - a.x) + (q.y - a.y) * (b.y - a.y)) / len2;
        const double off = std::fabs((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x));
        if (t > 0 && t < 1 && off * off <= tol * tol * len2)
          expected.push_back({ origin, p });
      }
    SnapExample example;
    const Array<OriginSegment> before = segments;
    EXPECT_EQ(snapPointsOntoSegments(points, segments, tol, example), expected.size()) << round;
    snapped += expected.size();
    // Every segment's chain passes through exactly its expected points.
    for (const auto& [s, origin] : before)
    {
      std::vector<int> chain = chainOf(segments, origin, s[0], s[1]);
      ASSERT_GE(chain.size(), 2u);
      EXPECT_EQ(chain.back(), s[1]) << round << " segment " << origin;
      std::vector<int> inner(chain.begin() + 1, chain.end() - 1), want;
      for (const auto& [o, p] : expected)
        if (o == origin)
          want.push_back(p);
      std::sort(inner.begin(), inner.end());
      EXPECT_EQ(inner, want) << round << " segment " << origin;
    }
  }
  // Most of the points placed near a segment are within the tolerance.
  EXPECT_GT(snapped, 1000u);
}

TEST(Snap, CoordinatesNearTheDoubleLimit)
{
  // Squared lengths and sums of lengths overflow here: found by the fuzzer
  // (a NaN sample count). Within 1.1e307 the mesher accepts coordinates.
  const Array<Point> points = { { -1e307, 0 }, { 1e307, 0 }, { 0, 1e292 }, { 5e306, -1e294 } };
  Array<OriginSegment> segments = { { { 0, 1 }, 0 } };
  SnapExample example;
  EXPECT_EQ(snapPointsOntoSegments(points, segments, 1e293, example), 1u);
  EXPECT_EQ(example.point, 2);
  // Beyond it (the mesher refuses such input): nothing, and no overflow.
  const Array<Point> huge = { { -1.7e308, 0 }, { 1.7e308, 0 }, { 0, 1 } };
  Array<OriginSegment> across = { { { 0, 1 }, 0 } };
  EXPECT_EQ(snapPointsOntoSegments(huge, across, 10.0, example), 0u);
  EXPECT_EQ(across.size(), 1u);
}

TEST(Snap, PointsEquallyFarAlongAreOrderedTheSameWhicheverWayTheSegmentRuns)
{
  // (2, 0) and (0, 2) are equally far along (0, 0)-(12, 12), on either side:
  // the segment zigzags through both, and the order must not depend on the
  // segment's or the points' numbering (the validator, splitting by brute
  // force, numbered them otherwise than the mesher, and the fuzzer caught it).
  auto chainPoints = [](const Array<Point>& points, Segment s) {
    Array<OriginSegment> segments = { { s, 0 } };
    SnapExample example;
    EXPECT_EQ(snapPointsOntoSegments(points, segments, 1.5, example), 2u);
    const int from = points[s[0]] < points[s[1]] ? s[0] : s[1];
    const int to = from == s[0] ? s[1] : s[0];
    std::vector<Point> chain;
    for (int v : chainOf(segments, 0, from, to))
      chain.push_back(points[v]);
    return chain;
  };
  const std::vector<Point> want = { { 0, 0 }, { 0, 2 }, { 2, 0 }, { 12, 12 } };
  const Array<Point> one = { { 0, 0 }, { 12, 12 }, { 2, 0 }, { 0, 2 } };
  const Array<Point> other = { { 12, 12 }, { 0, 2 }, { 2, 0 }, { 0, 0 } };
  EXPECT_EQ(chainPoints(one, { 0, 1 }), want);
  EXPECT_EQ(chainPoints(one, { 1, 0 }), want);
  EXPECT_EQ(chainPoints(other, { 0, 3 }), want);
  EXPECT_EQ(chainPoints(other, { 3, 0 }), want);
}
