// Adaptive exact predicates: a floating-point evaluation certified by a forward error bound,
// with an exact fallback in floating-point expansion arithmetic when the bound cannot decide.
//
// Requirements on the floating-point environment (checked below where the compiler can tell):
// IEEE-754 binary64 with round-to-nearest-even, no extended-precision intermediates (no x87;
// SSE2 on x86-64 is the default), and no value-changing optimisations (-ffast-math,
// -fassociative-math, MSVC /fp:fast) because the error-free transformations rely on the exact
// rounding of every single operation. FMA contraction (-ffp-contract=fast) is harmless: it only
// removes roundings, so both the error bounds and the error-free transformations still hold.
//
// Range of exactness. The filters are rigorous for all finite inputs, including underflow
// (absolute slack terms) and overflow (an infinite or NaN intermediate never certifies). The exact
// fallback first rescales the coordinates by a power of two so the largest magnitude lies in
// [1, 2) (exact, and cheap; the core already normalises coordinates by a power of two upstream, so
// this only matters for callers with extreme magnitudes). After that no intermediate can overflow,
// and the result is exact as long as no product loses bits below the smallest subnormal 2^-1074,
// which holds when every scaled coordinate is a multiple of 2^-537 (orient2d, degree 2) or 2^-268
// (incircle, degree 4). Sufficient condition: every nonzero coordinate is at least 2^-485
// (orient2d) or 2^-216 (incircle) times the largest one, and no coordinate underflows when scaled
// down. Inputs must be finite (NaN is returned otherwise).
#include "Predicates.h"

#include <algorithm>
#include <array>
#include <cfenv>
#include <cfloat>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

// (The header refuses -ffast-math and x87 arithmetic at compile time.)

// The exact fallbacks stay out of line so the filtered fast paths remain small, and are entered
// through cold wrappers so the fast paths are laid out for the common case. The exact code itself
// is not cold: GCC optimises cold code for size and would stop inlining the error-free
// transformations.
#if defined(__GNUC__)
#define OSM_NOINLINE __attribute__((noinline))
#define OSM_COLD __attribute__((noinline, cold))
#elif defined(_MSC_VER)
#define OSM_NOINLINE __declspec(noinline)
#define OSM_COLD __declspec(noinline)
#else
#define OSM_NOINLINE
#define OSM_COLD
#endif

namespace osm
{

RoundToNearest::RoundToNearest()
  : Saved(std::fegetround())
{
  if (this->Saved != FE_TONEAREST)
    std::fesetround(FE_TONEAREST);
}

RoundToNearest::~RoundToNearest()
{
  if (this->Saved != FE_TONEAREST)
    std::fesetround(this->Saved);
}

namespace
{

// ---------------------------------------------------------------------------------------------
// Filter constants.
//
// u is the unit roundoff. Writing each computed monomial as its exact value times (1 + theta_k),
// |theta_k| <= gamma_k = k u / (1 - k u), where k counts the roundings on its path, the value
// before the last operation (whose rounding cannot change the sign) differs from the exact
// determinant by at most gamma_k times the sum of the monomial magnitudes (the "permanent").
// The computed permanent under-estimates that sum by at most gamma_k' relatively, and computing
// the bound itself costs two more roundings. Hence:
//   orient2d: k = 3 (difference, difference, product), k' = 4:  need 3u + 30u^2 + O(u^3).
//   incircle: k = 10 (e.g. adx, adx, square, lift sum, bdx, cdy, product, cross difference,
//             lift * cross, first of the two final sums), k' = 11: need 10u + 240u^2 + O(u^3).
// The constants (in Predicates.h) round those up generously; the margin costs nothing measurable.

// Products that underflow have an absolute (not relative) error of at most 2^-1075 each, and
// additions that underflow are exact. For orient2d that adds at most ~2^-1073 to the error, far
// below DBL_MIN. For incircle the absolute errors of the first-level products are amplified by
// the lifts and cross terms; since |bdx*cdy| + |cdx*bdy| <= (blift + clift) / 2, all of it is
// bounded by a few 2^-1074 * (1 + alift + blift + clift). Both slacks are normal numbers (no slow
// subnormal arithmetic on the hot path) and far too small to matter for ordinary inputs.

// ---------------------------------------------------------------------------------------------
// Error-free transformations: hi is the rounded result and hi + lo the exact one.

struct TwoTerm
{
  double hi;
  double lo;
};

// Knuth's branch-free two-sum: exact for any finite a, b whose sum does not overflow.
inline TwoTerm twoSum(double a, double b)
{
  const double s = a + b;
  const double bVirtual = s - a;
  const double aVirtual = s - bVirtual;
  return { s, (a - aVirtual) + (b - bVirtual) };
}

// Negation is exact, so a difference is a sum.
inline TwoTerm twoDiff(double a, double b)
{
  return twoSum(a, -b);
}

// The fused multiply-add computes a*b - p with a single rounding, and that value is representable
// (it is the low half of the 106-bit exact product) unless it falls below 2^-1074.
inline TwoTerm twoProd(double a, double b)
{
  const double p = a * b;
  return { p, std::fma(a, b, -p) };
}

// ---------------------------------------------------------------------------------------------
// Expansions: a value represented exactly as an unevaluated sum of doubles, stored in order of
// increasing magnitude, without zeros, with strongly nonoverlapping components (Priest, Shewchuk).
// The capacity N is a compile-time upper bound on the length, so every intermediate of the exact
// predicates lives in a fixed-size stack array; no heap allocation ever happens.

template <int N>
struct Expansion
{
  std::array<double, N> c; // deliberately not zero-filled: only c[0, n) is ever read
  int n = 0;

  Expansion() = default;
  // Copy only the live components: cheaper, and never reads the uninitialised tail.
  Expansion(const Expansion& o)
    : n(o.n)
  {
    std::copy_n(o.c.data(), o.n, c.data());
  }
  Expansion& operator=(const Expansion& o)
  {
    n = o.n;
    std::copy_n(o.c.data(), o.n, c.data());
    return *this;
  }

  // Append unless zero. Branch-free: the slot is always written, which is safe because no
  // operation pushes more values than the capacity, zero or not.
  void push(double x)
  {
    c[n] = x;
    n += x != 0.0;
  }
  // The largest component dominates the sum of all the others, so it carries the sign. Its
  // magnitude can be off by up to a factor of 2 (a power of two above a long tail).
  double top() const { return n > 0 ? c[n - 1] : 0.0; }
  // The value rounded to within about one unit in the last place: the components summed from
  // the smallest, each below the last bit of the next, so no partial sum loses more than that.
  double sum() const
  {
    double s = 0.0;
    for (int i = 0; i < n; ++i)
      s += c[i];
    return s;
  }
};

// h = e + fSign * f for raw arrays of lengths n and m (fSign = +-1, so the scaling is exact); h
// must have room for n + m and not alias e or f. Shewchuk's fast expansion sum, which needs
// round-to-even and strongly nonoverlapping inputs, and keeps that property: merge both inputs by
// magnitude, then sweep a running sum through two-sums, emitting each rounding error as a
// component and dropping zeros.
int mergeSum(const double* e, int n, const double* f, int m, double* h, double fSign)
{
  // Merge into h itself. The select is written so the compiler can avoid a branch: which input
  // wins is data dependent and would be mispredicted about half the time.
  int i = 0, j = 0, k = 0;
  while (i < n && j < m)
  {
    const double a = e[i], b = fSign * f[j];
    const bool takeE = std::fabs(a) < std::fabs(b);
    h[k++] = takeE ? a : b;
    i += takeE;
    j += !takeE;
  }
  while (i < n)
    h[k++] = e[i++];
  while (j < m)
    h[k++] = fSign * f[j++];

  // The sweep runs in place: the component written at index out <= t - 1 never overtakes the
  // merged value read at index t.
  if (k == 0)
    return 0;
  int out = 0;
  double q = h[0];
  for (int t = 1; t < k; ++t)
  {
    const TwoTerm s = twoSum(q, h[t]);
    h[out] = s.lo; // kept only if nonzero, without a branch
    out += s.lo != 0.0;
    q = s.hi;
  }
  h[out] = q;
  return out + (q != 0.0);
}

template <int N, int M>
Expansion<N + M> operator+(const Expansion<N>& e, const Expansion<M>& f)
{
  Expansion<N + M> h;
  h.n = mergeSum(e.c.data(), e.n, f.c.data(), f.n, h.c.data(), 1.0);
  return h;
}

template <int N, int M>
Expansion<N + M> operator-(const Expansion<N>& e, const Expansion<M>& f)
{
  Expansion<N + M> h;
  h.n = mergeSum(e.c.data(), e.n, f.c.data(), f.n, h.c.data(), -1.0);
  return h;
}

// h = b * e: multiply component by component and fold the two-product results into a running sum
// from the smallest magnitude up (Shewchuk's scale-expansion with zero elimination).
template <int N>
Expansion<2 * N> scale(const Expansion<N>& e, double b)
{
  Expansion<2 * N> h;
  if (e.n == 0 || b == 0.0)
    return h;
  TwoTerm p = twoProd(e.c[0], b);
  h.push(p.lo);
  double q = p.hi;
  for (int i = 1; i < e.n; ++i)
  {
    p = twoProd(e.c[i], b);
    const TwoTerm s1 = twoSum(q, p.lo);
    h.push(s1.lo);
    const TwoTerm s2 = twoSum(p.hi, s1.hi);
    h.push(s2.lo);
    q = s2.hi;
  }
  h.push(q);
  return h;
}

// e * f as the sum of e scaled by each component of f. Two buffers alternate as source and
// destination of the running sum; starting on the right one makes the last sum land in `out`.
template <int N, int M>
Expansion<2 * N * M> operator*(const Expansion<N>& e, const Expansion<M>& f)
{
  Expansion<2 * N * M> out;
  std::array<double, 2 * N * M> spare;
  double* acc = f.n % 2 == 0 ? out.c.data() : spare.data();
  double* dst = f.n % 2 == 0 ? spare.data() : out.c.data();
  int len = 0;
  for (int j = 0; j < f.n; ++j)
  {
    const Expansion<2 * N> part = scale(e, f.c[j]);
    if (j == 0) // nothing to add to yet
    {
      std::copy_n(part.c.data(), part.n, dst);
      len = part.n;
    }
    else
      len = mergeSum(acc, len, part.c.data(), part.n, dst, 1.0);
    std::swap(acc, dst);
  }
  out.n = len;
  return out;
}

// ---------------------------------------------------------------------------------------------
// Exact fallbacks. Stages, cheapest first: the exact determinant of the rounded differences (the
// answer when no difference was rounded), then for incircle a first-order correction for their
// rounding errors with its own error bound, and finally the full expansion of the exact
// differences (orient2d goes there directly when a difference was rounded).

// Rescale the coordinates by 2^-shift so the largest magnitude lies in [1, 2). Multiplying by a
// power of two is exact barring underflow, and the sign of a homogeneous polynomial is unchanged.
// One factor multiplies everything (cheaper than a library call per coordinate); subnormal input
// is first lifted by an exact 2^600 so that the factor itself stays finite.
template <std::size_t K>
bool normalise(std::array<double, K>& v, int& shift)
{
  double largest = 0.0;
  for (const double x : v)
  {
    if (!std::isfinite(x))
      return false;
    largest = std::max(largest, std::fabs(x));
  }
  shift = 0;
  if (largest == 0.0)
    return true;
  if (largest < 0x1p-1000)
  {
    for (double& x : v)
      x *= 0x1p600;
    largest *= 0x1p600;
    shift = -600;
  }
  const int e = std::ilogb(largest);
  const double factor = std::ldexp(1.0, -e);
  for (double& x : v)
    x *= factor;
  shift += e;
  return true;
}

// Undo the scaling of a degree-d result for the magnitude estimate, never losing its sign.
double restore(double value, int shift, int degree)
{
  const double r = std::scalbn(value, degree * shift);
  if (r == 0.0 && value != 0.0)
    return std::copysign(std::numeric_limits<double>::denorm_min(), value);
  return r;
}

// Coordinate differences of the scaled input, each split into rounded value and exact tail.
template <std::size_t K>
using Differences = std::array<TwoTerm, K>;

bool tailsAreZero(const TwoTerm* d, std::size_t k)
{
  return std::all_of(d, d + k, [](const TwoTerm& t) { return t.lo == 0.0; });
}

// The differences as expansions: the rounded value alone (K = 1) or value plus tail (K = 2).
template <int K>
Expansion<K> asExpansion(const TwoTerm& t)
{
  Expansion<K> e;
  if constexpr (K == 2)
    e.push(t.lo);
  e.push(t.hi);
  return e;
}

// The determinants in expansion arithmetic, generic in the length K of the differences. The
// result capacities follow from the operand types: orient2d 8 K^2, incircle 96 K^4 (96 or 1536,
// about 12 KiB of stack for the latter). Zero elimination keeps the actual lengths much shorter.
template <int K>
auto orientDeterminant(const Differences<4>& d)
{
  const Expansion<K> acx = asExpansion<K>(d[0]), acy = asExpansion<K>(d[1]);
  const Expansion<K> bcx = asExpansion<K>(d[2]), bcy = asExpansion<K>(d[3]);
  return acx * bcy - acy * bcx;
}

template <int K>
auto incircleDeterminant(const Differences<6>& d)
{
  const Expansion<K> adx = asExpansion<K>(d[0]), ady = asExpansion<K>(d[1]);
  const Expansion<K> bdx = asExpansion<K>(d[2]), bdy = asExpansion<K>(d[3]);
  const Expansion<K> cdx = asExpansion<K>(d[4]), cdy = asExpansion<K>(d[5]);
  const auto bc = bdx * cdy - cdx * bdy;
  const auto ca = cdx * ady - adx * cdy;
  const auto ab = adx * bdy - bdx * ady;
  // lift * cross as cross * dx * dx + cross * dy * dy: for single-component differences these are
  // chains of linear-time scalings instead of a quadratic expansion product.
  const auto lifted = [](const auto& cross, const auto& dx, const auto& dy) {
    return (cross * dx) * dx + (cross * dy) * dy;
  };
  return lifted(bc, adx, ady) + lifted(ca, bdx, bdy) + lifted(ab, cdx, cdy);
}

// Between the exact determinant of the rounded differences h and the fully exact one: with t the
// tails (|t| <= u |h|), det(h + t) = det(h) + F + R, where F is linear in the tails and R holds
// the terms with two or more. det(h) is known exactly (head); F is evaluated in floating point.
// Bounds, with P the permanent of h (sum of |monomials|, estimated by the computed one to within
// gamma_7): |R| <= ((1 + u)^4 - 1 - 4u) P <= 7u^2 P; |F - F~| <= gamma_9 * 4u P; summing the n <=
// 96 head components costs gamma_95 times their absolute sum. The constants round these up, and the
// absolute slack covers underflow (all magnitudes are bounded after scaling). This resolves nearly
// every case whose differences are inexact (e.g. points on a circular arc) at a small fraction of
// the cost of the full expansion. Returns nothing if it cannot decide.
std::optional<double> incircleFirstOrder(const Expansion<96>& head, const Differences<6>& d)
{
  const double adx = d[0].hi, ady = d[1].hi, bdx = d[2].hi, bdy = d[3].hi;
  const double cdx = d[4].hi, cdy = d[5].hi;
  const double adxt = d[0].lo, adyt = d[1].lo, bdxt = d[2].lo, bdyt = d[3].lo;
  const double cdxt = d[4].lo, cdyt = d[5].lo;

  double estimate = 0.0, magnitude = 0.0;
  for (int i = 0; i < head.n; ++i)
  {
    estimate += head.c[i];
    magnitude += std::fabs(head.c[i]);
  }

  const double bc = bdx * cdy - cdx * bdy, ca = cdx * ady - adx * cdy, ab = adx * bdy - bdx * ady;
  const double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  // Row by row, d(lift * cross) = lift * dcross + dlift * cross.
  const double dbc = (bdx * cdyt + cdy * bdxt) - (cdx * bdyt + bdy * cdxt);
  const double dca = (cdx * adyt + ady * cdxt) - (adx * cdyt + cdy * adxt);
  const double dab = (adx * bdyt + bdy * adxt) - (bdx * adyt + ady * bdxt);
  const double dalift = 2.0 * (adx * adxt + ady * adyt);
  const double dblift = 2.0 * (bdx * bdxt + bdy * bdyt);
  const double dclift = 2.0 * (cdx * cdxt + cdy * cdyt);
  const double firstOrder =
    (alift * dbc + dalift * bc) + (blift * dca + dblift * ca) + (clift * dab + dclift * ab);

  const double permanent = alift * (std::fabs(bdx * cdy) + std::fabs(cdx * bdy)) +
    blift * (std::fabs(cdx * ady) + std::fabs(adx * cdy)) +
    clift * (std::fabs(adx * bdy) + std::fabs(bdx * ady));
  const double bound = 0x1p-46 * magnitude + 0x1p-100 * permanent + 0x1p-1000; // 128u, 64u^2
  const double value = estimate + firstOrder;
  if (std::fabs(value) > bound)
    return value;
  return std::nullopt;
}

// The orientation determinant evaluated exactly; rounded (accurate) or only its top component.
OSM_NOINLINE double orient2dExact(const Point& a, const Point& b, const Point& c, bool rounded)
{
  std::array<double, 6> v{ a.x, a.y, b.x, b.y, c.x, c.y };
  int shift = 0;
  if (!normalise(v, shift))
    return std::numeric_limits<double>::quiet_NaN();
  const Differences<4> d{ twoDiff(v[0], v[4]), twoDiff(v[1], v[5]), twoDiff(v[2], v[4]),
    twoDiff(v[3], v[5]) };
  const auto value = [rounded](const auto& e) { return rounded ? e.sum() : e.top(); };
  const double det = tailsAreZero(d.data(), d.size()) ? value(orientDeterminant<1>(d))
                                                      : value(orientDeterminant<2>(d));
  return restore(det, shift, 2);
}

OSM_NOINLINE double incircleExact(const Point& a, const Point& b, const Point& c, const Point& d)
{
  std::array<double, 8> v{ a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y };
  int shift = 0;
  if (!normalise(v, shift))
    return std::numeric_limits<double>::quiet_NaN();
  const Differences<6> diff{ twoDiff(v[0], v[6]), twoDiff(v[1], v[7]), twoDiff(v[2], v[6]),
    twoDiff(v[3], v[7]), twoDiff(v[4], v[6]), twoDiff(v[5], v[7]) };
  const Expansion<96> head = incircleDeterminant<1>(diff);
  if (tailsAreZero(diff.data(), diff.size())) // common for nearby points: head is exact
    return restore(head.top(), shift, 4);
  if (const std::optional<double> det = incircleFirstOrder(head, diff))
    return restore(*det, shift, 4);
  return restore(incircleDeterminant<2>(diff).top(), shift, 4);
}

} // namespace

// ---------------------------------------------------------------------------------------------
// The exact fallbacks of the inline filtered predicates in Predicates.h: reached only when the
// filter cannot certify the sign (near-degenerate input, exact degeneracy, overflow).

namespace detail
{

OSM_COLD double orient2dFallback(const Point& a, const Point& b, const Point& c)
{
  return orient2dExact(a, b, c, false);
}

OSM_COLD double incircleFallback(const Point& a, const Point& b, const Point& c, const Point& d)
{
  return incircleExact(a, b, c, d);
}

} // namespace detail

double orient2dAccurate(const Point& a, const Point& b, const Point& c)
{
  return orient2dExact(a, b, c, true);
}

} // namespace osm
