// Phase 3: the min-max-angle triangulation of a polygon, checked against an
// exhaustive search over all triangulations of small polygons.
#include "Complete.h"
#include "Predicates.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

using namespace osm;

namespace
{

/// The largest angle as the three angles give it: the oracle, independent of
/// maxAngle's shortcut.
double maxOfThree(const Point& a, const Point& b, const Point& c)
{
  return std::max({ angleAt(c, a, b), angleAt(a, b, c), angleAt(b, c, a) });
}

double largestAngle(const Array<Point>& P, const Array<Triangle>& tris)
{
  double m = 0;
  for (const Triangle& t : tris)
    m = std::max(m, maxOfThree(P[t[0]], P[t[1]], P[t[2]]));
  return m;
}

/// Smallest largest angle over all triangulations of a convex polygon (Catalan many).
double bruteForceConvex(const Array<Point>& P)
{
  const int k = static_cast<int>(P.size());
  std::function<double(int, int)> best = [&](int i, int j) -> double {
    if (j - i < 2)
      return 0;
    double b = std::numeric_limits<double>::infinity();
    for (int m = i + 1; m < j; ++m)
      b = std::min(b, std::max({ best(i, m), best(m, j), maxOfThree(P[i], P[m], P[j]) }));
    return b;
  };
  return best(0, k - 1);
}

Array<int> iota(std::size_t n)
{
  Array<int> ids(n);
  std::iota(ids.begin(), ids.end(), 0);
  return ids;
}

void expectValidTriangulation(const Array<Point>& P, const Array<Triangle>& tris)
{
  ASSERT_EQ(tris.size(), P.size() - 2);
  double area = 0, polygonArea = 0;
  for (const Triangle& t : tris)
  {
    ASSERT_GT(orient2d(P[t[0]], P[t[1]], P[t[2]]), 0);
    area += orient2d(P[t[0]], P[t[1]], P[t[2]]);
  }
  for (std::size_t i = 0; i < P.size(); ++i)
  {
    const Point &a = P[i], &b = P[(i + 1) % P.size()];
    polygonArea += a.x * b.y - b.x * a.y;
  }
  EXPECT_NEAR(area, polygonArea, 1e-9 * std::fabs(polygonArea));
}

} // namespace

TEST(Complete, ConvexPolygonsMatchExhaustiveSearch)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(0, 2 * std::acos(-1.0));
  for (int trial = 0; trial < 200; ++trial)
  {
    const int k = 4 + trial % 5;
    std::vector<double> angles(k);
    for (double& a : angles)
      a = U(rng);
    std::sort(angles.begin(), angles.end());
    Array<Point> P;
    for (double a : angles)
      P.push_back({ std::cos(a) * (1 + 0.0 * a), std::sin(a) });
    Array<Triangle> tris;
    ASSERT_TRUE(triangulateMinMaxAngle(P, iota(P.size()), tris));
    expectValidTriangulation(P, tris);
    EXPECT_NEAR(largestAngle(P, tris), bruteForceConvex(P), 1e-12) << "trial " << trial;
  }
}

TEST(Complete, NonConvexPolygonUsesOnlyInteriorDiagonals)
{
  // An arrow-head: vertex 2 is reflex, so diagonal 1-3 lies outside.
  const Array<Point> P{ { 0, 0 }, { 4, 0 }, { 2, 1 }, { 4, 4 }, { 0, 4 } };
  Array<Triangle> tris;
  ASSERT_TRUE(triangulateMinMaxAngle(P, iota(P.size()), tris));
  expectValidTriangulation(P, tris);
  for (const Triangle& t : tris)
    for (int i = 0; i < 3; ++i)
      EXPECT_FALSE((t[i] == 1 && t[(i + 1) % 3] == 3) || (t[i] == 3 && t[(i + 1) % 3] == 1));
}

TEST(Complete, StraightAnglesNeverGiveZeroAreaTriangles)
{
  // Stitch vertices make 180° polygon corners: a square with points on its sides.
  const Array<Point> P{ { 0, 0 }, { 1, 0 }, { 2, 0 }, { 2, 1 }, { 2, 2 }, { 1, 2 }, { 0, 2 },
    { 0, 1 } };
  Array<Triangle> tris;
  ASSERT_TRUE(triangulateMinMaxAngle(P, iota(P.size()), tris));
  expectValidTriangulation(P, tris);
  EXPECT_LE(largestAngle(P, tris) * 180 / std::acos(-1.0), 90.0 + 1e-9);
}

TEST(Complete, ReportsImpossiblePolygons)
{
  // All vertices collinear: no triangle of positive area exists.
  const Array<Point> P{ { 0, 0 }, { 1, 0 }, { 2, 0 }, { 3, 0 } };
  Array<Triangle> tris;
  EXPECT_FALSE(triangulateMinMaxAngle(P, iota(P.size()), tris));
}

// maxAngle computes only the angles opposite the longest edges; its value
// must be exactly the largest of all three, ties and extreme scales included.
TEST(Complete, MaxAngleIsTheLargestOfTheThreeAngles)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<std::array<Point, 3>> cases = {
    { { { 0, 0 }, { 1, 0 }, { 0.5, std::sqrt(3.0) / 2 } } }, // equilateral, within rounding
    { { { 0, 0 }, { 1, 0 }, { 0, 1 } } },                    // right isosceles
    { { { 0, 0 }, { 2, 0 }, { 1, 1e-12 } } },                // nearly flat, isosceles
    { { { 0, 0 }, { 1, 0 }, { 2, 0 } } },                    // flat
    { { { 0, 0 }, { 0, 0 }, { 1, 1 } } },                    // a repeated point
    { { { 0, 0 }, { 1e-160, 0 }, { 0, 1e-160 } } },          // squares underflow
    { { { 0, 0 }, { 1e160, 0 }, { 0, 1e160 } } },            // squares overflow
  };
  for (int i = 0; i < 20000; ++i)
  {
    const Point a{ unit(rng), unit(rng) };
    const Point b{ unit(rng), unit(rng) };
    cases.push_back({ a, b, { unit(rng), unit(rng) } });
    // Isosceles within rounding: c on the perpendicular bisector of ab.
    const double t = unit(rng);
    cases.push_back(
      { a, b, { 0.5 * (a.x + b.x) - t * (b.y - a.y), 0.5 * (a.y + b.y) + t * (b.x - a.x) } });
  }
  for (const auto& c : cases)
    for (int r = 0; r < 3; ++r) // every rotation of the corners
    {
      const Point &p = c[r], &q = c[(r + 1) % 3], &s = c[(r + 2) % 3];
      ASSERT_EQ(maxAngle(p, q, s), maxOfThree(p, q, s))
        << p.x << "," << p.y << " " << q.x << "," << q.y << " " << s.x << "," << s.y;
    }
}

// Quadrilaterals take a shortcut: the dynamic program unrolled, with four
// orientation tests for all of its diagonal and apex tests. It must give
// exactly what the program gives, ties (squares, kites) and degenerate
// quadrilaterals (straight and zero angles, repeated and collinear points,
// reflex and clockwise ones) included.
TEST(Complete, QuadrilateralsAsTheDynamicProgram)
{
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> grid(0, 3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Array<int> ids{ 10, 11, 12, 13 };
  int triangulated = 0, ties = 0;
  for (int trial = 0; trial < 100000; ++trial)
  {
    Array<Point> P(4);
    for (Point& p : P)
      p = trial % 2 == 0 ? Point{ double(grid(rng)), double(grid(rng)) }
                         : Point{ unit(rng), unit(rng) };
    Array<Triangle> quick, program;
    MinMaxScratch scratch;
    const bool a = triangulateMinMaxAngle(P, ids, quick, scratch);
    const bool b = triangulateMinMaxAngleByProgram(P, ids, program, scratch);
    ASSERT_EQ(a, b) << "trial " << trial;
    ASSERT_EQ(quick, program) << "trial " << trial;
    triangulated += a;
    ties += a && maxOfThree(P[0], P[1], P[3]) == maxOfThree(P[0], P[2], P[3]);
  }
  // The cases must have come up: triangulated ones, and ties between the diagonals.
  EXPECT_GT(triangulated, 15000);
  EXPECT_GT(ties, 100) << ties;
}
