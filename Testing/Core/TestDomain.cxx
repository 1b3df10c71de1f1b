// carveDomain with adjacency known in advance (the mesher passes that of the
// overlay triangles no segment crosses) must carve exactly as without it.
#include "Domain.h"
#include "Predicates.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>

using namespace osm;

namespace
{

/// An n x n grid of unit squares, each cut into two counter-clockwise triangles.
struct Grid
{
  int n = 0;
  Array<Point> points;
  Array<Triangle> tris;

  explicit Grid(int n)
    : n(n)
  {
    for (int y = 0; y <= n; ++y)
      for (int x = 0; x <= n; ++x)
        points.push_back({ double(x), double(y) });
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
      {
        const int a = id(x, y), b = id(x + 1, y), c = id(x + 1, y + 1), d = id(x, y + 1);
        tris.push_back({ a, b, c });
        tris.push_back({ a, c, d });
      }
  }
  int id(int x, int y) const { return y * (n + 1) + x; }
};

/// The boundary of the square [x0, x1] x [y0, y1] as constrained (lo, hi) pairs.
void addLoop(const Grid& g, int x0, int y0, int x1, int y1, Array<Segment>& out)
{
  auto add = [&](int a, int b) { out.push_back({ std::min(a, b), std::max(a, b) }); };
  for (int x = x0; x < x1; ++x)
  {
    add(g.id(x, y0), g.id(x + 1, y0));
    add(g.id(x, y1), g.id(x + 1, y1));
  }
  for (int y = y0; y < y1; ++y)
  {
    add(g.id(x0, y), g.id(x0, y + 1));
    add(g.id(x1, y), g.id(x1, y + 1));
  }
}

/// The true adjacency of the first count triangles, some edges left unknown.
KnownAdjacency knownFor(
  const Array<Triangle>& tris, const Array<Segment>& constrained, int count, std::mt19937& rng)
{
  const unsigned salt = rng() % 4;
  std::map<std::pair<int, int>, std::vector<int>> byEdge;
  auto key = [](int a, int b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  for (int t = 0; t < static_cast<int>(tris.size()); ++t)
    for (int i = 0; i < 3; ++i)
      byEdge[key(tris[t][(i + 1) % 3], tris[t][(i + 2) % 3])].push_back(t);
  std::set<std::pair<int, int>> isConstrained;
  for (const Segment& s : constrained)
    isConstrained.insert(key(s[0], s[1]));
  KnownAdjacency known;
  for (int t = 0; t < count; ++t)
  {
    std::array<int, 3> nbr{};
    std::uint8_t bits = 0;
    for (int i = 0; i < 3; ++i)
    {
      const auto k = key(tris[t][(i + 1) % 3], tris[t][(i + 2) % 3]);
      const std::vector<int>& both = byEdge[k];
      const int other = both.size() < 2 ? -1 : both[0] == t ? both[1] : both[0];
      // Unknown on both sides or neither: an edge is matched only if both sides are.
      const bool unknown = other >= count || (k.first * 7 + k.second * 13 + salt) % 4 == 0;
      nbr[i] = unknown ? KnownAdjacency::kUnknownNeighbour : other;
      bits |= static_cast<std::uint8_t>(isConstrained.count(k) << i);
    }
    known.nbr.push_back(nbr);
    known.constrained.push_back(bits);
  }
  return known;
}

} // namespace

TEST(Domain, KnownAdjacencyCarvesAsMatchingDoes)
{
  const Grid g(12);
  Array<Segment> constrained;
  addLoop(g, 2, 2, 9, 9, constrained);
  addLoop(g, 4, 4, 6, 6, constrained);
  const Array<Point> holes{ { 5.25, 5.5 }, { 30, 30 } };
  std::mt19937 rng(7);
  for (const bool removeExterior : { false, true })
    for (const int count : { 0, 1, 60, 144, 288 })
    {
      const Carving plain = carveDomain(g.points, g.tris, constrained, removeExterior, holes);
      const KnownAdjacency known = knownFor(g.tris, constrained, count, rng);
      const Carving hinted =
        carveDomain(g.points, g.tris, constrained, removeExterior, holes, known);
      EXPECT_EQ(hinted.regionId, plain.regionId) << count << " known, " << removeExterior;
      EXPECT_EQ(hinted.regions, plain.regions);
      EXPECT_EQ(hinted.unusedHoles, plain.unusedHoles);
      EXPECT_EQ(plain.regions, removeExterior ? 1u : 2u); // the ring; the hole removes the core
      EXPECT_EQ(plain.unusedHoles, Array<int>{ 1 });
    }
}

// Up to kHoleSeedsScanned seeds are found by a scan, more by a grid: the
// same seeds plus one far away must carve alike. Seeds on half and whole
// coordinates fall on edges and vertices too, where the first triangle in
// index order decides which region a seed removes.
TEST(Domain, HoleSeedsFoundByScanOrByGridCarveAlike)
{
  const Grid g(12);
  Array<Segment> constrained;
  addLoop(g, 1, 1, 4, 4, constrained);
  addLoop(g, 5, 1, 8, 4, constrained);
  addLoop(g, 1, 5, 4, 8, constrained);
  addLoop(g, 5, 5, 11, 11, constrained);
  addLoop(g, 7, 7, 9, 9, constrained);
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> halfSteps(-2, 26);
  for (int trial = 0; trial < 200; ++trial)
  {
    Array<Point> seeds;
    while (seeds.size() < kHoleSeedsScanned)
      seeds.push_back({ 0.5 * halfSteps(rng), 0.5 * halfSteps(rng) });
    Array<Point> more = seeds;
    more.push_back({ 100, 100 });
    for (const bool removeExterior : { false, true })
    {
      const Carving scanned = carveDomain(g.points, g.tris, constrained, removeExterior, seeds);
      const Carving gridded = carveDomain(g.points, g.tris, constrained, removeExterior, more);
      EXPECT_EQ(gridded.regionId, scanned.regionId) << "trial " << trial;
      EXPECT_EQ(gridded.regions, scanned.regions);
      Array<int> unused = scanned.unusedHoles;
      unused.push_back(static_cast<int>(kHoleSeedsScanned));
      EXPECT_EQ(gridded.unusedHoles, unused);
    }
  }
}

TEST(Domain, KnownAdjacencyIsUsed)
{
  // Known adjacency is trusted, not rechecked: a corner triangle declared
  // without neighbours is a region of its own, which matching would not give.
  const Grid g(4);
  EXPECT_EQ(carveDomain(g.points, g.tris, {}, false, {}).regions, 1u);
  KnownAdjacency known;
  known.nbr = { { -1, -1, -1 } };
  known.constrained = { 0 };
  const Carving split = carveDomain(g.points, g.tris, {}, false, {}, known);
  EXPECT_EQ(split.regions, 2u);
  EXPECT_NE(split.regionId[0], split.regionId[1]);
}

namespace
{

/// Gift wrapping, independent of convexHull: the strictly convex hull vertices
/// counter-clockwise from the smallest point (x, then y).
Array<int> giftWrap(const Array<Point>& P)
{
  const int n = static_cast<int>(P.size());
  const int first = static_cast<int>(std::min_element(P.begin(), P.end()) - P.begin());
  Array<int> hull;
  int p = first;
  do
  {
    hull.push_back(p);
    int q = p == 0 ? 1 : 0;
    for (int r = 0; r < n; ++r)
    {
      if (P[r] == P[p])
        continue;
      const double o = orient2d(P[p], P[q], P[r]);
      // r right of p->q, or on it and farther: r replaces q.
      if (P[q] == P[p] || o < 0 || (o == 0 && dist2(P[p], P[r]) > dist2(P[p], P[q])))
        q = r;
    }
    p = q;
  } while (p != first && hull.size() <= P.size());
  return hull;
}

} // namespace

TEST(Domain, ConvexHullMatchesGiftWrapping)
{
  std::mt19937 rng(11);
  for (int trial = 0; trial < 200; ++trial)
  {
    // Points on a small grid (many collinear and duplicate ones) or in a disc.
    const int n = 3 + static_cast<int>(rng() % 200);
    const bool grid = trial % 2 == 0;
    Array<Point> P;
    std::uniform_real_distribution<double> U(-1, 1);
    while (static_cast<int>(P.size()) < n)
    {
      const Point q =
        grid ? Point{ double(rng() % 7), double(rng() % 5) } : Point{ U(rng), U(rng) };
      if (grid || q.x * q.x + q.y * q.y <= 1)
        P.push_back(q);
    }
    const Array<int> hull = convexHull(P);
    const Array<int> reference = giftWrap(P);
    ASSERT_EQ(hull.size(), reference.size()) << "trial " << trial;
    for (std::size_t k = 0; k < hull.size(); ++k)
      EXPECT_EQ(P[hull[k]], P[reference[k]]) << "trial " << trial << ", vertex " << k;
  }
}

TEST(Domain, ConvexHullOfFewPoints)
{
  // Fewer than 3 points are returned as they are (sorted); none gives none.
  EXPECT_TRUE(convexHull({}).empty());
  EXPECT_EQ(convexHull({ { 2, 3 } }), (Array<int>{ 0 }));
  EXPECT_EQ(convexHull({ { 1, 0 }, { 0, 0 } }), (Array<int>{ 1, 0 }));
  // A point extreme in every direction but the others' (a right triangle's corner).
  EXPECT_EQ(convexHull({ { 0, 0 }, { 1, 0 }, { 0, 1 }, { 0.2, 0.2 } }).size(), 3u);
}
