// Tests of the independent mesh validator: valid hand-made meshes pass, and each check
// fails on a mesh built to break it, with a message naming the broken element.
#include "Validate.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace
{

using osm::Array;
using osm::Point;
using osm::Pslg;
using osm::Segment;
using osm::Triangle;
using osm::ValidationOptions;
using osm::ValidationReport;

/// Validates with every mesh vertex as an input point, plus the given segments.
ValidationReport check(const Array<Point>& points, const Array<Triangle>& triangles,
  const Array<Segment>& segments = {}, const ValidationOptions& options = {})
{
  Pslg input;
  input.points = points;
  input.segments = segments;
  return osm::validate(input, points, triangles, options);
}

bool mentions(const ValidationReport& report, const std::string& text)
{
  for (const std::string& e : report.errors)
    if (e.find(text) != std::string::npos)
      return true;
  return false;
}

/// All messages, for the failure output of an assertion.
std::string dump(const ValidationReport& report)
{
  std::string all;
  for (const std::string& e : report.errors)
    all += "\n  " + e;
  return all;
}

const Array<Point> kSquare = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
const Array<Triangle> kSquareTriangles = { { 0, 1, 2 }, { 0, 2, 3 } };

/// n x n unit squares, each split in two, interior vertices jittered by up to `jitter` in
/// each coordinate (under a third of the smallest altitude, so orientation stays positive).
/// The input is the outer square: four corners, four sides.
struct Grid
{
  Array<Point> points;
  Array<Triangle> triangles;
  Pslg input;
};

Grid makeGrid(int n, double jitter, unsigned seed)
{
  Grid g;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> shift(-jitter, jitter);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
    {
      const bool inside = i > 0 && i < n && j > 0 && j < n;
      g.points.push_back(
        { i + (inside ? shift(random) : 0.0), j + (inside ? shift(random) : 0.0) });
    }
  const auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
    {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if ((i + j) % 2 == 0)
        g.triangles.insert(g.triangles.end(), { { a, b, c }, { a, c, d } });
      else
        g.triangles.insert(g.triangles.end(), { { a, b, d }, { b, c, d } });
    }
  g.input.points = { g.points[id(0, 0)], g.points[id(n, 0)], g.points[id(n, n)],
    g.points[id(0, n)] };
  g.input.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
  return g;
}

TEST(Validate, SquareWithDiagonalPasses)
{
  const auto r =
    check(kSquare, kSquareTriangles, { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 0, 2 } });
  EXPECT_TRUE(r.ok) << dump(r);
  EXPECT_EQ(r.errorCount, 0u);
  EXPECT_EQ(r.triangles, 2u);
  EXPECT_NEAR(r.minAngleDeg, 45.0, 1e-12);
  EXPECT_NEAR(r.maxAngleDeg, 90.0, 1e-12);
}

TEST(Validate, RegularHexagonFanPasses)
{
  Array<Point> points = { { 0, 0 } };
  Array<Triangle> triangles;
  for (int i = 0; i < 6; ++i)
  {
    points.push_back({ std::cos(i * M_PI / 3), std::sin(i * M_PI / 3) });
    triangles.push_back({ 0, 1 + i, 1 + (i + 1) % 6 });
  }
  const auto r = check(points, triangles, { { 0, 1 }, { 1, 2 } });
  EXPECT_TRUE(r.ok) << dump(r);
  EXPECT_NEAR(r.minAngleDeg, 60.0, 1e-9);
  EXPECT_NEAR(r.maxAngleDeg, 60.0, 1e-9);
}

TEST(Validate, EmptyMeshPassesOnlyWithoutInputPoints)
{
  EXPECT_TRUE(check({}, {}).ok);
  Pslg input;
  input.points = kSquare;
  const auto r = osm::validate(input, {}, {});
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.errorCount, 4u);
}

TEST(Validate, IndexOutOfRangeFails)
{
  auto triangles = kSquareTriangles;
  triangles.push_back({ 0, 1, 7 });
  const auto r = check(kSquare, triangles);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "triangle 2 (0, 1, 7) has vertex index 7 out of range")) << dump(r);
}

TEST(Validate, RepeatedVertexFails)
{
  auto triangles = kSquareTriangles;
  triangles.push_back({ 0, 0, 1 });
  const auto r = check(kSquare, triangles);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "triangle 2 (0, 0, 1) repeats a vertex")) << dump(r);
}

TEST(Validate, ClockwiseTriangleFails)
{
  const auto r = check(kSquare, { { 0, 2, 1 }, { 0, 2, 3 } });
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "triangle 0 (0, 2, 1) has non-positive orientation")) << dump(r);
}

TEST(Validate, EdgeInThreeTrianglesFails)
{
  const Array<Point> points = { { 0, 0 }, { 1, 0 }, { 0.5, 1 }, { 0.5, 2 }, { 0.5, -1 } };
  const auto r = check(points, { { 0, 1, 2 }, { 0, 1, 3 }, { 1, 0, 4 } });
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "edge (0, 1) is shared by 3 triangles: 0, 1, 2")) << dump(r);
}

TEST(Validate, SharedEdgeInSameDirectionFails)
{
  const Array<Point> points = { { 0, 0 }, { 1, 0 }, { 0.5, 1 }, { 0.5, 2 } };
  const auto r = check(points, { { 0, 1, 2 }, { 0, 1, 3 } });
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "edge (0, 1) has the same direction in triangles 0, 1")) << dump(r);
}

TEST(Validate, FanWrappingTwiceFails)
{
  // 12 positive triangles of 60 degrees each around the origin: 720 degrees. Alternate
  // radii keep the ring vertices distinct.
  Array<Point> points = { { 0, 0 } };
  Array<Triangle> triangles;
  for (int i = 0; i < 12; ++i)
  {
    const double r = i < 6 ? 1.0 : 2.0;
    points.push_back({ r * std::cos(i * M_PI / 3), r * std::sin(i * M_PI / 3) });
    triangles.push_back({ 0, 1 + i, 1 + (i + 1) % 12 });
  }
  const auto r = check(points, triangles);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(
    mentions(r, "vertex 0 (0, 0): its closed fan of 12 triangles has angles summing to 720"))
    << dump(r);

  ValidationOptions noBruteForce;
  noBruteForce.bruteForceOverlapLimit = 0;
  const auto r2 = check(points, triangles, {}, noBruteForce);
  EXPECT_FALSE(r2.ok);
  EXPECT_TRUE(mentions(r2, "vertex 0 (0, 0)")) << dump(r2);
}

TEST(Validate, OpenFanWrappingPastItselfFails)
{
  // 7 triangles of 60 degrees: an open fan turning 420 degrees around the origin.
  Array<Point> points = { { 0, 0 } };
  Array<Triangle> triangles;
  for (int i = 0; i < 8; ++i)
  {
    const double r = 1.0 + 0.1 * i;
    points.push_back({ r * std::cos(i * M_PI / 3), r * std::sin(i * M_PI / 3) });
    if (i < 7)
      triangles.push_back({ 0, 1 + i, 2 + i });
  }
  ValidationOptions noBruteForce;
  noBruteForce.bruteForceOverlapLimit = 0;
  const auto r = check(points, triangles, {}, noBruteForce);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "vertex 0 (0, 0): its open fan of 7 triangles overlaps itself"))
    << dump(r);
}

TEST(Validate, OverlappingTrianglesWithoutSharedEdgeFail)
{
  const Array<Point> points = { { 0, 0 }, { 4, 0 }, { 0, 4 }, { 1, 1 }, { 5, 1 }, { 1, 5 } };
  const Array<Triangle> triangles = { { 0, 1, 2 }, { 3, 4, 5 } };
  const auto r = check(points, triangles);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "triangle 0 (0, 1, 2) and triangle 1 (3, 4, 5) overlap")) << dump(r);

  ValidationOptions noBruteForce;
  noBruteForce.bruteForceOverlapLimit = 0;
  const auto r2 = check(points, triangles, {}, noBruteForce);
  EXPECT_FALSE(r2.ok);
  EXPECT_FALSE(mentions(r2, "overlap")) << dump(r2);
  EXPECT_TRUE(mentions(r2, "vertex 3 (1, 1) lies in triangle 0 (0, 1, 2)")) << dump(r2);
  EXPECT_TRUE(mentions(r2, "boundary edges (1, 2) and (3, 4) cross")) << dump(r2);
}

TEST(Validate, NestedIslandFailsWithoutBruteForce)
{
  // A small triangle strictly inside a big one: no crossing, no shared element. Without the
  // pairwise check and with the vertex check on boundary vertices only, it is still caught.
  const Array<Point> points = { { 0, 0 }, { 9, 0 }, { 0, 9 }, { 1, 1 }, { 2, 1 }, { 1, 2 } };
  ValidationOptions noBruteForce;
  noBruteForce.bruteForceOverlapLimit = 0;
  const auto r = check(points, { { 0, 1, 2 }, { 3, 4, 5 } }, {}, noBruteForce);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "vertex 3 (1, 1) lies in triangle 0 (0, 1, 2)")) << dump(r);
}

TEST(Validate, VertexOnBoundaryEdgeFails)
{
  // A T-junction: vertex 4 splits the top of one triangle but not the triangle above it.
  const Array<Point> points = { { 0, 0 }, { 2, 0 }, { 0, 2 }, { 2, 2 }, { 1, 1 } };
  ValidationOptions noBruteForce;
  noBruteForce.bruteForceOverlapLimit = 0;
  const auto r = check(points, { { 0, 1, 2 }, { 1, 3, 4 }, { 4, 3, 2 } }, {}, noBruteForce);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "vertex 4 (1, 1) lies on boundary edge (1, 2)")) << dump(r);
}

TEST(Validate, CoincidentVerticesFail)
{
  const Array<Point> points = { { 0, 0 }, { 1, 0 }, { 0, 1 }, { 1, 0 }, { 1, 1 } };
  const auto r = check(points, { { 0, 1, 2 }, { 3, 4, 2 } });
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "vertices 1 and 3 coincide at (1, 0)")) << dump(r);
}

TEST(Validate, MissingInputVertexFails)
{
  Pslg input;
  input.points = kSquare;
  input.points.push_back({ 0.5, 0.25 });
  const auto r = osm::validate(input, kSquare, kSquareTriangles);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "input point 4 (0.5, 0.25) is not a mesh vertex")) << dump(r);

  ValidationOptions lenient;
  lenient.requireAllInputVertices = false;
  EXPECT_TRUE(osm::validate(input, kSquare, kSquareTriangles, lenient).ok);
}

TEST(Validate, SegmentThatIsNoChainOfEdgesFails)
{
  const auto r = check(kSquare, kSquareTriangles, { { 0, 2 }, { 1, 3 } });
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "segment 1 (input points 1, 3) is not a chain of mesh edges")) << dump(r);
  EXPECT_FALSE(mentions(r, "segment 0")) << dump(r);

  ValidationOptions noConformity;
  noConformity.checkConformity = false;
  EXPECT_TRUE(check(kSquare, kSquareTriangles, { { 1, 3 } }, noConformity).ok);
}

/// Segment (0, 1) from (0, 0) to (2, 0) meshed as a chain through vertex 2 at (1, y).
Array<Point> chainThrough(double y)
{
  return { { 0, 0 }, { 2, 0 }, { 1, y }, { 1, -1 }, { 1, 1 } };
}
const Array<Triangle> kChainTriangles = { { 0, 3, 2 }, { 3, 1, 2 }, { 0, 2, 4 }, { 2, 1, 4 } };

TEST(Validate, SegmentChainThroughOffLinePointFails)
{
  const auto r = check(chainThrough(0.1), kChainTriangles, { { 0, 1 } });
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "segment 0 (input points 0, 1) is not a chain of mesh edges")) << dump(r);
}

TEST(Validate, SegmentChainThroughRoundedOrInputPointPasses)
{
  // A rounded intersection point, off the line by far less than the tolerance.
  auto r = check(chainThrough(1e-15), kChainTriangles, { { 0, 1 } });
  EXPECT_TRUE(r.ok) << dump(r);
  // An input vertex exactly on the segment splits it.
  r = check(chainThrough(0.0), kChainTriangles, { { 0, 1 } });
  EXPECT_TRUE(r.ok) << dump(r);
}

TEST(Validate, SegmentChainWithinTheChainOffsetPasses)
{
  // Where a merge tolerance joined crossings, a chain may bend through a
  // vertex as far off its segment's line as the offset allowed, and no more,
  // where another segment passes (here segment 1, x = 1, through vertex 2).
  ValidationOptions joined;
  joined.chainOffset = 0.1;
  const Array<Segment> crossed = { { 0, 1 }, { 3, 4 } };
  EXPECT_TRUE(check(chainThrough(0.1), kChainTriangles, crossed, joined).ok);
  EXPECT_TRUE(check(chainThrough(-0.05), kChainTriangles, crossed, joined).ok);
  auto r = check(chainThrough(0.11), kChainTriangles, crossed, joined);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "nearest forward neighbour is 0.11 off the line")) << dump(r);
  // Scaled for exact arithmetic with the coordinates.
  Array<Point> tiny = chainThrough(0.1);
  for (Point& p : tiny)
    p = { p.x * 0x1p-200, p.y * 0x1p-200 };
  joined.chainOffset = 0.1 * 0x1p-200;
  EXPECT_TRUE(check(tiny, kChainTriangles, crossed, joined).ok);
  joined.chainOffset = 0.09 * 0x1p-200;
  EXPECT_FALSE(check(tiny, kChainTriangles, crossed, joined).ok);
}

TEST(Validate, SegmentChainBendingWhereNoOtherSegmentPassesFails)
{
  // A bend needs a crossing that was joined there: without segment 1 through
  // vertex 2, or with it too far away, the chain through vertex 2 is not one
  // (as after an edge on a segment is flipped).
  ValidationOptions joined;
  joined.chainOffset = 0.1;
  const std::string message =
    "segment 0 (input points 0, 1) is not a chain of mesh edges: its only chains within 0.1 of "
    "the line bend where no other input segment passes within 0.2";
  auto r = check(chainThrough(0.1), kChainTriangles, { { 0, 1 } }, joined);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, message)) << dump(r);
  // Segment 1 from (1.21, -1) to (1.21, 1) passes 0.21 from vertex 2; at
  // (1.19, ...) it passes within 0.2.
  Array<Point> points = chainThrough(0.1);
  points.push_back({ 1.21, -1 });
  points.push_back({ 1.21, 1 });
  ValidationOptions noPoints = joined;
  noPoints.requireAllInputVertices = false;
  r = check(points, kChainTriangles, { { 0, 1 }, { 5, 6 } }, noPoints);
  EXPECT_TRUE(mentions(r, message)) << dump(r);
  points[5].x = points[6].x = 1.19;
  r = check(points, kChainTriangles, { { 0, 1 }, { 5, 6 } }, noPoints);
  EXPECT_TRUE(r.ok) << dump(r);
}

TEST(Validate, SegmentWithAPointIndexOutOfRangeIsNamed)
{
  for (double offset : { 0.0, 0.1 })
  {
    ValidationOptions options;
    options.chainOffset = offset;
    const auto r = check(chainThrough(0.1), kChainTriangles, { { 3, 4 }, { 3, 99 } }, options);
    EXPECT_EQ(r.errorCount, 1u) << dump(r);
    EXPECT_TRUE(mentions(r, "segment 1 (input points 3, 99) has a point index out of range"))
      << dump(r);
  }
}

TEST(Validate, LargeAngleFails)
{
  const Array<Point> points = { { 0, 0 }, { 2, 0 }, { 1, std::tan(2.5 * M_PI / 180) } };
  ValidationOptions options;
  options.maxAngleDeg = 170;
  const auto r = check(points, { { 0, 1, 2 } }, {}, options);
  EXPECT_FALSE(r.ok);
  EXPECT_NEAR(r.maxAngleDeg, 175.0, 1e-9);
  EXPECT_NEAR(r.minAngleDeg, 2.5, 1e-9);
  EXPECT_TRUE(mentions(r, "triangle 0 (0, 1, 2) has an angle of 175")) << dump(r);
  options.maxAngleDeg = 176;
  EXPECT_TRUE(check(points, { { 0, 1, 2 } }, {}, options).ok);
}

TEST(Validate, EdgeLongerThanTheBoundFails)
{
  // The unit square's diagonal is sqrt(2) long.
  ValidationOptions options;
  options.maxEdgeLength = 1.4;
  const auto r = check(kSquare, kSquareTriangles, {}, options);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "has an edge of length 1.414")) << dump(r);
  EXPECT_TRUE(mentions(r, "(2 triangle(s) exceed the maximum edge length)")) << dump(r);
  options.maxEdgeLength = std::sqrt(2.0);
  EXPECT_TRUE(check(kSquare, kSquareTriangles, {}, options).ok);
  // Checked in the validator's own scaled coordinates too.
  Array<Point> huge = kSquare;
  for (Point& p : huge)
    p = { p.x * 1e200, p.y * 1e200 };
  options.maxEdgeLength = 1.4e200;
  EXPECT_FALSE(check(huge, kSquareTriangles, {}, options).ok);
  options.maxEdgeLength = 1.5e200;
  EXPECT_TRUE(check(huge, kSquareTriangles, {}, options).ok);
}

TEST(Validate, BowtieVertexPasses)
{
  // Two triangles touching only at vertex 0, as where a domain's boundary touches itself.
  const Array<Point> points = { { 0, 0 }, { 1, -1 }, { 1, 1 }, { -1, 1 }, { -1, -1 } };
  const auto r = check(points, { { 0, 1, 2 }, { 0, 3, 4 } });
  EXPECT_TRUE(r.ok) << dump(r);
}

TEST(Validate, BowtieWithOverlappingFansFails)
{
  // Two fans at vertex 0 whose sectors (-45..45 and 0..45 degrees) overlap.
  const Array<Point> points = { { 0, 0 }, { 1, -1 }, { 1, 1 }, { 3, 0 }, { 3, 3 } };
  ValidationOptions noBruteForce;
  noBruteForce.bruteForceOverlapLimit = 0;
  const auto r = check(points, { { 0, 1, 2 }, { 0, 3, 4 } }, {}, noBruteForce);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "vertex 0 (0, 0): 2 fans of triangles meet there and overlap"))
    << dump(r);
}

/// Removes the two triangles of each listed square (i, j) of an n x n grid.
void removeSquares(Grid& g, int n, const std::vector<std::pair<int, int>>& squares)
{
  std::vector<char> removed(g.triangles.size(), 0);
  for (const auto& [i, j] : squares)
    removed[2 * (j * n + i)] = removed[2 * (j * n + i) + 1] = 1;
  Array<Triangle> kept;
  for (std::size_t t = 0; t < g.triangles.size(); ++t)
    if (!removed[t])
      kept.push_back(g.triangles[t]);
  g.triangles = kept;
}

TEST(Validate, SmallGridPassesBruteForce)
{
  const Grid g = makeGrid(30, 0.15, 5); // 1800 triangles: every check, pairwise included
  const auto r = osm::validate(g.input, g.points, g.triangles);
  EXPECT_TRUE(r.ok) << dump(r);
}

TEST(Validate, GridWithHolesPasses)
{
  // A 3 x 3 hole (its inner vertices left unreferenced) and two holes touching at the
  // vertex (16, 16), which is then a valid bowtie.
  Grid g = makeGrid(20, 0.15, 9);
  std::vector<std::pair<int, int>> squares = { { 15, 15 }, { 16, 16 } };
  for (int j = 4; j < 7; ++j)
    for (int i = 4; i < 7; ++i)
      squares.push_back({ i, j });
  removeSquares(g, 20, squares);
  const auto r = osm::validate(g.input, g.points, g.triangles);
  EXPECT_TRUE(r.ok) << dump(r);

  ValidationOptions boundaryOnly; // vertex-in-triangle on boundary vertices only
  boundaryOnly.bruteForceOverlapLimit = 1;
  EXPECT_TRUE(osm::validate(g.input, g.points, g.triangles, boundaryOnly).ok);
}

TEST(Validate, HolesInTheGridFailTheDomainCheckUnlessTheyAreInTheInput)
{
  // A review found that the cover check alone passes the grid with holes
  // above, whose input is the outer square only: a mesher that dropped those
  // triangles would pass. With the domain checked it fails, and passes when
  // the input's segments bound the holes.
  Grid g = makeGrid(20, 0.15, 9);
  removeSquares(g, 20, { { 15, 15 } });
  ValidationOptions o;
  o.boundary = osm::DomainBoundary::Segments;
  const auto r = osm::validate(g.input, g.points, g.triangles, o);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "lies along no input segment: a triangle is missing inside the domain"))
    << dump(r);
  EXPECT_EQ(r.errorCount, 4u); // the square's four sides
  const int n = 20;
  const auto id = [n](int i, int j) { return j * (n + 1) + i; };
  Pslg bounded = g.input;
  for (const auto& [i, j] :
    std::vector<std::pair<int, int>>{ { 15, 15 }, { 16, 15 }, { 16, 16 }, { 15, 16 } })
    bounded.points.push_back(g.points[id(i, j)]);
  for (int k = 0; k < 4; ++k)
    bounded.segments.push_back({ 4 + k, 4 + (k + 1) % 4 });
  const auto fixed = osm::validate(bounded, g.points, g.triangles, o);
  EXPECT_TRUE(fixed.ok) << dump(fixed);
  // The hull allows the outer square, not the holes.
  o.boundary = osm::DomainBoundary::SegmentsOrHull;
  EXPECT_FALSE(osm::validate(g.input, g.points, g.triangles, o).ok);
}

TEST(Validate, ATriangleBeyondTheDomainFails)
{
  // The unit square's mesh plus a separate triangle: its edges lie along no
  // segment, and beyond the hull of the input points (the square's corners).
  Array<Point> points = kSquare;
  points.insert(points.end(), { { 3, 0 }, { 4, 0 }, { 3, 1 } });
  Array<Triangle> triangles = kSquareTriangles;
  triangles.push_back({ 4, 5, 6 });
  Pslg input;
  input.points = points;
  input.points.resize(4);
  input.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
  ValidationOptions o;
  o.requireAllInputVertices = false;
  o.boundary = osm::DomainBoundary::Segments;
  EXPECT_EQ(osm::validate(input, points, triangles, o).errorCount, 3u);
  o.boundary = osm::DomainBoundary::SegmentsOrHull;
  EXPECT_EQ(osm::validate(input, points, triangles, o).errorCount, 3u);
  // The bounding rectangle of every vertex holds the far triangle's bottom
  // edge (y = 0), not its other two.
  o.boundary = osm::DomainBoundary::SegmentsOrBox;
  EXPECT_EQ(osm::validate(input, points, triangles, o).errorCount, 2u);
  triangles.pop_back();
  for (auto b : { osm::DomainBoundary::Segments, osm::DomainBoundary::SegmentsOrHull,
         osm::DomainBoundary::SegmentsOrBox })
  {
    o.boundary = b;
    EXPECT_TRUE(osm::validate(input, points, triangles, o).ok);
  }
}

TEST(Validate, TheHullDomainsBoundaryMayRunAlongTheHullBetweenSegments)
{
  // Free points at the square's corners and one segment across it: the
  // mesh of the hull has boundary edges on the hull only, and a boundary
  // edge cut short of a hull corner fails.
  Pslg input;
  input.points = kSquare;
  input.points.push_back({ 0.5, 0.5 });
  input.segments = { { 0, 4 } };
  const Array<Point> points = input.points;
  const Array<Triangle> whole = { { 0, 1, 4 }, { 1, 2, 4 }, { 2, 3, 4 }, { 3, 0, 4 } };
  ValidationOptions o;
  o.boundary = osm::DomainBoundary::SegmentsOrHull;
  EXPECT_TRUE(osm::validate(input, points, whole, o).ok);
  const Array<Triangle> missing = { { 0, 1, 4 }, { 1, 2, 4 }, { 2, 3, 4 } };
  const auto r = osm::validate(input, points, missing, o);
  EXPECT_EQ(r.errorCount, 1u) << dump(r); // (3, 4): (0, 4) is a segment
  EXPECT_TRUE(mentions(r, "nor the convex hull")) << dump(r);
}

TEST(Validate, ABoundaryEdgeWithinRoundingOfATinyHullEdgeIsAlongIt)
{
  // Found by fuzzing the domain check: the hull's bottom edge runs from
  // (1, -1.5e-48) to (13, 0), and the mesh's boundary along it through
  // crossings rounded to y = 1.1e-16, which the box test of the lines left
  // out (their boxes were not grown by the rounding allowance).
  Pslg input;
  input.points = { { 0, 0 }, { 1, -1.5390887117594296e-48 }, { 13, 0 }, { 13, 5 }, { 0, 5 } };
  Array<Point> points = input.points;
  points.insert(points.end(),
    { { 3.0234804000625357, 1.1102230246251565e-16 },
      { 4.52691707195536, 1.1102230246251565e-16 } });
  const Array<Triangle> triangles = { { 0, 1, 4 }, { 1, 5, 4 }, { 5, 6, 4 }, { 6, 3, 4 },
    { 6, 2, 3 } };
  ValidationOptions o;
  o.boundary = osm::DomainBoundary::SegmentsOrHull;
  const auto r = osm::validate(input, points, triangles, o);
  EXPECT_TRUE(r.ok) << dump(r);
  // 1e-6 above the edge is no rounding.
  points[5].y = points[6].y = 1e-6;
  EXPECT_FALSE(osm::validate(input, points, triangles, o).ok);
}

TEST(Validate, AHoleSeedInsideATriangleFails)
{
  // A square with a square hole, meshed with the hole filled: the seed lies
  // inside a triangle. On an edge it is in no triangle's interior.
  Pslg input;
  input.points = { { 0, 0 }, { 3, 0 }, { 3, 3 }, { 0, 3 }, { 1, 1 }, { 2, 1 }, { 2, 2 }, { 1, 2 } };
  input.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 6 }, { 6, 7 },
    { 7, 4 } };
  input.holes = { { 1.25, 1.5 } };
  const Array<Triangle> ring = { { 0, 1, 5 }, { 0, 5, 4 }, { 1, 2, 6 }, { 1, 6, 5 }, { 2, 3, 7 },
    { 2, 7, 6 }, { 3, 0, 4 }, { 3, 4, 7 } };
  Array<Triangle> filled = ring;
  filled.insert(filled.end(), { { 4, 5, 6 }, { 4, 6, 7 } });
  ValidationOptions o;
  o.checkHoles = true;
  o.boundary = osm::DomainBoundary::Segments;
  EXPECT_TRUE(osm::validate(input, input.points, ring, o).ok);
  const auto r = osm::validate(input, input.points, filled, o);
  EXPECT_EQ(r.errorCount, 1u) << dump(r);
  EXPECT_TRUE(mentions(r, "hole seed 0 (1.25, 1.5) lies in triangle 9")) << dump(r);
  // A seed on the filling's diagonal (4, 6), as at a hole's centre, is in
  // it too (a review: it passed); one on a segment is not judged, as the
  // mesher removes one side of it and keeps the other.
  input.holes = { { 1.5, 1.5 } };
  EXPECT_EQ(osm::validate(input, input.points, filled, o).errorCount, 1u);
  input.holes = { { 1.5, 1 } };
  EXPECT_TRUE(osm::validate(input, input.points, filled, o).ok);
  EXPECT_TRUE(osm::validate(input, input.points, ring, o).ok);
}

TEST(Validate, JitteredGridPasses)
{
  const Grid g = makeGrid(200, 0.15, 7);
  const auto start = std::chrono::steady_clock::now();
  const auto r = osm::validate(g.input, g.points, g.triangles);
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  EXPECT_TRUE(r.ok) << dump(r);
  EXPECT_EQ(r.triangles, 80000u);
  EXPECT_GT(r.minAngleDeg, 10.0);
  EXPECT_LT(r.maxAngleDeg, 170.0);
  std::printf("validated %zu triangles in %.3f s\n", r.triangles, seconds.count());
}

TEST(Validate, JitteredGridWithFlippedTriangleFails)
{
  Grid g = makeGrid(200, 0.15, 7);
  g.points[100 * 201 + 100] = { 101.6, 100.3 }; // pushed across its right neighbour
  const auto r = osm::validate(g.input, g.points, g.triangles);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(mentions(r, "has non-positive orientation")) << dump(r);
}

TEST(Validate, ErrorMessagesAreCappedButCounted)
{
  Grid g = makeGrid(20, 0.0, 1);
  for (Triangle& t : g.triangles)
    std::swap(t[1], t[2]);
  const auto r = osm::validate(g.input, g.points, g.triangles);
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.errors.size(), ValidationOptions().maxErrorMessages);
  EXPECT_GE(r.errorCount, g.triangles.size());
}

// Timing only: run with --gtest_also_run_disabled_tests.
TEST(Validate, DISABLED_MillionTriangleGrid)
{
  const Grid g = makeGrid(708, 0.15, 3);
  const auto start = std::chrono::steady_clock::now();
  const auto r = osm::validate(g.input, g.points, g.triangles);
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  EXPECT_TRUE(r.ok) << dump(r);
  std::printf("validated %zu triangles in %.3f s\n", r.triangles, seconds.count());
}

} // namespace
