// Phase 2 in isolation: every crossing's good/bad class and every overlay
// edge's kept/discarded fate follow the paper's rules, recomputed here.
#include "Overlay.h"
#include "Predicates.h"
#include "Stitch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>

using namespace osm;

namespace
{

const double kPi = std::acos(-1.0);

/// Acute angle between the lines of two vectors, in degrees.
double lineAngle(double ax, double ay, double bx, double by)
{
  const double a = std::fabs(std::atan2(ax * by - ay * bx, ax * bx + ay * by)) * 180 / kPi;
  return a > 90 ? 180 - a : a;
}

struct Stitched
{
  Overlay overlay;
  OverlayEdges ov;
  Walk walk;
  Array<Segment> segments; ///< as overlay vertices
};

Stitched stitchInput(const Array<Point>& pts, const Array<Segment>& segs, double theta)
{
  Stitched s;
  RunContext run(nullptr);
  OverlayOptions o;
  o.gamma = gammaForMinAngle(theta);
  s.overlay = buildOverlay(pts, o, run);
  s.ov = compactOverlay(s.overlay.mesh);
  for (const Segment& g : segs)
    s.segments.push_back({ s.overlay.inputVertex[g[0]], s.overlay.inputVertex[g[1]] });
  s.walk = walkSegments(s.ov, s.overlay, s.segments, std::sin(theta * kPi / 180), run);
  return s;
}

/// count long random segments in the unit square, stitched at 30 degrees:
/// many of them cross.
Stitched randomLongSegments(unsigned seed, int count)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  Array<Point> pts;
  Array<Segment> segs;
  for (int i = 0; i < count; ++i)
  {
    pts.push_back({ U(rng), U(rng) });
    pts.push_back({ U(rng), U(rng) });
    segs.push_back({ 2 * i, 2 * i + 1 });
  }
  return stitchInput(pts, segs, 30);
}

/// The same crossing pairs, each at the same point.
void expectSameSegmentCrossings(const Walk& w, const Walk& ref)
{
  ASSERT_EQ(w.segmentCrossings.size(), ref.segmentCrossings.size());
  for (std::size_t k = 0; k < ref.segmentCrossings.size(); ++k)
  {
    const SegmentCrossing &x = w.segmentCrossings[k], &y = ref.segmentCrossings[k];
    EXPECT_TRUE(x.a == y.a && x.b == y.b && x.p == y.p) << "crossing " << k;
  }
}

} // namespace

TEST(Stitch, EdgeIdsNameEveryOverlayEdgeOnce)
{
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0, 1);
  Array<Point> pts;
  for (int i = 0; i < 300; ++i)
    pts.push_back({ U(rng), U(rng) });
  const Stitched s = stitchInput(pts, {}, 30);
  const OverlayEdges& ov = s.ov;
  std::set<std::pair<int, int>> distinct;
  for (int c = 0; c < static_cast<int>(ov.tris.size()); ++c)
    for (int i = 0; i < 3; ++i)
    {
      const int a = ov.tris[c][(i + 1) % 3], b = ov.tris[c][(i + 2) % 3];
      distinct.insert({ std::min(a, b), std::max(a, b) });
      // Both triangles of an edge give the same id, which names the edge.
      const int id = ov.edgeId(c, i);
      ASSERT_TRUE(ov.isEdge(id)) << c << " " << i;
      const Segment e = ov.ends(id);
      EXPECT_EQ(std::minmax(e[0], e[1]), std::minmax(a, b));
      const int u = ov.nbr[c][i];
      EXPECT_EQ(id / 3, u < 0 ? c : std::min(c, u));
      // The twin is u's half-edge back to c.
      const int twin = ov.twin(c, i);
      if (u < 0)
        EXPECT_EQ(twin, -1);
      else
      {
        EXPECT_EQ(twin / 3, u);
        EXPECT_EQ(ov.nbr[u][twin % 3], c);
      }
    }
  std::size_t ids = 0;
  for (int h = 0; h < static_cast<int>(ov.idBound()); ++h)
    ids += ov.isEdge(h);
  EXPECT_EQ(ids, distinct.size());
}

TEST(Stitch, CrossingsAreClassifiedAtTheta1)
{
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(0, 1);
  const double theta = 30;
  std::size_t good = 0, bad = 0;
  for (int trial = 0; trial < 20; ++trial)
  {
    // A fan of near-parallel segments from one corner plus scattered points.
    Array<Point> pts{ { 0, 0 } };
    Array<Segment> segs;
    for (int i = 1; i <= 4; ++i)
    {
      const double a = (0.2 + 0.01 * i + 0.3 * U(rng)) * kPi / 2;
      pts.push_back({ std::cos(a), std::sin(a) });
      segs.push_back({ 0, i });
    }
    const Stitched s = stitchInput(pts, segs, theta);
    ASSERT_TRUE(s.walk.segmentCrossings.empty());
    for (const Crossing& c : s.walk.crossings)
    {
      const Piece& piece = s.walk.pieces[c.piece];
      const Point& a = s.overlay.mesh.points[s.segments[piece.segment][0]];
      const Point& b = s.overlay.mesh.points[s.segments[piece.segment][1]];
      const Point& p = s.overlay.mesh.points[s.ov.ends(c.edge)[0]];
      const Point& q = s.overlay.mesh.points[s.ov.ends(c.edge)[1]];
      // The crossing is real: the edge's ends lie strictly on either side.
      EXPECT_LT(orientSign(a, b, p) * orientSign(a, b, q), 0);
      const double angle = lineAngle(b.x - a.x, b.y - a.y, q.x - p.x, q.y - p.y);
      EXPECT_EQ(c.good, angle > theta) << "angle " << angle;
      ++(c.good ? good : bad);
      // The stitch point lies on the edge, within rounding.
      EXPECT_GE(c.s, 0.0);
      EXPECT_LE(c.s, 1.0);
    }
  }
  EXPECT_GT(good, 0u);
  EXPECT_GT(bad, 0u); // the fan's near-parallel crossings
}

TEST(Stitch, ACrossingExactlyAtTheta1IsNotGood)
{
  // A good crossing is one above θ1, strictly (a mutation test: at θ1 itself
  // no test looked). A segment across a vertical overlay edge at right
  // angles, with sin θ1 = 1 exactly: the sine is 1, not above it.
  const Array<Point> pts{ { 0, 1 }, { 2, 1 }, { 1, 0 }, { 1, 1.8 } };
  RunContext run(nullptr);
  OverlayOptions o;
  o.gamma = gammaForMinAngle(30);
  Overlay overlay = buildOverlay(pts, o, run);
  const OverlayEdges ov = compactOverlay(overlay.mesh);
  const Array<Segment> segments{ { overlay.inputVertex[0], overlay.inputVertex[1] } };
  const Walk right = walkSegments(ov, overlay, segments, 1.0, run);
  std::size_t vertical = 0;
  for (const Crossing& c : right.crossings)
  {
    const Point& p = overlay.mesh.points[ov.ends(c.edge)[0]];
    const Point& q = overlay.mesh.points[ov.ends(c.edge)[1]];
    if (p.x == 1 && q.x == 1)
    {
      ++vertical;
      EXPECT_FALSE(c.good) << "a crossing at exactly θ1 = 90 degrees";
    }
  }
  EXPECT_EQ(vertical, 1u);
  // Just below, it is good.
  const Walk below = walkSegments(ov, overlay, segments, std::nextafter(1.0, 0.0), run);
  for (const Crossing& c : below.crossings)
    if (overlay.mesh.points[ov.ends(c.edge)[0]].x == 1 &&
      overlay.mesh.points[ov.ends(c.edge)[1]].x == 1)
      EXPECT_TRUE(c.good);
}

TEST(Stitch, EdgesAreKeptOrDiscardedByTheirCrossings)
{
  Array<Point> pts{ { 0, 0 }, { 1, 0.02 }, { 0, 0.05 }, { 1, 0.08 }, { 0.3, 0.9 } };
  Array<Segment> segs{ { 0, 1 }, { 2, 3 }, { 0, 4 } };
  Stitched s = stitchInput(pts, segs, 30);
  std::vector<int> crossings(s.ov.idBound(), 0), goods(s.ov.idBound(), 0);
  for (const Crossing& c : s.walk.crossings)
  {
    ++crossings[c.edge];
    goods[c.edge] += c.good;
  }
  Array<Edge> edges;
  Statistics stats;
  const PlanarGraph g =
    stitch(s.ov, s.overlay.mesh.points, s.overlay.isInput, s.walk, &edges, stats);
  std::size_t discarded = 0, k = 0; // edges[k] is the overlay edge with the k-th id
  for (int e = 0; e < static_cast<int>(s.ov.idBound()); ++e)
  {
    if (!s.ov.isEdge(e))
      continue;
    ASSERT_LT(k, edges.size());
    EXPECT_EQ(edges[k].a, s.ov.ends(e)[0]);
    EXPECT_EQ(edges[k].b, s.ov.ends(e)[1]);
    const bool expectKept = crossings[e] == 0 || goods[e] > 0;
    EXPECT_EQ(bool(edges[k].flags & EdgeKept), expectKept) << "edge " << e;
    EXPECT_EQ(bool(edges[k].flags & EdgeDiscarded), !expectKept) << "edge " << e;
    discarded += !expectKept;
    ++k;
  }
  EXPECT_EQ(stats.discardedEdges, discarded);
  EXPECT_GT(discarded, 0u); // the two long near-horizontal segments
  // One stitch vertex per crossing on a kept edge.
  std::size_t onKept = 0;
  for (const Crossing& c : s.walk.crossings)
    onKept += crossings[c.edge] > 0 && goods[c.edge] > 0;
  EXPECT_EQ(stats.stitchVertices, onKept);
  EXPECT_EQ(g.points.size(), s.overlay.mesh.points.size() + onKept);
}

TEST(Stitch, IntactTrianglesAreTheUncrossedOnesAndOpenSidesFaceTheRest)
{
  Array<Point> pts{ { 0, 0 }, { 1, 0.02 }, { 0, 0.05 }, { 1, 0.08 }, { 0.3, 0.9 }, { 0.7, 0.6 },
    { 0.2, 0.4 } };
  Array<Segment> segs{ { 0, 1 }, { 2, 3 }, { 0, 4 }, { 4, 5 } };
  Stitched s = stitchInput(pts, segs, 30);
  std::vector<char> crossed(s.ov.idBound(), 0);
  for (const Crossing& c : s.walk.crossings)
    crossed[c.edge] = 1;
  Statistics stats;
  const PlanarGraph g =
    stitch(s.ov, s.overlay.mesh.points, s.overlay.isInput, s.walk, nullptr, stats);
  ASSERT_EQ(g.openSides.size(), g.edges.size());
  // The sides of each overlay edge (as a directed vertex pair) that a crossed triangle lies on.
  std::map<std::pair<int, int>, int> expectedOpen;
  std::size_t intact = 0;
  for (std::size_t c = 0; c < s.ov.tris.size(); ++c)
  {
    const Triangle& t = s.ov.tris[c];
    bool anyCrossed = false;
    for (int i = 0; i < 3; ++i)
      anyCrossed |= crossed[s.ov.edgeId(static_cast<int>(c), i)] != 0;
    if (!anyCrossed)
    {
      ++intact;
      EXPECT_NE(std::find(g.intact.begin(), g.intact.end(), t), g.intact.end()) << "triangle " << c;
      continue;
    }
    for (int i = 0; i < 3; ++i) // t lies left of t[i+1] -> t[i+2]
      expectedOpen[{ t[(i + 1) % 3], t[(i + 2) % 3] }] = 1;
  }
  EXPECT_EQ(g.intact.size(), intact);
  EXPECT_GT(intact, 0u);
  EXPECT_LT(intact, s.ov.tris.size());
  // Every uncrossed overlay edge in the graph is open exactly on its crossed triangles' sides.
  std::size_t checked = 0;
  for (std::size_t e = 0; e < g.edges.size(); ++e)
  {
    const int a = g.edges[e][0], b = g.edges[e][1];
    const bool overlayEdge = a < static_cast<int>(s.overlay.mesh.points.size()) &&
      b < static_cast<int>(s.overlay.mesh.points.size());
    if (!overlayEdge)
    {
      EXPECT_EQ(g.openSides[e], OpenBoth) << "edge " << e << " through stitch vertices";
      continue;
    }
    const int left = expectedOpen.count({ a, b }) ? OpenLeft : 0;
    const int right = expectedOpen.count({ b, a }) ? OpenRight : 0;
    if (left | right)
    {
      EXPECT_EQ(g.openSides[e], left | right) << "edge " << e;
      ++checked;
    }
    else
      EXPECT_TRUE(g.constrained[e]) << "edge " << e << " between intact triangles";
  }
  EXPECT_GT(checked, 0u);
}

TEST(Stitch, WalksFollowTheSegmentInOrder)
{
  Array<Point> pts{ { 0, 0 }, { 1, 1 }, { 0.5, 0.1 }, { 0.2, 0.7 } };
  const Stitched s = stitchInput(pts, { { 0, 1 } }, 30);
  const Point &a = pts[0], &b = pts[1];
  double last = -1;
  for (const Crossing& c : s.walk.crossings)
  {
    const double t = ((c.p.x - a.x) * (b.x - a.x) + (c.p.y - a.y) * (b.y - a.y)) / 2.0;
    EXPECT_GT(t, last); // crossings are listed from a to b
    last = t;
  }
  ASSERT_FALSE(s.walk.pieces.empty());
  EXPECT_EQ(s.walk.pieces.front().v0, s.overlay.inputVertex[0]);
  EXPECT_EQ(s.walk.pieces.back().v1, s.overlay.inputVertex[1]);
}

TEST(Stitch, MoreCrossingsThanMemoryCouldMeshAreRefusedWithOne)
{
  // 12 horizontal and 12 vertical segments: 144 pairs cross. A streamline
  // circling a limit cycle crossed itself so often that the list of pairs
  // outgrew memory (a review); the walks stop at a quarter of the points the
  // memory holds in a mesh (memory / 1,200 bytes).
  Array<Point> pts;
  Array<Segment> segs;
  for (int i = 0; i < 12; ++i)
  {
    const double c = i + 0.5;
    const int first = static_cast<int>(pts.size());
    pts.insert(pts.end(), { { 0, c }, { 12, c }, { c, 0 }, { c, 12 } });
    segs.insert(segs.end(), { { first, first + 1 }, { first + 2, first + 3 } });
  }
  Stitched s = stitchInput(pts, segs, 30);
  ASSERT_EQ(s.walk.segmentCrossings.size(), 144u);
  RunContext run(nullptr);
  const double sinTheta1 = std::sin(30 * kPi / 180);
  const auto walkWith = [&](double memory) {
    return walkSegments(s.ov, s.overlay, s.segments, sinTheta1, run, nullptr, nullptr, {}, memory);
  };
  EXPECT_EQ(walkWith(144 * 1200).segmentCrossings.size(), 144u);
  try
  {
    walkWith(143 * 1200);
    FAIL() << "144 pairs crossed where 143 may";
  }
  catch (const Stop& stop)
  {
    EXPECT_EQ(stop.reason, "the input segments cross each other more than 143 times, e.g.");
    EXPECT_EQ(stop.tail.rfind(": a quarter of the points this machine's memory", 0), 0u)
      << stop.tail;
    EXPECT_NE(stop.tail.find("a streamline circling a limit cycle"), std::string::npos);
    EXPECT_TRUE(stop.located);
    ASSERT_GE(stop.segments[0], 0);
    ASSERT_GE(stop.segments[1], 0);
    const Array<Point>& P = s.overlay.mesh.points;
    const Segment &a = s.segments[stop.segments[0]], &b = s.segments[stop.segments[1]];
    EXPECT_LT(orientSign(P[a[0]], P[a[1]], P[b[0]]) * orientSign(P[a[0]], P[a[1]], P[b[1]]), 0);
    EXPECT_LT(orientSign(P[b[0]], P[b[1]], P[a[0]]) * orientSign(P[b[0]], P[b[1]], P[a[1]]), 0);
  }
  // The crossings of overlay edges: at most as many as the memory holds
  // points in a mesh (memory / 300 bytes); one more ends the walk there.
  const std::size_t n = s.walk.crossings.size();
  ASSERT_LT(n, 144u * 4);
  const std::string walkCap =
    "the segments cross more than " + std::to_string(n - 1) + " edges of the overlay";
  for (const std::size_t held : { n - 1, n })
    try
    {
      walkWith(300.0 * double(held));
      FAIL() << "no error with " << held;
    }
    catch (const Stop& stop)
    {
      // With n, the pairs' quarter of it is too few.
      EXPECT_EQ(
        stop.reason.rfind(held < n ? walkCap : "the input segments cross each other", 0), 0u)
        << stop.reason;
      EXPECT_EQ(
        stop.tail.rfind(held < n ? ": as many as this machine's memory" : ": a quarter", 0), 0u)
        << stop.tail;
      EXPECT_TRUE(stop.located);
      EXPECT_GE(stop.segments[0], 0);
    }
}

TEST(Stitch, CrossingsReducedOnTheWayKeepTheSamePointPerPair)
{
  // The records of crossing pairs are reduced whenever they grow by the cap:
  // the pairs and the point kept for each must not depend on when.
  Stitched s = randomLongSegments(5, 120);
  RunContext run(nullptr);
  const double sinTheta1 = std::sin(30 * kPi / 180);
  const Walk ref =
    walkSegments(s.ov, s.overlay, s.segments, sinTheta1, run, nullptr, nullptr, {}, 0);
  const std::size_t pairs = ref.segmentCrossings.size();
  ASSERT_GT(pairs, 1000u);
  // Memory for as many pairs as cross (1,200 bytes each), and 4 times as
  // many crossings of overlay edges, which is enough.
  ASSERT_LE(ref.crossings.size(), 4 * pairs);
  const Walk w = walkSegments(
    s.ov, s.overlay, s.segments, sinTheta1, run, nullptr, nullptr, {}, 1200.0 * double(pairs));
  EXPECT_EQ(ref.segmentCrossingsReduced, 0u);
  EXPECT_GE(w.segmentCrossingsReduced, 1u);
  expectSameSegmentCrossings(w, ref);
}

TEST(Stitch, TheMachinesMemoryIsAskedOnlyBeyondTheUncheckedCrossings)
{
  // By default the limits start from the memory of
  // kPointsUncheckedAgainstMemory points, and this machine's is asked when
  // the crossings outgrow them: a walk beyond them goes on, and finds what
  // a walk without limits finds.
  Stitched s = randomLongSegments(7, 480);
  if (physicalMemoryBytes() < 1e9)
    GTEST_SKIP() << "this machine's memory: " << physicalMemoryBytes();
  RunContext run(nullptr);
  const double sinTheta1 = std::sin(30 * kPi / 180);
  const Walk none =
    walkSegments(s.ov, s.overlay, s.segments, sinTheta1, run, nullptr, nullptr, {}, 0);
  ASSERT_GT(double(none.segmentCrossings.size()), kPointsUncheckedAgainstMemory / 4);
  const Walk asked = walkSegments(s.ov, s.overlay, s.segments, sinTheta1, run);
  expectSameSegmentCrossings(asked, none);
  EXPECT_EQ(asked.crossings.size(), none.crossings.size());
}

TEST(Stitch, KeepFirstOfEachPairKeepsTheFirstRecordOfEachPair)
{
  // Records of one pair can carry points that differ by rounding (each walk
  // computes its own); the first recorded is kept, whatever the sort does
  // with the others (an unstable sort keeps any of them).
  Array<SegmentCrossing> records;
  for (int k = 0; k < 300; ++k)
    records.push_back({ k % 7, 10 + k % 3, { double(k), 0.0 } });
  keepFirstOfEachPair(records);
  ASSERT_EQ(records.size(), 21u); // 7 × 3 pairs, (k mod 7, k mod 3) all met below 21
  for (std::size_t i = 0; i < records.size(); ++i)
  {
    const SegmentCrossing& r = records[i];
    if (i > 0)
      EXPECT_TRUE(std::make_pair(records[i - 1].a, records[i - 1].b) < std::make_pair(r.a, r.b));
    // The first k with k mod 7 == a and k mod 3 == b - 10: below 21.
    int first = 0;
    while (first % 7 != r.a || first % 3 != r.b - 10)
      ++first;
    EXPECT_EQ(r.p.x, double(first)) << "pair " << r.a << ", " << r.b;
  }
}

/// Segments are walked in spatial order; everything stitching makes from the
/// walks must be what walks in index order would give: the same graph, edge
/// for edge, the same inspected edges and the same segment crossings.
TEST(Stitch, TheStitchedGraphDoesNotDependOnTheWalkOrder)
{
  for (unsigned seed = 1; seed <= 6; ++seed)
  {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0, 1);
    Array<Point> pts;
    Array<Segment> segs;
    for (int i = 0; i < 60; ++i) // long random segments: many cross
    {
      pts.push_back({ U(rng), U(rng) });
      pts.push_back({ U(rng), U(rng) });
      segs.push_back({ 2 * i, 2 * i + 1 });
    }
    // Overlapping collinear segments share pieces (duplicates), and one
    // passes exactly through another's crossing points.
    const int c = static_cast<int>(pts.size());
    for (double x : { 0.125, 0.375, 0.625, 0.875 })
      pts.push_back({ x, 0.5 });
    segs.push_back({ c, c + 2 });
    segs.push_back({ c + 1, c + 3 });
    segs.push_back({ c, c + 3 });
    Stitched s = stitchInput(pts, segs, 30);
    ASSERT_GT(s.walk.segmentCrossings.size(), 20u) << "seed " << seed;
    ASSERT_GT(s.walk.overlaps.size(), 0u) << "seed " << seed;

    const std::size_t m = s.segments.size();
    Array<int> identity(m), reversed(m), shuffled(m);
    for (std::size_t i = 0; i < m; ++i)
      identity[i] = reversed[m - 1 - i] = shuffled[i] = static_cast<int>(i);
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    RunContext run(nullptr);
    const double sinTheta1 = std::sin(30 * kPi / 180);
    Statistics refStats;
    Array<Edge> refEdges;
    const Walk ref = walkSegments(s.ov, s.overlay, s.segments, sinTheta1, run, &identity);
    const PlanarGraph g0 =
      stitch(s.ov, s.overlay.mesh.points, s.overlay.isInput, ref, &refEdges, refStats);
    const std::array<const Array<int>*, 3> orders{ &reversed, &shuffled, nullptr };
    for (const Array<int>* order : orders)
    {
      const Walk w = walkSegments(s.ov, s.overlay, s.segments, sinTheta1, run, order);
      ASSERT_EQ(w.segmentCrossings.size(), ref.segmentCrossings.size()) << "seed " << seed;
      for (std::size_t k = 0; k < w.segmentCrossings.size(); ++k)
      {
        const SegmentCrossing &x = w.segmentCrossings[k], &y = ref.segmentCrossings[k];
        EXPECT_TRUE(x.a == y.a && x.b == y.b && x.p == y.p)
          << "seed " << seed << ", crossing " << k;
      }
      EXPECT_EQ(w.overlaps, ref.overlaps);
      Statistics stats;
      Array<Edge> edges;
      const PlanarGraph g =
        stitch(s.ov, s.overlay.mesh.points, s.overlay.isInput, w, &edges, stats);
      EXPECT_TRUE(g.points == g0.points) << "seed " << seed;
      EXPECT_TRUE(g.origin == g0.origin) << "seed " << seed;
      EXPECT_TRUE(g.intact == g0.intact) << "seed " << seed;
      EXPECT_TRUE(g.intactAdjacency.nbr == g0.intactAdjacency.nbr) << "seed " << seed;
      EXPECT_TRUE(g.edges == g0.edges) << "seed " << seed;
      EXPECT_TRUE(g.constrained == g0.constrained) << "seed " << seed;
      EXPECT_TRUE(g.openSides == g0.openSides) << "seed " << seed;
      ASSERT_EQ(edges.size(), refEdges.size()) << "seed " << seed;
      for (std::size_t k = 0; k < edges.size(); ++k)
        EXPECT_TRUE(edges[k].a == refEdges[k].a && edges[k].b == refEdges[k].b &&
          edges[k].flags == refEdges[k].flags)
          << "seed " << seed << ", edge " << k;
      EXPECT_EQ(stats.goodCrossings, refStats.goodCrossings);
      EXPECT_EQ(stats.badCrossings, refStats.badCrossings);
    }
  }
}

// Where two segments overlap, the overlay edges crossing the shared part are
// crossed once, not once per segment: the statistics count the same crossings
// as for the line cut into pieces that only touch (the same points, so the same
// overlay).
TEST(Stitch, OverlappingSegmentsCountEachCrossingOnce)
{
  const Array<Point> pts{ { 0, 0 }, { 2, 0 }, { 1, 0 }, { 3, 0 }, { 0.3, 0.5 }, { 1.7, -0.4 },
    { 1.2, 0.3 }, { 2.6, 0.45 }, { 0.5, -0.2 }, { 1.5, 0.2 } };
  auto crossingStats = [&](const Array<Segment>& segs) {
    Stitched s = stitchInput(pts, segs, 30);
    Statistics stats;
    Array<Edge> edges;
    stitch(s.ov, s.overlay.mesh.points, s.overlay.isInput, s.walk, &edges, stats);
    return std::array<std::size_t, 3>{ stats.crossings, stats.goodCrossings, stats.badCrossings };
  };
  const auto overlapping = crossingStats({ { 0, 1 }, { 2, 3 } });
  const auto pieces = crossingStats({ { 0, 2 }, { 2, 1 }, { 1, 3 } });
  EXPECT_GT(pieces[0], 0u);
  EXPECT_EQ(overlapping, pieces);
}
