// Values at the mesh's vertices from the input points' (Interpolation.h):
// weights that are convex combinations, input vertices that keep their own
// value, points on segments that take the value along their segment, and
// linear fields reproduced everywhere within the known points' hull.
#include "Clean.h"
#include "Interpolation.h"
#include "MeshTestUtils.h"

#include <algorithm>
#include <cmath>
#include <random>

using namespace osm;

namespace
{

double linear(const Point& p)
{
  return 2.0 * p.x - 3.0 * p.y + 1.0;
}

/// The mesh, with the segment of each vertex found on one.
Result meshed(const Pslg& in, Options o = {})
{
  o.keepVertexSegments = true;
  return mesh(in, o);
}

/// Every vertex's terms, by vertex; each vertex must be visited once.
std::vector<VertexTerms> termsOf(const Pslg& in, const Result& r, const std::string& name)
{
  std::vector<VertexTerms> all(r.mesh.vertices.size());
  std::vector<char> seen(all.size(), 0);
  EXPECT_TRUE(r.vertexSegment.size() == r.mesh.vertices.size()) << name;
  EXPECT_TRUE(visitInputWeights(in, r, [&](const VertexTerms& t) {
    EXPECT_LT(t.vertex, all.size()) << name;
    if (t.vertex < all.size())
    {
      EXPECT_FALSE(seen[t.vertex]) << name << ": vertex " << t.vertex << " visited twice";
      seen[t.vertex] = 1;
      all[t.vertex] = t;
    }
    return true;
  }));
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(all.size())) << name;
  // Each has terms: distinct input points, weights in (0, 1] summing to 1.
  for (const VertexTerms& t : all)
  {
    EXPECT_GE(t.count, 1) << name << ": vertex " << t.vertex << " has no terms";
    double sum = 0;
    for (int k = 0; k < t.count; ++k)
    {
      EXPECT_GE(t.point[k], 0) << name;
      EXPECT_LT(t.point[k], static_cast<int>(in.points.size())) << name;
      EXPECT_GT(t.weight[k], 0.0) << name;
      sum += t.weight[k];
      for (int j = 0; j < k; ++j)
        EXPECT_NE(t.point[j], t.point[k]) << name << ": vertex " << t.vertex;
    }
    EXPECT_NEAR(sum, 1.0, 1e-12) << name << ": vertex " << t.vertex;
  }
  return all;
}

/// Σ w f(input point) over the terms of a vertex.
template <typename F>
double valueAt(const VertexTerms& t, const Pslg& in, F f)
{
  double sum = 0;
  for (int k = 0; k < t.count; ++k)
    sum += t.weight[k] * f(in.points[t.point[k]]);
  return sum;
}

/// Random points and random segments in the unit square, free to cross.
Pslg randomInput(std::mt19937_64& rng, int points, int segments)
{
  std::uniform_real_distribution<double> U(0, 1);
  Pslg p;
  for (int i = 0; i < points + 2 * segments; ++i)
    p.points.push_back({ U(rng), U(rng) });
  for (int s = 0; s < segments; ++s)
    p.segments.push_back({ points + 2 * s, points + 2 * s + 1 });
  return p;
}

/// A random input (in) of the given size, meshed in the given domain.
Result meshedRandom(Pslg& in, int seed, int points, int segments, Domain domain)
{
  std::mt19937_64 rng(seed);
  in = randomInput(rng, points, segments);
  Options o;
  o.domain = domain;
  const Result r = meshed(in, o);
  EXPECT_TRUE(r.ok) << r.error;
  return r;
}

} // namespace

TEST(Interpolation, LinearFieldsAreReproducedAtEveryVertex)
{
  for (int seed = 0; seed < 30; ++seed)
    for (Domain domain : { Domain::Hull, Domain::Auto })
    {
      std::mt19937_64 rng(seed);
      const Pslg in = randomInput(rng, 20, 12);
      const std::string name = "seed " + std::to_string(seed);
      Options o;
      o.domain = domain;
      const Result r = meshed(in, o);
      ASSERT_TRUE(r.ok) << name << ": " << r.error;
      const std::vector<VertexTerms> w = termsOf(in, r, name);
      for (std::size_t v = 0; v < r.mesh.vertices.size(); ++v)
        ASSERT_NEAR(valueAt(w[v], in, linear), linear(r.mesh.vertices[v]), 1e-12)
          << name << ": vertex " << v << " at " << formatPoint(r.mesh.vertices[v]);
    }
}

TEST(Interpolation, InputVerticesKeepTheirOwnValueAndOthersLieOnTheirSegment)
{
  std::mt19937_64 rng(7);
  Pslg in = randomInput(rng, 10, 15);
  in.points.push_back(in.points[3]); // a duplicate: merged into point 3
  Options o;
  o.domain = Domain::Box; // no hull edges, which are stitched too but no input segment
  const Result r = meshed(in, o);
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_GT(r.stats.crossingsSplit, 0u);
  const std::vector<VertexTerms> w = termsOf(in, r, "crossing segments");
  std::size_t onSegments = 0;
  for (std::size_t v = 0; v < r.mesh.vertices.size(); ++v)
  {
    const VertexOrigin origin = r.vertexOrigin[v];
    if (origin == VertexOrigin::Input)
    {
      ASSERT_GE(w[v].inputPoint, 0);
      EXPECT_EQ(r.inputVertex[w[v].inputPoint], static_cast<int>(v));
      ASSERT_EQ(w[v].count, 1);
      EXPECT_EQ(w[v].point[0], w[v].inputPoint);
      continue;
    }
    EXPECT_EQ(w[v].inputPoint, -1);
    // Stitch vertices and crossings lie on a segment; their terms are its ends.
    if (origin == VertexOrigin::Stitch || origin == VertexOrigin::Other)
    {
      ++onSegments;
      ASSERT_GE(w[v].segment, 0) << "vertex " << v;
      const Segment& s = in.segments[w[v].segment];
      EXPECT_LT(distanceToSegment(r.mesh.vertices[v], in.points[s[0]], in.points[s[1]]), 1e-12);
      for (int k = 0; k < w[v].count; ++k)
        EXPECT_TRUE(w[v].point[k] == s[0] || w[v].point[k] == s[1]) << "vertex " << v;
    }
  }
  EXPECT_GT(onSegments, 0u);
  EXPECT_EQ(w[r.inputVertex.back()].inputPoint, 3); // the first of the merged pair
}

TEST(Interpolation, ASegmentToAMergedCopyTakesTheKeptPointsTuple)
{
  // Found by a review: a segment drawn to point 4, a copy of point 1 (as
  // Append Geometry leaves shared ends), ran to point 4's value and jumped
  // to point 1's at the vertex. Given twice, and within a merge tolerance.
  for (const double shift : { 0.0, 1e-7, 0.25 })
  {
    Pslg in;
    in.points = { { 0, 0 }, { 4, 0 }, { 4, 4 }, { 0, 4 }, { 4 + shift, shift } };
    in.segments = { { 0, 4 }, { 4, 2 }, { 2, 3 }, { 3, 0 } };
    Options o;
    o.mergeTolerance = 2 * shift;
    o.maxEdgeLength = 1;
    const Result r = meshed(in, o);
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_EQ(r.inputVertex[4], r.inputVertex[1]);
    const std::string name = "shift " + formatNumber(shift);
    const std::vector<VertexTerms> w = termsOf(in, r, name);
    std::size_t along = 0;
    for (std::size_t v = 0; v < w.size(); ++v)
    {
      for (int k = 0; k < w[v].count; ++k)
        EXPECT_NE(w[v].point[k], 4)
          << name << ": vertex " << v << " takes the dropped copy's tuple";
      if (w[v].segment == 0)
      {
        ++along;
        // Linear along the segment from point 0 (0) to point 1 (1).
        const double value =
          valueAt(w[v], in, [&](const Point& q) { return q == in.points[1] ? 1.0 : 0.0; });
        EXPECT_NEAR(value, r.mesh.vertices[v].x / 4, 1e-6) << name << ": vertex " << v;
        // Placed between the points kept, not the segment's own ends (the
        // fuzzer: a field linear over the input was off by 0.027 there).
        EXPECT_NEAR(valueAt(w[v], in, linear), linear(r.mesh.vertices[v]), 1e-12)
          << name << ": vertex " << v;
      }
    }
    EXPECT_GT(along, 0u) << name;
  }
}

TEST(Interpolation, BeyondTheInputTheBoxTakesValuesWithinTheInputs)
{
  Pslg in;
  const Result r = meshedRandom(in, 3, 15, 5, Domain::Box);
  ASSERT_TRUE(r.ok);
  const std::vector<VertexTerms> w = termsOf(in, r, "box");
  const Bounds b = boundsOf(in.points);
  std::size_t beyond = 0;
  for (std::size_t v = 0; v < r.mesh.vertices.size(); ++v)
  {
    const Point& p = r.mesh.vertices[v];
    beyond += p.x < b.lo.x || p.x > b.hi.x || p.y < b.lo.y || p.y > b.hi.y;
    // Within the inputs' bounds, linear fields are reproduced.
    if (p.x > b.lo.x && p.x < b.hi.x && p.y > b.lo.y && p.y < b.hi.y)
      continue;
    const double x = valueAt(w[v], in, [](const Point& q) { return q.x; });
    EXPECT_GE(x, b.lo.x);
    EXPECT_LE(x, b.hi.x);
  }
  EXPECT_GT(beyond, 0u);
}

// A field with a kink along a segment, |x - 1/2| in the unit square split by
// the segment x = 1/2: given at the input points only, it is reproduced
// where the values on each side come from that side.
TEST(Interpolation, ValuesAreNotAveragedAcrossASegment)
{
  Pslg in;
  in.points = { { 0, 0 }, { 0.5, 0 }, { 1, 0 }, { 1, 1 }, { 0.5, 1 }, { 0, 1 } };
  in.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 4 }, { 4, 5 }, { 5, 0 }, { 1, 4 } };
  auto kink = [](const Point& p) { return std::abs(p.x - 0.5); };
  double worst = 0;
  for (double angle : { 30.0, 20.0, 10.0 })
  {
    Options o;
    o.minAngleDeg = angle;
    const Result r = meshed(in, o);
    ASSERT_TRUE(r.ok) << r.error;
    const std::vector<VertexTerms> w = termsOf(in, r, "kink");
    for (std::size_t v = 0; v < r.mesh.vertices.size(); ++v)
      worst = std::max(worst, std::abs(valueAt(w[v], in, kink) - kink(r.mesh.vertices[v])));
  }
  EXPECT_LT(worst, 1e-12);
}

// The same kink with random points on both sides: the triangles of the
// points on segments seldom reach across it.
TEST(Interpolation, KinksAlongSegmentsAmongRandomPoints)
{
  auto kink = [](const Point& p) { return std::abs(p.x - 0.5); };
  std::size_t vertices = 0, off = 0;
  double worst = 0;
  for (int seed = 0; seed < 40; ++seed)
  {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(0, 1);
    Pslg in;
    in.points = { { 0, 0 }, { 0.5, 0 }, { 1, 0 }, { 1, 1 }, { 0.5, 1 }, { 0, 1 } };
    in.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 4 }, { 4, 5 }, { 5, 0 }, { 1, 4 } };
    for (int i = 0; i < 30; ++i)
      in.points.push_back({ U(rng), U(rng) });
    const Result r = meshed(in);
    ASSERT_TRUE(r.ok) << r.error;
    const std::vector<VertexTerms> w = termsOf(in, r, "kink " + std::to_string(seed));
    for (std::size_t v = 0; v < r.mesh.vertices.size(); ++v)
    {
      const double e = std::abs(valueAt(w[v], in, kink) - kink(r.mesh.vertices[v]));
      worst = std::max(worst, e);
      off += e > 1e-12;
    }
    vertices += r.mesh.vertices.size();
  }
  std::printf("kink: %zu of %zu vertices off, worst %g\n", off, vertices, worst);
  EXPECT_LT(worst, 1e-12);
}

// One input point meshes as the box around it: its value everywhere (the
// fuzzer's first find: no extent to pad the known points' triangulation by).
TEST(Interpolation, OnePointGivesItsValueEverywhere)
{
  Pslg in;
  in.points = { { 4, 0 } };
  const Result r = meshed(in);
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_GT(r.mesh.vertices.size(), 1u);
  for (const VertexTerms& t : termsOf(in, r, "one point"))
  {
    ASSERT_EQ(t.count, 1);
    EXPECT_EQ(t.point[0], 0);
  }
}

// The same input at 1e300 and at 1e-300 gives the same terms, and convex
// ones among subnormal numbers (the fuzzer's second find): coordinates are
// scaled by a power of two first, so that no square or circumcircle test
// overflows.
TEST(Interpolation, HugeAndTinyCoordinatesGiveTheSameTerms)
{
  Pslg unit;
  const Result r = meshedRandom(unit, 11, 10, 6, Domain::Hull);
  ASSERT_TRUE(r.ok);
  const std::vector<VertexTerms> reference = termsOf(unit, r, "unit");
  for (double factor : { 0x1p996, 0x1p-1000, 0x1p-1060 })
  {
    Pslg in = unit;
    Result scaled = r;
    for (Point& p : in.points)
      p = { p.x * factor, p.y * factor };
    for (Point& p : scaled.mesh.vertices)
      p = { p.x * factor, p.y * factor };
    const std::vector<VertexTerms> w = termsOf(in, scaled, "scaled");
    if (factor < 0x1p-1040) // subnormal: the points lost bits, convex terms only
      continue;
    for (std::size_t v = 0; v < w.size(); ++v)
    {
      ASSERT_EQ(w[v].count, reference[v].count) << factor << ": vertex " << v;
      for (int k = 0; k < w[v].count; ++k)
      {
        EXPECT_EQ(w[v].point[k], reference[v].point[k]);
        EXPECT_NEAR(w[v].weight[k], reference[v].weight[k], 1e-9);
      }
    }
  }
}

// An overlay Steiner point that a segment passes through exactly (here the
// circumcenter of a right triangle whose hypotenuse is the segment) lies on
// it: a kink along the segment is kept there (the review's first find, when
// only stitch vertices and crossings were looked up).
TEST(Interpolation, OverlayVerticesOnASegmentTakeItsValues)
{
  Pslg in;
  in.points = { { 3, 6 }, { 3, 4 }, { 2, 6 }, { 2, 4 } };
  in.segments = { { 0, 3 } };
  const Result r = meshed(in);
  ASSERT_TRUE(r.ok) << r.error;
  const std::vector<VertexTerms> w = termsOf(in, r, "right triangles");
  // |distance to the segment's line|, 0 along it.
  auto kink = [](const Point& p) { return std::abs(2 * (p.x - 3) - (p.y - 6)) / std::sqrt(5.0); };
  std::size_t onIt = 0;
  for (std::size_t v = 0; v < w.size(); ++v)
  {
    const Point& p = r.mesh.vertices[v];
    if (r.vertexOrigin[v] == VertexOrigin::Overlay && kink(p) < 1e-12)
    {
      ++onIt;
      EXPECT_EQ(w[v].segment, 0) << formatPoint(p);
    }
    EXPECT_NEAR(valueAt(w[v], in, kink), kink(p), 1e-12) << formatPoint(p);
  }
  EXPECT_GT(onIt, 0u);
}

// With a merge tolerance a segment bends through points near it; its
// vertices keep it (not a nearer other segment: the review's third find),
// and lie within the tolerance of it.
TEST(Interpolation, VerticesKeepTheirSegmentWhereItBends)
{
  Pslg in;
  in.points = { { 0, 0 }, { 10, 0 }, { 5, 0.1 }, { 4.6, 0.16 }, { 4.6, 3 }, { 0, 5 }, { 10, 5 } };
  in.segments = { { 0, 1 }, { 3, 4 } };
  Options o;
  o.mergeTolerance = 0.1;
  o.domain = Domain::Hull;
  const Result r = meshed(in, o);
  ASSERT_TRUE(r.ok) << r.error;
  std::size_t onA = 0;
  for (const VertexTerms& t : termsOf(in, r, "bent"))
  {
    const Point& p = r.mesh.vertices[t.vertex];
    if (t.segment < 0)
      continue;
    const Segment& s = in.segments[t.segment];
    EXPECT_LE(distanceToSegment(p, in.points[s[0]], in.points[s[1]]), 0.1 + 1e-12)
      << formatPoint(p) << " on segment " << t.segment;
    if (p.y < 0.2 && p.x > 3 && p.x < 6 && p.y > 0.01)
    {
      ++onA;
      EXPECT_EQ(t.segment, 0) << formatPoint(p);
    }
  }
  EXPECT_GT(onA, 0u);
}

// The fuzzer's case: a merge tolerance moves a segment's end onto an earlier
// point (by up to the tolerance), then bends the moved segment through a
// point near it (by up to the tolerance again). A vertex on the bent piece
// takes the value at its nearest point of the input segment, so a linear
// field is off there by at most its gradient times twice the tolerance.
TEST(Interpolation, ASegmentMovedAndBentByTheToleranceKeepsItsValuesWithinTwiceIt)
{
  Pslg in;
  // Segment 1-0 ends at (14, 4), which merges into (15, 5); the moved
  // segment then bends through (12, 8), 1.45 off its line.
  in.points = { { 0, 12 }, { 15, 5 }, { 14, 4 }, { 12, 8 }, { 0, 2 }, { 15, 12 } };
  in.segments = { { 2, 0 } };
  Options o;
  o.mergeTolerance = 1.5;
  o.maxEdgeLength = 1; // for stitch vertices all along it
  o.domain = Domain::Hull;
  const Result r = meshed(in, o);
  ASSERT_TRUE(r.ok) << r.error;
  const Point a = in.points[2], b = in.points[0];
  const double gradient = std::sqrt(2.0 * 2.0 + 3.0 * 3.0);
  double furthest = 0;
  for (const VertexTerms& t : termsOf(in, r, "moved and bent"))
  {
    if (t.segment != 0)
      continue;
    const Point& p = r.mesh.vertices[t.vertex];
    const double off = distanceToSegment(p, a, b);
    furthest = std::max(furthest, off);
    EXPECT_LE(off, 2 * o.mergeTolerance + 1e-12) << formatPoint(p);
    EXPECT_LE(std::abs(valueAt(t, in, linear) - linear(p)), gradient * off * (1 + 1e-12) + 1e-12)
      << formatPoint(p);
  }
  // Some vertex lies further than one tolerance off: the case is exercised.
  EXPECT_GT(furthest, o.mergeTolerance);
}

// Input subsegments name their input segment (hull edges none), and both
// their ends lie on it.
TEST(Interpolation, InputSubsegmentsNameTheirSegment)
{
  Pslg in;
  const Result r = meshedRandom(in, 5, 10, 12, Domain::Hull);
  ASSERT_TRUE(r.ok);
  std::size_t named = 0, hull = 0;
  for (const Edge& e : r.edges)
  {
    if (!(e.flags & EdgeInput))
    {
      EXPECT_EQ(e.segment, -1);
      continue;
    }
    if (e.segment < 0)
    {
      ++hull;
      continue;
    }
    ++named;
    const Segment& s = in.segments[e.segment];
    for (int v : { e.a, e.b })
      EXPECT_LT(distanceToSegment(r.edgeVertices[v], in.points[s[0]], in.points[s[1]]), 1e-12);
  }
  EXPECT_GT(named, 0u);
  EXPECT_GT(hull, 0u);
}

// A hull edge nearly along a segment (the fuzzer's fourth find): with the
// known points' triangulation's corners 2^26 times the extent away, the
// triangles with a corner reached 0.0002 inside the hull there, and a point
// on the hull edge took the segment's values (off by 5e-4 here). A linear
// field is reproduced, to rounding at values of 2e5 in slivers (3e-6).
TEST(Interpolation, AHullEdgeNearlyAlongASegment)
{
  Pslg in;
  in.points = { { -127023.95459057762, 10 }, { 4, 0 }, { 0, 0 } };
  in.segments = { { 2, 0 } };
  const Result r = meshed(in);
  ASSERT_TRUE(r.ok) << r.error;
  const std::vector<VertexTerms> w = termsOf(in, r, "flat hull");
  for (std::size_t v = 0; v < w.size(); ++v)
    EXPECT_NEAR(valueAt(w[v], in, linear), linear(r.mesh.vertices[v]), 1e-5)
      << formatPoint(r.mesh.vertices[v]);
}

// Three nearly collinear input points on the hull (guitar.poly's (32.6, 8.57),
// (32.8, 8.49) and (33.4, 8.25), found by a user review): a stitch point on
// the hull edge took weights in their sliver off by 1e-4, since the areas in
// doubles were trusted down to 1e-14 of their terms, and a linear field came
// out 2e-4 off there.
TEST(Interpolation, ASliverOfCollinearHullPoints)
{
  Pslg in;
  in.points = { { 32.6, 8.57 }, { 32.8, 8.49 }, { 33.4, 8.25 }, { 33.6, 8.17 }, { 33.6, 7.88 },
    { 32.4, 8.36 }, { 33.2, 8.04 } };
  in.segments = { { 0, 1 }, { 2, 3 }, { 3, 4 }, { 5, 0 }, { 6, 2 } };
  Options o;
  o.domain = Domain::Hull;
  o.maxEdgeLength = 0.05;
  const Result r = meshed(in, o);
  ASSERT_TRUE(r.ok) << r.error;
  const std::vector<VertexTerms> w = termsOf(in, r, "collinear hull points");
  for (std::size_t v = 0; v < w.size(); ++v)
    ASSERT_NEAR(valueAt(w[v], in, linear), linear(r.mesh.vertices[v]), 1e-12)
      << formatPoint(r.mesh.vertices[v]);
}

TEST(Interpolation, TermsWithoutWeightAreLeftOut)
{
  // A mutation test: zero and negative weights were kept as terms, in room
  // for 6.
  VertexTerms t;
  t.add(3, 0.0);
  t.add(4, -0.25);
  t.add(5, 1.0);
  ASSERT_EQ(t.count, 1);
  EXPECT_EQ(t.point[0], 5);
  EXPECT_EQ(t.weight[0], 1.0);
}
