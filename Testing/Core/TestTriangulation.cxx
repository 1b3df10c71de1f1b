// The triangulation layer: bulk Delaunay insertion and the SVR overlay, checked
// for the empty-circle property, quality, and that every point is a vertex.
#include "Delaunay.h"
#include "Overlay.h"
#include "Predicates.h"
#include "SpatialSort.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

using namespace osm;

namespace
{

/// Every live triangle is CCW, neighbours agree, and no neighbour's far vertex
/// lies strictly inside its circumcircle (local Delaunay = Delaunay).
void expectDelaunay(const Triangulation& T)
{
  for (int t = 0; t < T.slots(); ++t)
  {
    if (!T.alive(t))
      continue;
    ASSERT_GT(orient2d(T.vertex(t, 0), T.vertex(t, 1), T.vertex(t, 2)), 0) << "triangle " << t;
    for (int i = 0; i < 3; ++i)
    {
      const int u = T.tri[t].n[i];
      if (u < 0)
        continue;
      ASSERT_TRUE(T.alive(u));
      int far = -1;
      for (int j = 0; j < 3; ++j)
        if (T.localIndex(t, T.tri[u].v[j]) < 0)
          far = T.tri[u].v[j];
      ASSERT_GE(far, 0);
      EXPECT_LE(incircle(T.vertex(t, 0), T.vertex(t, 1), T.vertex(t, 2), T.points[far]), 0)
        << "triangle " << t << " is not Delaunay";
    }
  }
}

Array<Point> randomPoints(int n, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  Array<Point> pts(n);
  for (Point& p : pts)
    p = { U(rng), U(rng) };
  return pts;
}

/// Two triangles covering the square [-4, 4]^2; its corners are vertices 0 to 3.
Triangulation squareOfSide8()
{
  Triangulation T;
  const int c0 = T.addPoint({ -4, -4 }), c1 = T.addPoint({ 4, -4 });
  const int c2 = T.addPoint({ 4, 4 }), c3 = T.addPoint({ -4, 4 });
  T.link(T.newTriangle(c0, c1, c2), T.newTriangle(c0, c2, c3));
  return T;
}

/// A start for point location.
int anyLiveTriangle(const Triangulation& T)
{
  for (int t = 0; t < T.slots(); ++t)
    if (T.alive(t))
      return t;
  return -1;
}

} // namespace

TEST(Triangulation, BulkDelaunayOfRandomAndGridPoints)
{
  Array<int> vertexOf;
  Triangulation T = delaunayTriangulation(randomPoints(3000, 1), vertexOf);
  expectDelaunay(T);
  EXPECT_EQ(T.liveTriangles(), 2 * 3000 + 2); // 2n + 2 for n points inside a 4-corner box
  for (int v : vertexOf)
    EXPECT_GE(v, 0);
  // A grid is full of cocircular quadruples: the exact incircle must cope.
  Array<Point> grid;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j)
      grid.push_back({ i * 0.1, j * 0.1 });
  T = delaunayTriangulation(grid, vertexOf);
  expectDelaunay(T);
  EXPECT_EQ(T.liveTriangles(), 2 * 1600 + 2);
}

TEST(Triangulation, HilbertOrderIsAPermutation)
{
  const Array<Point> pts = randomPoints(1000, 2);
  Array<int> order = hilbertOrder(pts);
  EXPECT_EQ(std::set<int>(order.begin(), order.end()).size(), pts.size());
  // Consecutive points are close on average: far less than random pairs (~0.52).
  double total = 0;
  for (std::size_t i = 1; i < order.size(); ++i)
    total += std::sqrt(dist2(pts[order[i]], pts[order[i - 1]]));
  EXPECT_LT(total / (order.size() - 1), 0.1);
}

TEST(Triangulation, HilbertOrderIsACurveAndKeepsTiesInInputOrder)
{
  // A 256 x 256 grid on every 256th cell of the 2^16 grid (the corner point
  // makes the bounds exactly 65535): a Hilbert curve steps to a neighbour.
  Array<Point> pts;
  for (int i = 0; i < 256; ++i)
    for (int j = 0; j < 256; ++j)
      pts.push_back({ 256.0 * i, 256.0 * j });
  pts.push_back({ 65535, 65535 });
  const Array<int> order = hilbertOrder(pts);
  ASSERT_EQ(order.size(), pts.size());
  std::vector<int> grid; // the order without the corner point
  for (int i : order)
    if (i != 65536)
      grid.push_back(i);
  ASSERT_EQ(grid.size(), 65536u);
  EXPECT_EQ(pts[grid.front()], (Point{ 0, 0 }));
  EXPECT_EQ(pts[grid.back()], (Point{ 65280, 0 })); // the curve ends at the other bottom corner
  int steps = 0;
  for (std::size_t k = 1; k < grid.size(); ++k)
  {
    const Point &a = pts[grid[k - 1]], &b = pts[grid[k]];
    steps += std::fabs(a.x - b.x) + std::fabs(a.y - b.y) == 256.0;
  }
  EXPECT_EQ(steps, 65535);
  // Equal points (one cell) stay in input order, whatever the number of points
  // (the radix sort changes its digit size at 65,536).
  for (std::size_t n : { std::size_t(10), std::size_t(70000) })
  {
    Array<Point> same(n, Point{ 0.5, 0.5 });
    same.push_back({ 0, 0 });
    same.push_back({ 1, 1 });
    const Array<int> o = hilbertOrder(same);
    EXPECT_EQ(o.front(), static_cast<int>(n));
    for (std::size_t k = 1; k < n; ++k)
      ASSERT_LT(o[k], o[k + 1]) << n;
  }
}

TEST(Overlay, IsADelaunayQualityMeshOfThePoints)
{
  for (const bool offCenters : { true, false })
    for (double angle : { 20.0, 25.0, 30.0, 33.0 })
    {
      SCOPED_TRACE(std::to_string(angle) + (offCenters ? " off-centers" : " circumcenters"));
      RunContext run(nullptr);
      OverlayOptions o;
      o.gamma = gammaForMinAngle(angle);
      o.offCenters = offCenters;
      const Array<Point> pts = randomPoints(500, 3);
      const Overlay ov = buildOverlay(pts, o, run);
      expectDelaunay(ov.mesh);
      for (std::size_t i = 0; i < pts.size(); ++i)
      {
        ASSERT_GE(ov.inputVertex[i], 0);
        EXPECT_EQ(ov.mesh.points[ov.inputVertex[i]], pts[i]);
        EXPECT_TRUE(ov.isInput[ov.inputVertex[i]]);
      }
      for (int t = 0; t < ov.mesh.slots(); ++t)
        if (ov.mesh.alive(t))
          for (int i = 0; i < 3; ++i)
            EXPECT_GE(angleAt(ov.mesh.vertex(t, (i + 1) % 3), ov.mesh.vertex(t, i),
                        ov.mesh.vertex(t, (i + 2) % 3)) *
                180 / std::acos(-1.0),
              angle - 1e-9);
      EXPECT_EQ(ov.refinementsSkipped, 0u);
    }
}

TEST(Overlay, OffCentersNeedFewerSteinerPoints)
{
  // The off-center lands nearer the short edge that made a triangle poor, so
  // fewer points reach the same quality (about 10% on real inputs).
  for (unsigned seed : { 3u, 4u, 5u })
  {
    const Array<Point> pts = randomPoints(2000, seed);
    std::size_t steiner[2];
    for (const bool offCenters : { false, true })
    {
      RunContext run(nullptr);
      OverlayOptions o;
      o.offCenters = offCenters;
      steiner[offCenters] = buildOverlay(pts, o, run).steinerPoints;
    }
    EXPECT_LT(steiner[1], steiner[0] * 0.95) << seed;
  }
}

TEST(Overlay, GradesToTinyFeatures)
{
  // Two points 1e-8 apart in a unit square: size grows only logarithmically.
  Array<Point> pts{ { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 }, { 0.5, 0.5 }, { 0.5 + 1e-8, 0.5 } };
  RunContext run(nullptr);
  const Overlay ov = buildOverlay(pts, {}, run);
  expectDelaunay(ov.mesh);
  EXPECT_LT(ov.mesh.points.size(), 3000u); // a uniform mesh would need ~1e16
}

TEST(Overlay, SteinerCapStops)
{
  RunContext run(nullptr);
  OverlayOptions o;
  o.maxSteinerPoints = 5;
  EXPECT_THROW(buildOverlay(randomPoints(100, 4), o, run), Stop);
}

TEST(Triangulation, LocateGivesUpOnACycleInsteadOfHanging)
{
  // Two triangles whose neighbour links point at each other although they do
  // not touch: the walk towards (3, 3) would bounce between them forever.
  Triangulation T;
  const int a = T.addPoint({ 0, 0 }), b = T.addPoint({ 1, 0 }), c = T.addPoint({ 0, 1 });
  const int d = T.addPoint({ 5, 5 }), e = T.addPoint({ 6, 5 }), f = T.addPoint({ 5, 6 });
  const int t0 = T.newTriangle(a, b, c), t1 = T.newTriangle(d, e, f);
  for (int i = 0; i < 3; ++i)
  {
    T.tri[t0].n[i] = t1;
    T.tri[t1].n[i] = t0;
  }
  EXPECT_EQ(T.locate({ 3, 3 }, t0), -2);
  // On the same triangles a point inside t0 is still found at once.
  EXPECT_EQ(T.locate({ 0.2, 0.2 }, t0), t0);
}

TEST(Triangulation, InsertionPutsTheNewVertexAtIndex2)
{
  // The refinement's queue tells a standing triangle from a stale item by
  // its slot and vertex 2: every triangle an insertion makes must have the
  // new vertex there, and be counter-clockwise. Halfway, the insertion
  // scratch is given back: insertion must work on without it.
  Triangulation T = squareOfSide8();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-3, 3);
  Triangulation::Cavity cavity;
  Array<int> created;
  for (int k = 0; k < 500; ++k)
  {
    if (k == 250)
      T.releaseInsertionScratch();
    const Point p{ U(rng), U(rng) };
    const int start = T.locate(p, anyLiveTriangle(T));
    ASSERT_GE(start, 0);
    if (!T.cavityOf(p, start, cavity))
      continue;
    const int v = T.addPoint(p);
    ASSERT_TRUE(T.insertIntoCavity(v, cavity, created));
    for (std::size_t k = 0; k < created.size(); ++k)
    {
      const int t = created[k], next = created[(k + 1) % created.size()];
      EXPECT_EQ(T.tri[t].v[2], v);
      EXPECT_GT(orient2d(T.vertex(t, 0), T.vertex(t, 1), T.vertex(t, 2)), 0);
      // In counter-clockwise order around v, fans of 3 too (a mutation test).
      EXPECT_EQ(T.tri[t].v[1], T.tri[next].v[0]) << "a fan of " << created.size();
    }
  }
  expectDelaunay(T);
}

TEST(Triangulation, LargeFanIsLinkedAroundTheNewVertexInOrder)
{
  // The centre of a circle of points has them all in its cavity: a fan far
  // larger than refinement makes.
  Triangulation T = squareOfSide8();
  Triangulation::Cavity cavity;
  Array<int> created;
  auto insert = [&](const Point& p) {
    const int start = T.locate(p, anyLiveTriangle(T));
    EXPECT_GE(start, 0);
    EXPECT_TRUE(T.cavityOf(p, start, cavity));
    const int v = T.addPoint(p);
    EXPECT_TRUE(T.insertIntoCavity(v, cavity, created));
    return v;
  };
  const int n = 64;
  const double pi = std::acos(-1.0);
  for (int k = 0; k < n; ++k)
    insert({ std::cos(2 * pi * k / n), std::sin(2 * pi * k / n) });
  const int v = insert({ 0.01, 0.02 });
  ASSERT_GE(created.size(), std::size_t(n));
  for (std::size_t k = 0; k < created.size(); ++k)
  {
    const int t = created[k], next = created[(k + 1) % created.size()];
    EXPECT_EQ(T.tri[t].v[2], v);
    // Counter-clockwise around v: each triangle's successor is across its
    // edge (b, v), and faces back across the successor's edge (v, b).
    EXPECT_EQ(T.tri[t].n[0], next) << "fan position " << k;
    EXPECT_EQ(T.tri[next].n[1], t) << "fan position " << k;
    EXPECT_EQ(T.tri[t].v[1], T.tri[next].v[0]);
  }
  expectDelaunay(T);
}

TEST(Triangulation, AFanOnTheHullIsInCounterClockwiseOrderToo)
{
  // A point on a hull edge: the fan around it is open, of 3 triangles here,
  // and the order is not the cavity boundary's (a mutation test: left
  // unsorted below 4 triangles, it came reversed).
  Triangulation T;
  for (const Point& p : { Point{ 0, 0 }, Point{ 2, 0 }, Point{ 0, 2 }, Point{ 2, 2 } })
    T.addPoint(p);
  const int t0 = T.newTriangle(0, 1, 2), t1 = T.newTriangle(1, 3, 2);
  T.link(t0, t1);
  const int v = T.addPoint({ 1, 0 });
  Triangulation::Cavity cavity;
  Array<int> created;
  ASSERT_TRUE(T.cavityOf(T.points[v], T.locate(T.points[v], t0), cavity));
  ASSERT_TRUE(T.insertIntoCavity(v, cavity, created));
  ASSERT_EQ(created.size(), 3u);
  for (std::size_t k = 0; k + 1 < created.size(); ++k)
    EXPECT_EQ(T.tri[created[k]].v[1], T.tri[created[k + 1]].v[0]) << "fan position " << k;
  for (int t : created)
    EXPECT_GT(orient2d(T.vertex(t, 0), T.vertex(t, 1), T.vertex(t, 2)), 0);
}

TEST(Triangulation, ACavityIsRefusedAtAVertexOfItsStart)
{
  // Two triangles over [-4, 4]^2 (squareOfSide8()). At (4, -4), a hull corner
  // with a single triangle, insertion alone would not refuse the copy: it
  // would replace that triangle by one around a second vertex there (a
  // mutation test).
  Triangulation T;
  const int c0 = T.addPoint({ -4, -4 }), c1 = T.addPoint({ 4, -4 });
  const int c2 = T.addPoint({ 4, 4 }), c3 = T.addPoint({ -4, 4 });
  const int t0 = T.newTriangle(c0, c1, c2);
  T.link(t0, T.newTriangle(c0, c2, c3));
  Triangulation::Cavity cavity;
  for (const Point& p : T.points)
    EXPECT_FALSE(T.cavityOf(p, T.locate(p, t0), cavity)) << p.x << ", " << p.y;
}

TEST(Triangulation, AnOpenFanAfterALargeFanIsLinkedOnlyToItsOwnNeighbours)
{
  // Two fans of more than 16 triangles, linked through the per-vertex
  // scratch: first a closed one around the centre of 20 points on a circle,
  // one of them A; then an open one around O, on the hull edge AB of a half
  // circle (touching the first only at A), whose last triangle ends at A. A
  // scratch entry left over for A would link that triangle across the hull
  // edge (A, O) (a mutation test).
  const double pi = std::acos(-1.0);
  Triangulation T;
  const int A = T.addPoint({ -2, 0 }), B = T.addPoint({ 2, 0 });
  const int n = 20; // half circle of radius 2 around O: A, B, Q1..Qn counter-clockwise
  int q = T.addPoint({ 2 * std::cos(pi / (n + 1)), 2 * std::sin(pi / (n + 1)) });
  const int half = T.newTriangle(A, B, q);
  for (int k = 2, prev = half; k <= n; ++k)
  {
    const int next = T.addPoint({ 2 * std::cos(pi * k / (n + 1)), 2 * std::sin(pi * k / (n + 1)) });
    const int t = T.newTriangle(A, q, next);
    T.link(prev, t);
    prev = t, q = next;
  }
  const int m = 20; // circle of radius 1 around (-3, 0), through A
  int p = T.addPoint({ -3 + std::cos(2 * pi / m), std::sin(2 * pi / m) });
  int circle = -1;
  for (int k = 2, prev = -1; k < m; ++k)
  {
    const int next = T.addPoint({ -3 + std::cos(2 * pi * k / m), std::sin(2 * pi * k / m) });
    const int t = T.newTriangle(A, p, next);
    if (prev >= 0)
      T.link(prev, t);
    else
      circle = t;
    prev = t, p = next;
  }
  Triangulation::Cavity cavity;
  Array<int> created;
  const auto insert = [&](const Point& x, int from) {
    const int start = T.locate(x, from);
    ASSERT_GE(start, 0);
    ASSERT_TRUE(T.cavityOf(x, start, cavity));
    ASSERT_TRUE(T.insertIntoCavity(T.addPoint(x), cavity, created));
  };
  insert({ -3, 0 }, circle);
  ASSERT_EQ(created.size(), std::size_t(m));
  insert({ 0, 0 }, half);
  ASSERT_EQ(created.size(), std::size_t(n + 1));
  EXPECT_EQ(T.tri[created.front()].n[1], -1); // across (O, B): the hull
  EXPECT_EQ(T.tri[created.back()].v[1], A);
  EXPECT_EQ(T.tri[created.back()].n[0], -1); // across (A, O): the hull
  // Every link is across a shared edge and returned.
  for (int t = 0; t < T.slots(); ++t)
    for (int i = 0; T.alive(t) && i < 3; ++i)
      if (const int u = T.tri[t].n[i]; u >= 0)
      {
        EXPECT_GE(T.localIndex(u, T.tri[t].v[(i + 1) % 3]), 0) << "triangle " << t << " edge " << i;
        EXPECT_GE(T.localIndex(u, T.tri[t].v[(i + 2) % 3]), 0) << "triangle " << t << " edge " << i;
        EXPECT_TRUE(T.tri[u].n[0] == t || T.tri[u].n[1] == t || T.tri[u].n[2] == t);
      }
}
