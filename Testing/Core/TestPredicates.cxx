// Exactness tests for orient2d and incircle: every sign is compared with exact rational arithmetic
// (GMP; every finite double converts exactly to mpq_class). Near-degenerate test sets also count
// how often a naive double determinant gets the sign wrong and require that to happen, so each of
// those tests demonstrably catches a predicate that is merely "accurate".
#include "Predicates.h"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace
{

using osm::Point;

int sign(double v)
{
  return (v > 0) - (v < 0);
}

// ---- exact references -------------------------------------------------------------------------

int exactOrient(const Point& a, const Point& b, const Point& c)
{
  const mpq_class acx = mpq_class(a.x) - mpq_class(c.x), acy = mpq_class(a.y) - mpq_class(c.y);
  const mpq_class bcx = mpq_class(b.x) - mpq_class(c.x), bcy = mpq_class(b.y) - mpq_class(c.y);
  return sgn(mpq_class(acx * bcy - acy * bcx));
}

// Sign of the 4x4 determinant with rows (x, y, x^2 + y^2, 1), expanded about d.
int exactIncircle(const Point& a, const Point& b, const Point& c, const Point& d)
{
  const mpq_class dx(d.x), dy(d.y);
  const mpq_class adx = mpq_class(a.x) - dx, ady = mpq_class(a.y) - dy;
  const mpq_class bdx = mpq_class(b.x) - dx, bdy = mpq_class(b.y) - dy;
  const mpq_class cdx = mpq_class(c.x) - dx, cdy = mpq_class(c.y) - dy;
  const mpq_class alift = adx * adx + ady * ady;
  const mpq_class blift = bdx * bdx + bdy * bdy;
  const mpq_class clift = cdx * cdx + cdy * cdy;
  const mpq_class det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) +
    clift * (adx * bdy - bdx * ady);
  return sgn(det);
}

// ---- naive determinants, only to prove a test set is hard ------------------------------------

double naiveOrient(const Point& a, const Point& b, const Point& c)
{
  return (a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x);
}

double naiveIncircle(const Point& a, const Point& b, const Point& c, const Point& d)
{
  const double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  return (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
    (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
    (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
}

// ---- deterministic inputs ---------------------------------------------------------------------

// Platform-independent uniform numbers (the standard distributions are implementation-defined).
class Rng
{
public:
  explicit Rng(std::uint64_t seed)
    : engine(seed)
  {}
  double unit() { return static_cast<double>(engine() >> 11) * 0x1p-53; } // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  int integer(int lo, int hi) // [lo, hi]
  {
    return lo + static_cast<int>(engine() % static_cast<std::uint64_t>(hi - lo + 1));
  }

private:
  std::mt19937_64 engine;
};

// Move x by k units in the last place.
double ulps(double x, int k)
{
  const double toward = k > 0 ? HUGE_VAL : -HUGE_VAL;
  for (int i = 0; i < std::abs(k); ++i)
    x = std::nextafter(x, toward);
  return x;
}

Point perturb(const Point& p, Rng& rng, int maxUlps)
{
  return { ulps(p.x, rng.integer(-maxUlps, maxUlps)), ulps(p.y, rng.integer(-maxUlps, maxUlps)) };
}

// Where a configuration (coordinates within +-100) is placed: x -> offset + scale * x, rounded
// like real input data.
//
// A configuration much smaller than its distance to the origin lives on a grid that is coarse
// relative to its size (ulp(1e15) = 0.125), so ulp perturbations there are large and a naive
// determinant gets them right: those "narrow" frames check large offsets and exact zeros, not
// hardness. The "wide" frames put configurations of size ~offset/4 far from the origin, which is
// hard again. Then tiny, huge (products stay finite: ~1e200 for orient2d, ~1e300 for incircle),
// and beyond that range, which the exact fallback handles by power-of-two rescaling.
struct Frame
{
  const char* name;
  double offset;
  double scale;
  bool hard; // near-degenerate sets in this frame must defeat a naive determinant
  Point operator()(const Point& p) const { return { offset + scale * p.x, offset + scale * p.y }; }
};

const std::vector<Frame> orientFrames = { { "unit", 0.0, 1.0, true },
  { "offset 1e7", 1e7, 1.0, false }, { "offset 1e15", 1e15, 1.0, false },
  { "wide offset 1e7", 1e7, 1e7 / 400, true }, { "wide offset 1e15", 1e15, 1e15 / 400, true },
  { "scale 1e-150", 0.0, 1e-150, true }, { "scale 1e100", 0.0, 1e100, true },
  { "scale 1e-300", 0.0, 1e-300, true }, { "scale 1e200", 0.0, 1e200, true } };
const std::vector<Frame> incircleFrames = { { "unit", 0.0, 1.0, true },
  { "offset 1e7", 1e7, 1.0, false }, { "offset 1e15", 1e15, 1.0, false },
  { "wide offset 1e7", 1e7, 1e7 / 400, true }, { "wide offset 1e15", 1e15, 1e15 / 400, true },
  { "scale 1e-150", 0.0, 1e-150, true }, { "scale 1e70", 0.0, 1e70, true },
  { "scale 1e-300", 0.0, 1e-300, true }, { "scale 1e150", 0.0, 1e150, true } };

std::string str(const Point& p)
{
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%a, %a)", p.x, p.y);
  return buf;
}

// ---- comparison bookkeeping -------------------------------------------------------------------

// Compares a predicate with the exact sign; an exactly degenerate case must return exactly 0.
struct Tally
{
  std::string what;
  int cases = 0;
  int wrong = 0;
  int naiveWrong = 0;
  int zeros = 0;

  void check(int exact, double got, double naive, const std::vector<Point>& pts)
  {
    ++cases;
    zeros += exact == 0;
    naiveWrong += sign(naive) != exact;
    if (sign(got) == exact && (exact != 0 || got == 0.0))
      return;
    if (++wrong <= 5)
    {
      std::string msg =
        what + ": exact sign " + std::to_string(exact) + ", got " + std::to_string(got) + " for";
      for (const Point& p : pts)
        msg += " " + str(p);
      ADD_FAILURE() << msg;
    }
  }
  void orient(const Point& a, const Point& b, const Point& c)
  {
    check(exactOrient(a, b, c), osm::orient2d(a, b, c), naiveOrient(a, b, c), { a, b, c });
  }
  void incircle(const Point& a, const Point& b, const Point& c, const Point& d)
  {
    check(exactIncircle(a, b, c, d), osm::incircle(a, b, c, d), naiveIncircle(a, b, c, d),
      { a, b, c, d });
  }
  // Every case right; for a near-degenerate set, also proof that the set is hard.
  void expectAllRight(bool mustDefeatNaive) const
  {
    EXPECT_EQ(wrong, 0) << what << ": " << wrong << " of " << cases << " signs wrong";
    if (mustDefeatNaive)
    {
      EXPECT_GT(naiveWrong, 0) << what << ": too easy, a naive determinant gets all " << cases
                               << " right";
    }
    if (std::getenv("OSM_PREDICATES_VERBOSE"))
      std::printf("  %-34s %6d cases, %5d exact zeros, naive wrong %5d\n", what.c_str(), cases,
        zeros, naiveWrong);
  }
};

// Integer points on the circle x^2 + y^2 = r^2 (5525 = 5^2 * 13 * 17 has 180 of them).
std::vector<Point> latticeCircle(int r)
{
  std::vector<Point> pts;
  const long long r2 = static_cast<long long>(r) * r;
  for (long long x = -r; x <= r; ++x)
  {
    const long long y = std::llround(std::sqrt(static_cast<double>(r2 - x * x)));
    if (x * x + y * y == r2)
    {
      pts.push_back({ static_cast<double>(x), static_cast<double>(y) });
      if (y != 0)
        pts.push_back({ static_cast<double>(x), static_cast<double>(-y) });
    }
  }
  return pts;
}

// Four distinct indices in random order.
std::array<int, 4> pickFour(Rng& rng, int n)
{
  std::array<int, 4> k{};
  for (int i = 0; i < 4; ++i)
  {
    bool fresh = false;
    while (!fresh)
    {
      k[i] = rng.integer(0, n - 1);
      fresh = true;
      for (int j = 0; j < i; ++j)
        fresh = fresh && k[j] != k[i];
    }
  }
  return k;
}

// ---- orient2d ---------------------------------------------------------------------------------

TEST(Orient2d, KnownSigns)
{
  const Point o{ 0, 0 }, x{ 1, 0 }, y{ 0, 1 };
  EXPECT_GT(osm::orient2d(o, x, y), 0);
  EXPECT_LT(osm::orient2d(o, y, x), 0);
  EXPECT_EQ(osm::orient2d(o, x, { 2, 0 }), 0.0);
  EXPECT_EQ(osm::orient2d(o, o, y), 0.0);
  EXPECT_EQ(osm::orientSign(o, x, y), 1);
  EXPECT_EQ(osm::orientSign(x, o, y), -1);
  // The smallest possible turn: one ulp off the line y = x near 1.
  EXPECT_GT(osm::orient2d({ 0, 0 }, { 1, 1 }, { 0.5, std::nextafter(0.5, 1.0) }), 0);
  EXPECT_LT(osm::orient2d({ 0, 0 }, { 1, 1 }, { 0.5, std::nextafter(0.5, 0.0) }), 0);
}

TEST(Orient2d, RandomWellSeparated)
{
  Rng rng(0x0A11CE);
  for (const Frame& f : orientFrames)
  {
    Tally t{ std::string("random, ") + f.name };
    for (int i = 0; i < 4000; ++i)
    {
      const auto p = [&]() { return f({ rng.uniform(-100, 100), rng.uniform(-100, 100) }); };
      const Point a = p(), b = p(), c = p();
      t.orient(a, b, c);
    }
    t.expectAllRight(false);
  }
}

// Shewchuk's classic picture: a 256 x 256 ulp grid of points next to the line through
// (12, 12) and (24, 24); a naive determinant gets a large fraction of them wrong.
TEST(Orient2d, UlpGridNearDiagonal)
{
  Tally t{ "ulp grid near (0.5, 0.5)" };
  const Point b{ 12, 12 }, c{ 24, 24 };
  double x = 0.5;
  for (int i = 0; i < 256; ++i, x = std::nextafter(x, 1.0))
  {
    double y = 0.5;
    for (int j = 0; j < 256; ++j, y = std::nextafter(y, 1.0))
      t.orient({ x, y }, b, c);
  }
  t.expectAllRight(true);
  EXPECT_EQ(t.zeros, 256); // exactly the points with x == y are collinear
}

// Three points on y = x, each coordinate then moved by up to 3 ulps; one case in eight is left
// unperturbed and so exactly collinear.
TEST(Orient2d, PerturbedDiagonal)
{
  Rng rng(0xD1A6);
  for (const Frame& f : orientFrames)
  {
    Tally t{ std::string("diagonal, ") + f.name };
    for (int i = 0; i < 4000; ++i)
    {
      const int spread = rng.integer(0, 7) == 0 ? 0 : 3;
      const auto p = [&]() {
        const double s = f({ rng.uniform(-100, 100), 0 }).x;
        return perturb({ s, s }, rng, spread);
      };
      const Point a = p(), b = p(), c = p();
      t.orient(a, b, c);
    }
    t.expectAllRight(f.hard);
    EXPECT_GT(t.zeros, 0) << t.what;
  }
}

// c = a + s (b - a) rounded to doubles: collinear up to one rounding, at arbitrary slopes.
TEST(Orient2d, ArbitrarySlopeLines)
{
  Rng rng(0x51093);
  for (const Frame& f : orientFrames)
  {
    Tally t{ std::string("line, ") + f.name };
    for (int i = 0; i < 4000; ++i)
    {
      const Point a = f({ rng.uniform(-100, 100), rng.uniform(-100, 100) });
      const Point b = f({ rng.uniform(-100, 100), rng.uniform(-100, 100) });
      const double s = rng.uniform(-1, 2);
      const Point c{ a.x + s * (b.x - a.x), a.y + s * (b.y - a.y) };
      t.orient(a, b, c);
      t.orient(perturb(a, rng, 1), b, c);
    }
    t.expectAllRight(f.hard);
  }
}

// orient2dAccurate places crossing points, so its magnitude, not only its sign, must be right:
// within 2 units in the last place of the exact determinant, on near-collinear sets where the
// filtered orient2d's magnitude is often far off (which the test requires, to show it is hard).
TEST(Orient2d, AccurateMagnitudeNearLines)
{
  Rng rng(0xACC);
  // And coordinates below 2^-1000, which the exact arithmetic lifts first.
  std::vector<Frame> frames = orientFrames;
  frames.push_back({ "scale 1e-306", 0.0, 1e-306, true });
  for (const Frame& f : frames)
  {
    if (f.scale > 1e150)
      continue; // the determinant itself would overflow a double
    // Below, it underflows to 0 or a subnormal, which the accurate value
    // must be too (a mutation test: a wrong rescaling there gave 1e-262).
    int estimateFarOff = 0;
    for (int i = 0; i < 4000; ++i)
    {
      const Point a = f({ rng.uniform(-100, 100), rng.uniform(-100, 100) });
      const Point b = f({ rng.uniform(-100, 100), rng.uniform(-100, 100) });
      const double s = rng.uniform(-1, 2);
      const Point c = perturb({ a.x + s * (b.x - a.x), a.y + s * (b.y - a.y) }, rng, 4);
      const mpq_class acx = mpq_class(a.x) - mpq_class(c.x), acy = mpq_class(a.y) - mpq_class(c.y);
      const mpq_class bcx = mpq_class(b.x) - mpq_class(c.x), bcy = mpq_class(b.y) - mpq_class(c.y);
      const mpq_class determinant = acx * bcy - acy * bcx;
      const double exact = determinant.get_d();
      const double accurate = osm::orient2dAccurate(a, b, c);
      if (sgn(determinant) == 0)
      {
        EXPECT_EQ(accurate, 0.0) << f.name << str(a) << str(b) << str(c);
        continue;
      }
      // (Plus two of the smallest subnormals: tiny frames give subnormal determinants.)
      EXPECT_LE(std::fabs(accurate - exact), 0x1p-51 * std::fabs(exact) + 0x1p-1073)
        << f.name << str(a) << str(b) << str(c) << " exact " << exact << " got " << accurate;
      if (std::fabs(osm::orient2d(a, b, c) - exact) > 1e-3 * std::fabs(exact))
        ++estimateFarOff;
    }
    if (f.hard)
      EXPECT_GT(estimateFarOff, 0) << f.name << ": no case where orient2d's magnitude is off";
  }
}

// Exactly collinear inputs, built only from exact operations, must give exactly 0.
TEST(Orient2d, ExactlyDegenerateIsZero)
{
  Rng rng(0x2E60);
  const double scales[] = { 1.0, 0x1p-500, 0x1p-1000, 0x1p300, 0x1p900 };
  const double offsets[] = { 0.0, 1e7, 1e15 };
  int cases = 0;
  for (const double sc : scales)
    for (const double off : offsets)
      for (int i = 0; i < 500; ++i)
      {
        // Integer points on y = m x + q with small integers (exact in doubles), then an exact
        // translation (integers below 2^53) or an exact power-of-two scaling.
        const int m = rng.integer(-7, 7), q = rng.integer(-50, 50);
        const auto p = [&]() {
          const double x = rng.integer(-1000, 1000);
          return sc == 1.0 ? Point{ off + x, off + m * x + q } : Point{ sc * x, sc * (m * x + q) };
        };
        const Point a = p(), b = p(), c = p();
        ASSERT_EQ(exactOrient(a, b, c), 0);
        EXPECT_EQ(osm::orient2d(a, b, c), 0.0) << str(a) << str(b) << str(c);
        EXPECT_EQ(osm::orient2d(a, a, c), 0.0);
        ++cases;
      }
  EXPECT_EQ(cases, 7500);
}

// ---- incircle ---------------------------------------------------------------------------------

TEST(Incircle, KnownSigns)
{
  const Point a{ 0, 0 }, b{ 1, 0 }, c{ 0, 1 };
  EXPECT_GT(osm::incircle(a, b, c, { 0.25, 0.25 }), 0); // inside, abc counter-clockwise
  EXPECT_LT(osm::incircle(a, b, c, { 2, 2 }), 0);       // outside
  EXPECT_EQ(osm::incircle(a, b, c, { 1, 1 }), 0.0);     // the fourth corner of the square
  EXPECT_LT(osm::incircle(a, c, b, { 0.25, 0.25 }), 0); // clockwise flips the sign
  EXPECT_EQ(osm::incircle(a, b, c, a), 0.0);
  EXPECT_GT(osm::incircle(a, b, c, { 1, std::nextafter(1.0, 0.0) }), 0);
  EXPECT_LT(osm::incircle(a, b, c, { 1, std::nextafter(1.0, 2.0) }), 0);
}

TEST(Incircle, RandomWellSeparated)
{
  Rng rng(0x1C1C);
  for (const Frame& f : incircleFrames)
  {
    Tally t{ std::string("random, ") + f.name };
    for (int i = 0; i < 4000; ++i)
    {
      const auto p = [&]() { return f({ rng.uniform(-100, 100), rng.uniform(-100, 100) }); };
      const Point a = p(), b = p(), c = p(), d = p();
      t.incircle(a, b, c, d);
    }
    t.expectAllRight(false);
  }
}

// Corners of an axis-aligned square, in random order, perturbed by up to 2 ulps.
TEST(Incircle, PerturbedSquare)
{
  Rng rng(0x5055);
  for (const Frame& f : incircleFrames)
  {
    Tally t{ std::string("square, ") + f.name };
    for (int i = 0; i < 4000; ++i)
    {
      const double cx = rng.uniform(-50, 50), cy = rng.uniform(-50, 50), h = rng.uniform(1, 50);
      const Point corner[4] = { { cx - h, cy - h }, { cx + h, cy - h }, { cx + h, cy + h },
        { cx - h, cy + h } };
      const std::array<int, 4> k = pickFour(rng, 4);
      const auto p = [&](int j) { return perturb(f(corner[k[j]]), rng, 2); };
      t.incircle(p(0), p(1), p(2), p(3));
    }
    t.expectAllRight(f.hard);
  }
}

// Four of the 180 integer points of a Pythagorean circle, perturbed by up to 3 ulps; one case in
// eight is left unperturbed, which stays exactly cocircular in the frames that are exact here.
TEST(Incircle, PerturbedPythagoreanCircle)
{
  const std::vector<Point> circle = latticeCircle(5525);
  ASSERT_EQ(circle.size(), 180u);
  Rng rng(0x9E3779B9);
  for (const Frame& f : incircleFrames)
  {
    Tally t{ std::string("pythagorean, ") + f.name };
    for (int i = 0; i < 4000; ++i)
    {
      const Point centre{ static_cast<double>(rng.integer(-9999, 9999)),
        static_cast<double>(rng.integer(-9999, 9999)) };
      const std::array<int, 4> k = pickFour(rng, static_cast<int>(circle.size()));
      const int spread = rng.integer(0, 7) == 0 ? 0 : 3;
      const auto p = [&](int j) {
        const Point q{ centre.x + circle[k[j]].x, centre.y + circle[k[j]].y };
        return perturb(f(q), rng, spread);
      };
      t.incircle(p(0), p(1), p(2), p(3));
    }
    t.expectAllRight(f.hard);
    if (f.scale == 1.0) // integer coordinates below 2^53: the translation is exact
    {
      EXPECT_GT(t.zeros, 400) << t.what;
    }
  }
}

// Points at arbitrary angles on a circle, rounded to doubles: cocircular up to rounding.
TEST(Incircle, ArbitraryAngleCircle)
{
  Rng rng(0xC0C1);
  for (const Frame& f : incircleFrames)
  {
    Tally t{ std::string("angles, ") + f.name };
    for (int i = 0; i < 4000; ++i)
    {
      const double cx = rng.uniform(-50, 50), cy = rng.uniform(-50, 50), r = rng.uniform(1, 50);
      const auto p = [&]() {
        const double th = rng.uniform(0, 6.283185307179586);
        return f({ cx + r * std::cos(th), cy + r * std::sin(th) });
      };
      t.incircle(p(), p(), p(), p());
    }
    t.expectAllRight(f.hard);
  }
}

// Exactly cocircular inputs, built only from exact operations, must give exactly 0.
TEST(Incircle, ExactlyDegenerateIsZero)
{
  const std::vector<Point> circle = latticeCircle(5525);
  Rng rng(0x0C1C);
  const double scales[] = { 1.0, 0x1p-500, 0x1p-800, 0x1p200, 0x1p800 };
  const double offsets[] = { 0.0, 1e7, 1e15 };
  int cases = 0;
  for (const double sc : scales)
    for (const double off : offsets)
      for (int i = 0; i < 300; ++i)
      {
        const double cx = rng.integer(-9999, 9999), cy = rng.integer(-9999, 9999);
        const std::array<int, 4> k = pickFour(rng, static_cast<int>(circle.size()));
        const auto p = [&](int j) {
          const Point q{ cx + circle[k[j]].x, cy + circle[k[j]].y };
          return sc == 1.0 ? Point{ off + q.x, off + q.y } : Point{ sc * q.x, sc * q.y };
        };
        const Point a = p(0), b = p(1), c = p(2), d = p(3);
        ASSERT_EQ(exactIncircle(a, b, c, d), 0);
        EXPECT_EQ(osm::incircle(a, b, c, d), 0.0) << str(a) << str(b) << str(c) << str(d);
        EXPECT_EQ(osm::incircle(a, b, c, b), 0.0);
        ++cases;
      }
  EXPECT_EQ(cases, 4500);
}

// ---- symmetry ---------------------------------------------------------------------------------

// Signs are invariant under cyclic permutation and flip under a transposition. Checked on
// near-degenerate inputs, where a non-exact predicate would disagree with itself.
TEST(Predicates, PermutationSymmetry)
{
  Rng rng(0x5E77);
  const std::vector<Point> circle = latticeCircle(5525);
  for (int i = 0; i < 2000; ++i)
  {
    const auto onDiagonal = [&]() {
      const double s = rng.uniform(-100, 100);
      return perturb({ s, s }, rng, 2);
    };
    const Point a = onDiagonal(), b = onDiagonal(), c = onDiagonal();
    const int o = sign(osm::orient2d(a, b, c));
    EXPECT_EQ(sign(osm::orient2d(b, c, a)), o);
    EXPECT_EQ(sign(osm::orient2d(c, a, b)), o);
    EXPECT_EQ(sign(osm::orient2d(b, a, c)), -o);
    EXPECT_EQ(sign(osm::orient2d(a, c, b)), -o);

    const std::array<int, 4> k = pickFour(rng, static_cast<int>(circle.size()));
    const auto q = [&](int j) { return perturb(circle[k[j]], rng, 1); };
    const Point p0 = q(0), p1 = q(1), p2 = q(2), p3 = q(3);
    const int s = sign(osm::incircle(p0, p1, p2, p3));
    EXPECT_EQ(sign(osm::incircle(p1, p2, p0, p3)), s);
    EXPECT_EQ(sign(osm::incircle(p2, p0, p1, p3)), s);
    EXPECT_EQ(sign(osm::incircle(p1, p0, p2, p3)), -s);
    EXPECT_EQ(sign(osm::incircle(p0, p1, p3, p2)), -s);
  }
}

} // namespace

TEST(Predicates, NonFiniteCoordinatesGiveNoSign)
{
  // A mutation test: with the fallback's finiteness check removed, infinite
  // input gave 0, "collinear", which no caller would question.
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isnan(osm::orient2d({ inf, 0 }, { 1, 0 }, { 0, 1 })));
  EXPECT_TRUE(std::isnan(osm::orient2d({ nan, 0 }, { 1, 0 }, { 0, 1 })));
  EXPECT_TRUE(std::isnan(osm::orient2dAccurate({ 1e308, 0 }, { inf, 1 }, { 0, 0 })));
  EXPECT_TRUE(std::isnan(osm::incircle({ inf, 0 }, { 1, 0 }, { 0, 1 }, { 0, 0 })));
  EXPECT_TRUE(std::isnan(osm::incircle({ 0, 0 }, { 1, 0 }, { 0, 1 }, { 0.5, -inf })));
}

TEST(Orient2d, SubnormalCoordinatesAreLiftedFirst)
{
  // Below 2^-1023 the factor to [1, 2) alone would be infinite: the exact
  // arithmetic lifts such input by 2^600 first (a mutation test: without the
  // lift every predicate gave NaN here).
  const double d = std::numeric_limits<double>::denorm_min();
  EXPECT_GT(osm::orient2d({ 0, 0 }, { 3 * d, 0 }, { 0, 5 * d }), 0);
  EXPECT_LT(osm::orient2d({ 0, 0 }, { 0, 5 * d }, { 3 * d, 0 }), 0);
  EXPECT_GT(osm::orient2dAccurate({ 0, 0 }, { 3 * d, 0 }, { 0, 5 * d }), 0);
  EXPECT_GT(osm::incircle({ 0, 0 }, { 4 * d, 0 }, { 0, 4 * d }, { d, d }), 0);
  EXPECT_LT(osm::incircle({ 0, 0 }, { 4 * d, 0 }, { 0, 4 * d }, { 5 * d, 5 * d }), 0);
}
