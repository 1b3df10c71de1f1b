// Property tests: generated inputs of the kinds that break meshers (tiny
// angles, near-parallel segments, spirals, clusters of huge spread, far from
// the origin), many seeds each, with the independent validator as oracle.
#include "MeshTestUtils.h"
#include "Predicates.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <set>

using namespace osm;

namespace
{

const double kPi = std::acos(-1.0);

/// Spokes from a hub, consecutive ones `step` degrees apart, plus a random one.
Pslg fan(std::mt19937_64& rng, double stepDeg)
{
  std::uniform_real_distribution<double> U(0.2, 1.0);
  Pslg p;
  p.points.push_back({ 0, 0 });
  const int spokes = 2 + static_cast<int>(rng() % 6);
  const double base = U(rng) * 2 * kPi;
  for (int i = 0; i < spokes; ++i)
  {
    const double a = base + i * stepDeg * kPi / 180, r = U(rng);
    p.points.push_back({ r * std::cos(a), r * std::sin(a) });
    p.segments.push_back({ 0, i + 1 });
  }
  const double a = base + 180 * kPi / 180;
  p.points.push_back({ std::cos(a), std::sin(a) });
  p.segments.push_back({ 0, spokes + 1 });
  return p;
}

/// Two long segments `gap` apart (relative to their length), at a random angle.
Pslg nearParallel(std::mt19937_64& rng, double gap)
{
  std::uniform_real_distribution<double> U(0, 1);
  const double a = U(rng) * kPi, c = std::cos(a), s = std::sin(a), shift = U(rng) * 0.5;
  auto at = [&](double x, double y) { return Point{ x * c - y * s, x * s + y * c }; };
  Pslg p;
  p.points = { at(0, 0), at(1, 0), at(shift, gap), at(shift + 1, gap) };
  p.segments = { { 0, 1 }, { 2, 3 } };
  return p;
}

/// A polyline spiralling inwards with geometrically shrinking radius.
Pslg spiral(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> U(0, 1);
  const double ratio = 0.9 + 0.08 * U(rng), step = 0.3 + 0.5 * U(rng);
  Pslg p;
  double r = 1;
  for (int i = 0; i < 150; ++i, r *= ratio)
  {
    p.points.push_back({ r * std::cos(i * step), r * std::sin(i * step) });
    if (i > 0)
      p.segments.push_back({ i - 1, i });
  }
  return p;
}

bool crossesAny(const Pslg& p, const Point& a, const Point& b)
{
  for (const Segment& s : p.segments)
  {
    const Point &c = p.points[s[0]], &d = p.points[s[1]];
    const int o1 = orientSign(a, b, c), o2 = orientSign(a, b, d);
    const int o3 = orientSign(c, d, a), o4 = orientSign(c, d, b);
    if (o1 * o2 <= 0 && o3 * o4 <= 0)
      return true; // crossing or touching: keep the generated input clean
  }
  return false;
}

/// Random segments in the unit square, each kept only if it touches no other.
Pslg randomSegments(std::mt19937_64& rng, int count)
{
  std::uniform_real_distribution<double> U(0, 1), L(-0.15, 0.15);
  Pslg p;
  for (int tries = 0; tries < 20 * count && static_cast<int>(p.segments.size()) < count; ++tries)
  {
    const Point a{ U(rng), U(rng) };
    const Point b{ a.x + L(rng), a.y + L(rng) };
    if (crossesAny(p, a, b))
      continue;
    const int i = static_cast<int>(p.points.size());
    p.points.push_back(a);
    p.points.push_back(b);
    p.segments.push_back({ i, i + 1 });
  }
  return p;
}

/// Clusters of points and short segments whose size is 1e-8 of their spacing.
Pslg clusters(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> U(0, 1);
  Pslg p;
  for (int c = 0; c < 4; ++c)
  {
    const Point centre{ U(rng), U(rng) };
    const int first = static_cast<int>(p.points.size());
    for (int i = 0; i < 6; ++i)
      p.points.push_back({ centre.x + 1e-8 * U(rng), centre.y + 1e-8 * U(rng) });
    p.segments.push_back({ first, first + 1 });
  }
  return p;
}

Pslg translated(Pslg p, double offset)
{
  for (Point& q : p.points)
    q = { q.x + offset, q.y + offset * 0.5 };
  return p;
}

/// Smallest distance between two input points over the largest coordinate.
double relativeSpacing(const Pslg& p)
{
  double least = INFINITY, largest = 0;
  for (std::size_t i = 0; i < p.points.size(); ++i)
  {
    largest = std::max({ largest, std::fabs(p.points[i].x), std::fabs(p.points[i].y) });
    for (std::size_t j = i + 1; j < p.points.size(); ++j)
      least =
        std::min(least, std::hypot(p.points[i].x - p.points[j].x, p.points[i].y - p.points[j].y));
  }
  return least / largest;
}

/// The mesher refuses features below about 1e-14 of the coordinates (a few
/// dozen units in the last place), with a clear error. Far from the origin a
/// generated spiral can wind down to there: then that error is the right
/// answer; from 1e-13 up, the input must mesh.
void meshValidateOrRefuseBelowPrecision(const Pslg& p, const std::string& name)
{
  if (relativeSpacing(p) >= 1e-13)
  {
    meshAndValidate(p, name);
    return;
  }
  const Result r = mesh(p);
  if (r.ok)
    meshAndValidate(p, name);
  else
    EXPECT_NE(r.error.find("closer together than double precision resolves"), std::string::npos)
      << name << ": " << r.error;
}

/// Two to five long segments (lengths 1 to 4) through a point (the origin or
/// near it), with rounded directions, and one to three segments 1e-10 to
/// 1e-14 long within 1e-13 to 1e-16 of that point: crossings a few units in
/// the last place apart at the long segments' scale, many at the short ones'.
Pslg tinySegmentsAtACrossing(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const Point c = rng() % 2 ? Point{ 0, 0 } : Point{ 6 * U(rng) - 3, 6 * U(rng) - 3 };
  Pslg p;
  auto add = [&](const Point& centre, double angle, double r1, double r2) {
    const int i = static_cast<int>(p.points.size());
    p.points.push_back({ centre.x + r1 * std::cos(angle), centre.y + r1 * std::sin(angle) });
    p.points.push_back({ centre.x - r2 * std::cos(angle), centre.y - r2 * std::sin(angle) });
    p.segments.push_back({ i, i + 1 });
  };
  for (int k = 2 + static_cast<int>(rng() % 4); k > 0; --k)
    add(c, kPi * U(rng), 0.5 + 1.5 * U(rng), 0.5 + 1.5 * U(rng));
  for (int k = 1 + static_cast<int>(rng() % 3); k > 0; --k)
  {
    const double length = std::pow(10.0, -10 - 4 * U(rng));
    const double off = std::pow(10.0, -13 - 3 * U(rng));
    add(
      { c.x + off * (2 * U(rng) - 1), c.y + off * (2 * U(rng) - 1) }, kPi * U(rng), length, length);
  }
  return p;
}

/// Rays from one point at angle steps of 1e-12 to 1e-3 radians and lengths
/// from 1e-6 to 1e6, some of their ends joined in turn: points far closer to
/// long segments than their lengths' rounding (a review's family).
Pslg raysAtTinyAngles(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> U(0.0, 1.0);
  Pslg p;
  p.points.push_back({ 0, 0 });
  const double start = 2 * kPi * U(rng);
  const int rays = 3 + static_cast<int>(rng() % 7);
  for (int k = 0; k < rays; ++k)
  {
    const double angle = start + k * std::pow(10.0, -12 + 9 * U(rng));
    const double length = std::pow(10.0, -6 + 12 * U(rng));
    p.points.push_back({ length * std::cos(angle), length * std::sin(angle) });
    p.segments.push_back({ 0, k + 1 });
    if (k > 0 && rng() % 2)
      p.segments.push_back({ k, k + 1 });
  }
  return p;
}

/// Segments drawn with no regard for each other, as digitised networks often
/// are (roads over rivers with no node where they meet): 3 to 30 random
/// segments in the unit square crossing freely, a third of them long, some
/// sharing an end, and with one chance in four a star of 3 to 8 through one
/// random point.
Pslg crossingSegments(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> U(0.0, 1.0);
  Pslg p;
  auto add = [&](const Point& a, const Point& b) {
    const int i = static_cast<int>(p.points.size());
    p.points.push_back(a);
    p.points.push_back(b);
    p.segments.push_back({ i, i + 1 });
  };
  const int count = 3 + static_cast<int>(rng() % 28);
  for (int k = 0; k < count; ++k)
  {
    const Point a{ U(rng), U(rng) };
    const double reach = rng() % 3 == 0 ? 1.0 : 0.2;
    const Point b{ a.x + reach * (2 * U(rng) - 1), a.y + reach * (2 * U(rng) - 1) };
    if (k > 0 && rng() % 5 == 0) // from the end of an earlier one
    {
      const int from = static_cast<int>(rng() % p.points.size());
      p.points.push_back(b);
      p.segments.push_back({ from, static_cast<int>(p.points.size()) - 1 });
    }
    else if (!(a == b))
      add(a, b);
  }
  if (rng() % 4 == 0)
  {
    const Point c{ U(rng), U(rng) };
    for (int k = 3 + static_cast<int>(rng() % 6); k > 0; --k)
    {
      const double angle = kPi * U(rng), r1 = 0.1 + U(rng), r2 = 0.1 + U(rng);
      add({ c.x + r1 * std::cos(angle), c.y + r1 * std::sin(angle) },
        { c.x - r2 * std::cos(angle), c.y - r2 * std::sin(angle) });
    }
  }
  return p;
}

/// Segments digitised to end on another and missing it by `gap`: a unit
/// square's sides and a diagonal, and 3 to 12 segments from inside it each
/// ending `gap` short of a side or of the diagonal (an undershoot) or `gap`
/// past it (an overshoot, crossing it).
Pslg nearTJunctions(std::mt19937_64& rng, double gap)
{
  std::uniform_real_distribution<double> U(0.05, 0.95);
  Pslg p;
  p.points = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  p.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 0, 2 } };
  for (int k = 3 + static_cast<int>(rng() % 10); k > 0; --k)
  {
    const int target = static_cast<int>(rng() % 5);
    const Point a = p.points[p.segments[target][0]], b = p.points[p.segments[target][1]];
    const double t = U(rng), len = std::hypot(b.x - a.x, b.y - a.y);
    // The unit normal to the target towards the start, which lies 0.05 to
    // 0.3 off it, on the square's inside.
    Point n{ -(b.y - a.y) / len, (b.x - a.x) / len };
    const Point mid{ a.x + t * (b.x - a.x), a.y + t * (b.y - a.y) };
    if (n.x * (0.5 - mid.x) + n.y * (0.5 - mid.y) < 0 || (target == 4 && rng() % 2))
      n = { -n.x, -n.y };
    const double off = 0.05 + 0.25 * U(rng), miss = rng() % 2 ? gap : -gap;
    const int i = static_cast<int>(p.points.size());
    p.points.push_back({ mid.x + off * n.x + 0.1 * (U(rng) - 0.5), mid.y + off * n.y });
    p.points.push_back({ mid.x + miss * n.x, mid.y + miss * n.y });
    p.segments.push_back({ i, i + 1 });
  }
  return p;
}

/// Road networks digitised with misses: 1 to 6 junctions, each of 3 or 4
/// roads through it, each road 1e-11 to 1e-9 off it (random side), long
/// enough to cross other junctions' roads, half of them drawn as two
/// segments meeting at their own point nearest the junction. No cycle of
/// segments more than a speck across passes through an input point.
Pslg roadJunctions(std::mt19937_64& rng, Array<Point>& junctions)
{
  std::uniform_real_distribution<double> U(0.0, 1.0);
  Pslg p;
  junctions.clear();
  for (int j = 1 + static_cast<int>(rng() % 6); j > 0; --j)
  {
    const Point c{ U(rng), U(rng) };
    junctions.push_back(c);
    const int roads = 3 + static_cast<int>(rng() % 2);
    for (int k = 0; k < roads; ++k)
    {
      const double t = kPi * (k + 0.8 * U(rng)) / roads, miss = std::pow(10.0, -11 + 2 * U(rng));
      const double off = rng() % 2 ? miss : -miss, r1 = 0.2 + 0.6 * U(rng), r2 = 0.2 + 0.6 * U(rng);
      const Point o{ c.x - off * std::sin(t), c.y + off * std::cos(t) };
      const int i = static_cast<int>(p.points.size());
      p.points.push_back({ o.x + r1 * std::cos(t), o.y + r1 * std::sin(t) });
      p.points.push_back({ o.x - r2 * std::cos(t), o.y - r2 * std::sin(t) });
      if (rng() % 2 == 0)
      {
        p.points.push_back(o);
        p.segments.insert(p.segments.end(), { { i, i + 2 }, { i + 2, i + 1 } });
      }
      else
        p.segments.push_back({ i, i + 1 });
    }
  }
  return p;
}

/// Seeds per family; OSM_PROPERTY_SEEDS raises it for a long stress run.
const int kSeeds =
  std::getenv("OSM_PROPERTY_SEEDS") ? std::atoi(std::getenv("OSM_PROPERTY_SEEDS")) : 25;

} // namespace

TEST(Properties, FansDownToAHundredthOfADegree)
{
  for (double step : { 10.0, 1.0, 0.1, 0.01 })
    for (int seed = 0; seed < kSeeds; ++seed)
    {
      std::mt19937_64 rng(seed);
      meshAndValidate(
        fan(rng, step), "fan " + std::to_string(step) + " seed " + std::to_string(seed));
    }
}

TEST(Properties, NearParallelSegmentsDownToGapsOf1e9)
{
  for (double gap : { 1e-3, 1e-5, 1e-7, 1e-9 })
    for (int seed = 0; seed < kSeeds; ++seed)
    {
      std::mt19937_64 rng(seed);
      meshAndValidate(
        nearParallel(rng, gap), "gap " + std::to_string(gap) + " seed " + std::to_string(seed));
    }
}

TEST(Properties, GeometricSpirals)
{
  for (int seed = 0; seed < kSeeds; ++seed)
  {
    std::mt19937_64 rng(seed);
    meshAndValidate(spiral(rng), "spiral seed " + std::to_string(seed));
  }
}

TEST(Properties, RandomNonCrossingSegments)
{
  for (int seed = 0; seed < kSeeds; ++seed)
  {
    std::mt19937_64 rng(seed);
    meshAndValidate(randomSegments(rng, 60), "random seed " + std::to_string(seed));
  }
}

TEST(Properties, FreelyCrossingSegments)
{
  // Crossings are split where they are (rounded), and the pieces meshed as
  // any segments; the validator checks each input segment as a chain through
  // its crossings. In the hull, and in the regions the crossings close (whose
  // carving removes the parts of segments outside them: no conformity).
  // Stars whose rounded crossings scatter over more than a few units in the
  // last place, where two of their segments are nearly parallel, were refused
  // (8 of 1,000 at 9537ac6, with or without a merge tolerance); any refusal
  // must say that a merge tolerance would join them. With one of 1e-12, the
  // crossings within it join, and the mesh must follow every segment. With
  // one of 1e-3 (a thousandth of the extent: roads digitised apart), joins
  // bend the segments, and each one's chain must stay within it of its line.
  int meshed = 0;
  const int cases = 4 * kSeeds;
  for (int seed = 0; seed < cases; ++seed)
  {
    std::mt19937_64 rng(seed);
    const Pslg p = crossingSegments(rng);
    const std::string name = "crossing segments, seed " + std::to_string(seed);
    Options hull;
    hull.domain = Domain::Hull;
    if (const Result r = mesh(p, hull); !r.ok)
    {
      EXPECT_NE(r.error.find("if segments there are meant to meet at one point, a merge tolerance"),
        std::string::npos)
        << name << ": " << r.error;
      EXPECT_NE(r.error.find("than double precision"), std::string::npos)
        << name << ": " << r.error;
    }
    else
    {
      meshAndValidate(p, name + " (hull)", hull);
      ValidationOptions regionsOnly;
      regionsOnly.checkConformity = false;
      meshAndValidate(p, name + " (auto)", {}, regionsOnly);
      ++meshed;
    }
    hull.mergeTolerance = 1e-12;
    meshAndValidate(p, name + " (hull, merge tolerance 1e-12)", hull);
    hull.mergeTolerance = 1e-3;
    meshAndValidate(p, name + " (hull, merge tolerance 1e-3)", hull);
  }
  EXPECT_GE(meshed, cases * 99 / 100);
}

TEST(Properties, FlippedEdgesOnSegmentsFailTheChainCheckWithATolerance)
{
  // With a merge tolerance the validator lets a segment's chain bend, but
  // only where another segment passes (a crossing joined there), and must
  // still see most broken chains: flipping a mesh edge on a segment breaks
  // conformity. When any vertex within the tolerance of the line could
  // complete a chain, 71 of 3,374 such flips passed (25 seeds), 355 of
  // 12,829 (100 seeds); with the bend rule 2 and 115, where segments pass
  // that close (stars). At most 1.5% may pass.
  int flips = 0, passed = 0;
  for (int seed = 0; seed < kSeeds; ++seed)
  {
    std::mt19937_64 rng(seed);
    Pslg p = crossingSegments(rng);
    Options options;
    options.domain = Domain::Hull;
    options.mergeTolerance = 1e-3;
    const Result r = mesh(p, options);
    ASSERT_TRUE(r.ok) << "seed " << seed << ": " << r.error;
    if (r.stats.crossingsSplit == 0)
      continue;
    for (std::size_t i = 0; i < p.points.size(); ++i)
      p.points[i] = r.mesh.vertices[r.inputVertex[i]];
    ValidationOptions vo;
    vo.snapTolerance = vo.chainOffset = options.mergeTolerance;
    vo.maxErrorMessages = 1;
    vo.bruteForceOverlapLimit = 0; // conformity is what a flip breaks
    ASSERT_TRUE(validate(p, r.mesh.vertices, r.mesh.triangles, vo).ok) << "seed " << seed;
    std::set<std::pair<Point, Point>> onSegments;
    for (const Edge& e : r.edges)
      if (e.flags & EdgeInput)
        onSegments.insert(std::minmax(r.edgeVertices[e.a], r.edgeVertices[e.b]));
    const Array<Triangle>& T = r.mesh.triangles;
    const Array<Point>& X = r.mesh.vertices;
    std::map<std::pair<int, int>, int> triangleOf; // half-edge (u, v) -> its triangle
    for (std::size_t t = 0; t < T.size(); ++t)
      for (int k = 0; k < 3; ++k)
        triangleOf[{ T[t][k], T[t][(k + 1) % 3] }] = static_cast<int>(t);
    for (const auto& [uv, t1] : triangleOf)
    {
      const int u = uv.first, v = uv.second; // (clang 14 captures no bindings)
      const auto twin = triangleOf.find({ v, u });
      if (u > v || twin == triangleOf.end() || !onSegments.count(std::minmax(X[u], X[v])))
        continue;
      const auto opposite = [&](int t) { return T[t][0] + T[t][1] + T[t][2] - u - v; };
      const int w1 = opposite(t1), w2 = opposite(twin->second);
      if (!(orient2d(X[w1], X[u], X[w2]) > 0 && orient2d(X[w2], X[v], X[w1]) > 0))
        continue; // not convex: no flip
      Array<Triangle> flipped = T;
      flipped[t1] = { w1, u, w2 };
      flipped[twin->second] = { w2, v, w1 };
      ++flips;
      passed += validate(p, X, flipped, vo).ok;
    }
  }
  EXPECT_GT(flips, 20 * kSeeds);
  EXPECT_LE(200 * passed, 3 * flips) << passed << " of " << flips << " flips passed";
}

TEST(Properties, RoadJunctionsDigitisedApart)
{
  // The auto domain meshes the hull, every input point in it, whatever the
  // crossings close (before: the tiny triangles at junctions alone, or the
  // regions between roads, every input point left out), unless a region
  // more than a speck across has an input point on its boundary: where a
  // road drawn as two segments bounds one, the enclosed regions are meshed,
  // the roads beyond them cut (no conformity then). With a merge tolerance of
  // 1e-8, above the misses, each junction in the hull is one vertex, and each
  // road's chain passes within the tolerance of its line.
  int joinedJunctions = 0, junctionCount = 0;
  ValidationOptions regionsOnly;
  regionsOnly.checkConformity = false;
  for (int seed = 0; seed < 2 * kSeeds; ++seed)
  {
    std::mt19937_64 rng(seed);
    Array<Point> junctions;
    const Pslg p = roadJunctions(rng, junctions);
    const bool split = p.segments.size() * 2 > p.points.size();
    const std::string name = "road junctions, seed " + std::to_string(seed);
    const Result r = meshAndValidate(p, name, {}, split ? regionsOnly : ValidationOptions{});
    if (!r.ok)
      continue;
    // Regions bounded by roads drawn as two segments have an input point on
    // their boundary, and are meshed alone: then larger than any speck.
    EXPECT_TRUE(std::count(r.inputVertex.begin(), r.inputVertex.end(), -1) == 0 ||
      (split && area(r.mesh) > 1e-12))
      << name << ": " << area(r.mesh);
    Options joined;
    joined.mergeTolerance = 1e-8;
    const Result j = meshAndValidate(
      p, name + ", merge tolerance 1e-8", joined, split ? regionsOnly : ValidationOptions{});
    const bool hull = std::count(j.inputVertex.begin(), j.inputVertex.end(), -1) == 0;
    EXPECT_TRUE(hull || (split && area(j.mesh) > 1e-12)) << name << ": " << area(j.mesh);
    if (!hull)
      continue;
    for (const Point& c : junctions)
    {
      long near = 0;
      for (const Point& v : j.mesh.vertices)
        near += std::hypot(v.x - c.x, v.y - c.y) <= 1e-8;
      joinedJunctions += near == 1;
      ++junctionCount;
    }
  }
  // Another junction's road may pass within the tolerance of one: rare.
  EXPECT_GE(joinedJunctions, junctionCount * 99 / 100)
    << joinedJunctions << " of " << junctionCount;
}

TEST(Properties, SegmentsEndingNearAnother)
{
  // Undershoots and overshoots (a crossing) of 1e-6 down to 1e-15 of the
  // extent, as digitised networks have. Without a merge tolerance, the
  // gaps above about 1e-14 of the coordinates mesh, graded down to them, and
  // below that they may be refused, with where and the remedy; with a merge
  // tolerance of twice the gap every segment ends on the one it meant to,
  // crossings included, and the mesh follows every one.
  // In the box domain, where every segment is meshed (the hull's edges
  // would run within the gap of the square's sides, past the overshoots).
  Options box;
  box.domain = Domain::Box;
  for (double gap : { 1e-6, 1e-9, 1e-12, 1e-15 })
    for (int seed = 0; seed < kSeeds; ++seed)
    {
      std::mt19937_64 rng(seed);
      const Pslg p = nearTJunctions(rng, gap);
      const std::string name = "gap " + std::to_string(gap) + " seed " + std::to_string(seed);
      Options exact = box;
      if (const Result r = mesh(p, exact); r.ok)
        meshAndValidate(p, name, exact);
      else
      {
        EXPECT_LT(gap, 1e-13) << name << ": " << r.error;
        EXPECT_NE(r.error.find("merge tolerance"), std::string::npos) << name << ": " << r.error;
      }
      Options snapped = box;
      snapped.mergeTolerance = 2 * gap;
      meshAndValidate(p, name + ", merge tolerance", snapped);
    }
}

TEST(Properties, ClustersWithSpread1e8)
{
  for (int seed = 0; seed < kSeeds; ++seed)
  {
    std::mt19937_64 rng(seed);
    meshAndValidate(clusters(rng), "clusters seed " + std::to_string(seed));
  }
}

TEST(Properties, TranslatedFarFromTheOrigin)
{
  for (int seed = 0; seed < kSeeds; ++seed)
  {
    std::mt19937_64 rng(seed);
    const std::string s = std::to_string(seed);
    meshAndValidate(translated(fan(rng, 1.0), 1e7), "far fan seed " + s);
    meshValidateOrRefuseBelowPrecision(translated(spiral(rng), 1e7), "far spiral seed " + s);
    meshAndValidate(translated(randomSegments(rng, 30), 1e7), "far random seed " + s);
    meshAndValidate(translated(nearParallel(rng, 1e-6), 1e7), "far parallel seed " + s);
  }
}

/// Meshes cases inputs of generate (seeds 0, 1, ...) in the hull domain:
/// each must be a valid mesh or refused as below double precision, and at
/// least a third must be meshed.
void expectMeshedOrRefusedBelowPrecision(
  Pslg (*generate)(std::mt19937_64&), int cases, const std::string& family)
{
  Options hull;
  hull.domain = Domain::Hull;
  int meshed = 0;
  for (int seed = 0; seed < cases; ++seed)
  {
    std::mt19937_64 rng(seed);
    const Pslg p = generate(rng);
    const std::string name = family + ", seed " + std::to_string(seed);
    const Result r = mesh(p, hull);
    if (!r.ok)
    {
      EXPECT_NE(r.error.find("than double precision"), std::string::npos)
        << name << ": " << r.error;
      continue;
    }
    meshAndValidate(p, name, hull);
    ++meshed;
  }
  EXPECT_GE(meshed, cases / 3) << family;
}

TEST(Properties, TinySegmentsAtCrossingsOfLongOnes)
{
  // Crossings merged into one point bend the segments through it: a tiny
  // one bent at the long ones' scale was no longer a chain of mesh edges (97
  // of 300 such inputs before, 0 since). Those below what double precision
  // separates may be refused, with a clear error; most are meshed.
  expectMeshedOrRefusedBelowPrecision(
    tinySegmentsAtACrossing, 4 * kSeeds, "tiny segments at a crossing");
}

TEST(Properties, RaysAtTinyAnglesMeshOrAreRefusedAsBelowPrecision)
{
  // A review found 19 of 2,000 such fans refused as an "internal error": a
  // point 1e-18 of the scale from a long segment distorted a wide face (13
  // of these 2,000 seeds, the first 125: hence 300 cases by default).
  expectMeshedOrRefusedBelowPrecision(raysAtTinyAngles, 12 * kSeeds, "rays at tiny angles");
}

TEST(Properties, MaximumEdgeLengthHoldsOnEveryEdge)
{
  // Completion's diagonals may exceed the overlay's bound (by up to 17% on
  // the real inputs); they are split, and no edge of any family is longer.
  std::size_t split = 0, meshes = 0;
  for (int seed = 0; seed < kSeeds; ++seed)
    for (double h : { 0.2, 0.07, 0.03 })
    {
      std::mt19937_64 rng(seed);
      const std::string name = " seed " + std::to_string(seed) + " h " + std::to_string(h);
      Options o;
      o.maxEdgeLength = h;
      for (const auto& [family, p] : { std::pair{ "fan", fan(rng, 1.0) }, { "spiral", spiral(rng) },
             { "random", randomSegments(rng, 30) }, { "parallel", nearParallel(rng, 1e-5) } })
      {
        // The validator checks every edge against the bound.
        const Result r = meshAndValidate(p, family + name, o);
        split += r.stats.longEdgesSplit;
        ++meshes;
      }
    }
  // The families do make such diagonals: the split is exercised.
  EXPECT_GT(split, 0u) << "over " << meshes << " meshes";
  std::printf("%zu long edges split in %zu meshes\n", split, meshes);
}

TEST(Properties, SegmentsInAHoleAreCountedWhateverTheSizeBound)
{
  // Found by a review: with a size bound, splitting long completed edges
  // appends points after the stitch vertices, and the dropped pieces' stitch
  // vertices were looked up past them: 43 of these 540 meshes named the wrong
  // segments (a hole's side, a hull edge) or none, so that a dropped segment
  // went unreported. Cracks inside a square hole: each is dropped.
  std::size_t split = 0;
  for (int seed = 0; seed < kSeeds / 5; ++seed)
  {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> U(3.2, 6.8);
    Pslg p;
    p.points = { { 0, 0 }, { 10, 0 }, { 10, 10 }, { 0, 10 }, { 3, 3 }, { 7, 3 }, { 7, 7 },
      { 3, 7 } };
    p.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 6 }, { 6, 7 }, { 7, 4 } };
    const int cracks = 1 + seed % 3;
    for (int i = 0; i < cracks; ++i)
    {
      const int a = static_cast<int>(p.points.size());
      p.points.push_back({ U(rng), U(rng) });
      p.points.push_back({ U(rng), U(rng) });
      p.segments.push_back({ a, a + 1 });
    }
    p.holes = { { 3.1, 3.1 } };
    for (double h : { 0.9, 0.5, 0.3 })
      for (double angle : { 14.7, 20.7, 25.0 })
      {
        Options o;
        o.maxEdgeLength = h;
        o.minAngleDeg = angle;
        const std::string name =
          "cracks in a hole, seed " + std::to_string(seed) + " h " + std::to_string(h);
        const Result r = meshAndValidate(p, name, o);
        ASSERT_TRUE(r.ok) << name << ": " << r.error;
        split += r.stats.longEdgesSplit;
        // Every crack counted, and one of them (8 on) named.
        const std::string said = std::to_string(cracks) +
          " input segment(s) lie outside the meshed domain (outside every enclosed region or in a "
          "hole), wholly or in part, and are not in the mesh there, e.g. input segment ";
        EXPECT_TRUE(std::any_of(r.warnings.begin(), r.warnings.end(),
          [&](const std::string& w) {
            return w.rfind(said, 0) == 0 && std::atoi(w.c_str() + said.size()) >= 8;
          }))
          << name << ": " << (r.warnings.empty() ? "" : r.warnings.back());
      }
  }
  EXPECT_GT(split, 0u); // the case the review found is exercised
}

/// A rotated unit square holding up to 9 rectangles (one per cell of a 3 x 3
/// grid), some holding a smaller one: nested and side-by-side regions. Each
/// region gets a seed with no area limit or one of 1e-3 and 2e-4.
struct Regions
{
  Pslg pslg;
  double angle = 0;
  std::vector<Bounds> rects; ///< in unrotated coordinates, inner ones after their outer
  std::vector<double> limit; ///< per rect, then the square's last; 0 for none
};

Regions nestedRegions(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> U(0, 1);
  Regions r;
  r.angle = U(rng) * kPi;
  const double c = std::cos(r.angle), s = std::sin(r.angle);
  auto add = [&](const Bounds& b) {
    const int i = static_cast<int>(r.pslg.points.size());
    for (const Point& q : { b.lo, Point{ b.hi.x, b.lo.y }, b.hi, Point{ b.lo.x, b.hi.y } })
      r.pslg.points.push_back({ q.x * c - q.y * s, q.x * s + q.y * c });
    for (int k = 0; k < 4; ++k)
      r.pslg.segments.push_back({ i + k, i + (k + 1) % 4 });
  };
  const double limits[3] = { 0, 1e-3, 2e-4 };
  for (int cell = 0; cell < 9; ++cell)
  {
    if (U(rng) < 0.4)
      continue;
    const Point lo{ (cell % 3 + 0.1 + 0.2 * U(rng)) / 3, (cell / 3 + 0.1 + 0.2 * U(rng)) / 3 };
    const Point hi{ lo.x + 0.4 / 3, lo.y + 0.4 / 3 };
    r.rects.push_back({ lo, hi });
    if (U(rng) < 0.5)
      r.rects.push_back({ { lo.x + 0.1 / 3, lo.y + 0.1 / 3 }, { hi.x - 0.1 / 3, hi.y - 0.1 / 3 } });
  }
  add({ { 0, 0 }, { 1, 1 } });
  for (const Bounds& b : r.rects)
    add(b);
  r.rects.push_back({ { 0, 0 }, { 1, 1 } });
  for (const Bounds& b : r.rects)
  {
    // A seed near the lower left corner: inside the region, outside any nested one.
    const Point q{ b.lo.x + 0.01 / 3, b.lo.y + 0.01 / 3 };
    r.limit.push_back(limits[rng() % 3]);
    r.pslg.regions.push_back({ { q.x * c - q.y * s, q.x * s + q.y * c }, double(r.limit.size()),
      r.limit.back() > 0 ? r.limit.back() : -1.0 });
  }
  return r;
}

TEST(Properties, RegionAreasHoldOnEveryTriangle)
{
  Options o;
  o.regionAreas = true;
  std::size_t limited = 0;
  for (int seed = 0; seed < kSeeds; ++seed)
  {
    std::mt19937_64 rng(seed);
    const Regions r = nestedRegions(rng);
    const Result m = meshAndValidate(r.pslg, "regions seed " + std::to_string(seed), o);
    const double c = std::cos(r.angle), s = std::sin(r.angle);
    for (std::size_t t = 0; t < m.mesh.triangles.size(); ++t)
    {
      const Triangle& tri = m.mesh.triangles[t];
      const Point &a = m.mesh.vertices[tri[0]], &b = m.mesh.vertices[tri[1]],
                  &d = m.mesh.vertices[tri[2]];
      const Point g{ (a.x + b.x + d.x) / 3, (a.y + b.y + d.y) / 3 };
      const Point u{ g.x * c + g.y * s, -g.x * s + g.y * c }; // rotated back
      // The innermost rectangle holding the centroid: nested ones come after.
      std::size_t k = r.rects.size() - 1;
      for (std::size_t i = 0; i + 1 < r.rects.size(); ++i)
        if (u.x > r.rects[i].lo.x && u.x < r.rects[i].hi.x && u.y > r.rects[i].lo.y &&
          u.y < r.rects[i].hi.y)
          k = i;
      EXPECT_EQ(m.regionAttribute[t], double(k + 1)) << "seed " << seed << " triangle " << t;
      if (r.limit[k] > 0)
      {
        ++limited;
        EXPECT_LE(0.5 * orient2d(a, b, d), r.limit[k] * (1 + 1e-12))
          << "seed " << seed << " triangle " << t << " of region " << k;
      }
    }
  }
  EXPECT_GT(limited, 1000u);
}

TEST(Properties, SameInputSameOutput)
{
  std::mt19937_64 rng(3);
  const Pslg p = randomSegments(rng, 40);
  const Result a = mesh(p), b = mesh(p);
  ASSERT_TRUE(a.ok && b.ok);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  ASSERT_EQ(a.mesh.vertices.size(), b.mesh.vertices.size());
  for (std::size_t i = 0; i < a.mesh.vertices.size(); ++i)
    ASSERT_EQ(a.mesh.vertices[i], b.mesh.vertices[i]);
}
