// SizeBoxes: the grid finds exactly the boxes a scan finds, and the point
// estimate neither counts overlapping boxes twice nor overflows.
#include "SizeBoxes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace osm;

namespace
{

/// The answer of a scan over every box.
bool scan(const Array<SizeBox>& boxes, const Point& a, const Point& b, const Point& c, double l2)
{
  for (const SizeBox& s : boxes)
  {
    const Bounds& r = s.box;
    const bool outside = std::max({ a.x, b.x, c.x }) < r.lo.x ||
      std::min({ a.x, b.x, c.x }) > r.hi.x || std::max({ a.y, b.y, c.y }) < r.lo.y ||
      std::min({ a.y, b.y, c.y }) > r.hi.y;
    if (l2 > s.maxEdgeLength * s.maxEdgeLength && !outside)
      return true;
  }
  return false;
}

} // namespace

TEST(SizeBoxes, TheGridAnswersAsAScanOfEveryBox)
{
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(0, 1);
  for (int count : { 1, 3, 40, 900 })
  {
    Array<SizeBox> boxes;
    for (int k = 0; k < count; ++k)
    {
      const Point lo{ U(rng), U(rng) };
      const double w = 0.3 * U(rng) * U(rng), h = 0.3 * U(rng) * U(rng);
      boxes.push_back({ { lo, { lo.x + w, lo.y + h } }, 0.01 + 0.1 * U(rng) });
    }
    const SizeBoxes grid(boxes);
    // A triangle reaching 1e10 beyond the boxes (found by the fuzzer under
    // UBSan: its cell index overflowed int before being clamped).
    const Point far{ -1e10, -1e10 }, near{ 0.5, 0.5 }, up{ 0.5, 1e10 };
    EXPECT_EQ(grid.tooLong(far, near, up, 1e20), scan(boxes, far, near, up, 1e20));
    int hits = 0;
    for (int t = 0; t < 20000; ++t)
    {
      const Point a{ 1.4 * U(rng) - 0.2, 1.4 * U(rng) - 0.2 };
      const double r = 0.2 * U(rng) * U(rng);
      const Point b{ a.x + r * (U(rng) - 0.5), a.y + r * (U(rng) - 0.5) };
      const Point c{ a.x + r * (U(rng) - 0.5), a.y + r * (U(rng) - 0.5) };
      const double l2 = std::max({ dist2(a, b), dist2(b, c), dist2(a, c) });
      const bool expected = scan(boxes, a, b, c, l2);
      hits += expected;
      ASSERT_EQ(grid.tooLong(a, b, c, l2), expected) << count << " boxes, triangle " << t;
    }
    EXPECT_GT(hits, 0) << count << " boxes";
  }
}

TEST(SizeBoxes, CoversAsAScanOfEveryBox)
{
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0, 1);
  for (int count : { 1, 5, 300 })
  {
    Array<SizeBox> boxes;
    for (int k = 0; k < count; ++k)
    {
      const Point lo{ U(rng), U(rng) };
      const double w = 0.4 * U(rng), h = 0.4 * U(rng);
      boxes.push_back({ { lo, { lo.x + w, lo.y + h } }, 1.0 });
    }
    const SizeBoxes grid(boxes);
    int hits = 0;
    for (int t = 0; t < 20000; ++t)
    {
      const Point lo{ 1.4 * U(rng) - 0.2, 1.4 * U(rng) - 0.2 };
      const double r = 0.2 * U(rng) * U(rng);
      const Bounds b{ lo, { lo.x + r * U(rng), lo.y + r * U(rng) } };
      const bool expected =
        std::any_of(boxes.begin(), boxes.end(), [&](const SizeBox& s) { return within(b, s.box); });
      hits += expected;
      ASSERT_EQ(grid.covers(b), expected) << count << " boxes, bounds " << t;
    }
    EXPECT_GT(hits, 0) << count << " boxes";
    // A box covers itself, boundaries included.
    EXPECT_TRUE(grid.covers(boxes.back().box));
  }
  EXPECT_FALSE(SizeBoxes({}).covers({ { 0, 0 }, { 0, 0 } }));
}

TEST(SizeBoxes, BoxesOverTheWholeSpanAreListedInFewCells)
{
  // 20,000 boxes each over most of the span: one cell per box would list
  // each in thousands of cells (found by a review: 100,000 such boxes
  // overflowed the count); the grid coarsens instead, and answers alike.
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> U(0, 1);
  Array<SizeBox> boxes;
  for (int k = 0; k < 20000; ++k)
    boxes.push_back(
      { { { 0.05 * U(rng), 0.05 * U(rng) }, { 0.95 + 0.05 * U(rng), 0.95 + 0.05 * U(rng) } },
        0.01 + U(rng) });
  const SizeBoxes grid(boxes);
  for (int t = 0; t < 200; ++t)
  {
    const Point a{ U(rng), U(rng) }, b{ a.x + 0.1 * U(rng), a.y }, c{ a.x, a.y + 0.1 * U(rng) };
    const double l2 = std::max({ dist2(a, b), dist2(b, c), dist2(a, c) });
    ASSERT_EQ(grid.tooLong(a, b, c, l2), scan(boxes, a, b, c, l2)) << t;
  }
}

TEST(SizeBoxes, PointsNeededCountsOverlapsOnceAndNeverOverflows)
{
  const Bounds mesh{ { -1, -1 }, { 2, 2 } };
  // 100 copies of the unit box at bound 0.01: the unit box once, about 11,547.
  Array<SizeBox> copies(100, SizeBox{ { { 0, 0 }, { 1, 1 } }, 0.01 });
  const double once = 1.0 / (0.8660254037844386 * 1e-4);
  EXPECT_NEAR(SizeBoxes(copies).pointsNeeded(mesh), once, 1e-6 * once);
  EXPECT_NEAR(SizeBoxes({ copies.front() }).pointsNeeded(mesh), once, 1e-6 * once);
  // A bound whose square overflows asks for nothing; a box beyond the mesh too.
  EXPECT_EQ(SizeBoxes({ SizeBox{ { { 0, 0 }, { 1, 1 } }, 1e300 } }).pointsNeeded(mesh), 0.0);
  EXPECT_EQ(SizeBoxes({ SizeBox{ { { 5, 5 }, { 6, 6 } }, 0.01 } }).pointsNeeded(mesh), 0.0);
  // A bound whose square underflows asks for infinitely many: refused upstream.
  EXPECT_EQ(SizeBoxes({ SizeBox{ { { 0, 0 }, { 1, 1 } }, 1e-300 } }).pointsNeeded(mesh),
    std::numeric_limits<double>::infinity());
}
