// Exact geometric predicates (adaptive: floating-point filter, exact fallback).
// The sign of each result is always correct; the magnitude is only an estimate.
#ifndef osm_Predicates_h
#define osm_Predicates_h

#include "Geometry.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

// The error bounds below rely on IEEE round-to-nearest double arithmetic.
#if defined(__FAST_MATH__)
#error "The OSM predicates must not be compiled with -ffast-math: they need exact IEEE rounding."
#endif
#if defined(FLT_EVAL_METHOD) && FLT_EVAL_METHOD != 0
#error "The OSM predicates need double arithmetic without extended precision (SSE2, not x87)."
#endif

namespace osm
{

/// Rounds to nearest while it lives, then restores the thread's rounding
/// mode: the predicates' error bounds, and so every mesh, assume it. A host
/// that rounds upward on the calling thread changed 94 of 112 meshes (a
/// review). The public entry points that compute geometry hold one.
class RoundToNearest
{
public:
  RoundToNearest();
  ~RoundToNearest();
  RoundToNearest(const RoundToNearest&) = delete;
  RoundToNearest& operator=(const RoundToNearest&) = delete;

private:
  int Saved;
};

namespace detail
{
// Forward error bounds of the filtered evaluations; Predicates.cxx derives them.
constexpr double kU = 0x1p-53;
constexpr double kOrientBound = (3.0 + 64.0 * kU) * kU;
constexpr double kIncircleBound = (10.0 + 512.0 * kU) * kU;
constexpr double kOrientSlack = DBL_MIN;     // covers underflowing products
constexpr double kIncircleSlack = 0x1p-1018; // times (1 + alift + blift + clift)

double orient2dFallback(const Point& a, const Point& b, const Point& c);
double incircleFallback(const Point& a, const Point& b, const Point& c, const Point& d);
} // namespace detail

/// > 0 if a, b, c turn counter-clockwise, < 0 if clockwise, 0 if collinear.
/// Inline filtered evaluation; the rare uncertain case goes to the exact fallback.
/// NaN (no sign) when a coordinate is not finite, here and in every predicate.
inline double orient2d(const Point& a, const Point& b, const Point& c)
{
  const double acx = a.x - c.x, bcx = b.x - c.x;
  const double acy = a.y - c.y, bcy = b.y - c.y;
  const double left = acx * bcy;
  const double right = acy * bcx;
  const double det = left - right;
  const double bound =
    detail::kOrientBound * (std::fabs(left) + std::fabs(right)) + detail::kOrientSlack;
  if (std::fabs(det) > bound) // false for NaN, and for inf since the bound is then inf too
    return det;
  return detail::orient2dFallback(a, b, c);
}

/// For a, b, c counter-clockwise: > 0 if d lies strictly inside their circumcircle,
/// < 0 if strictly outside, 0 if on it. (Sign flips if a, b, c are clockwise.)
inline double incircle(const Point& a, const Point& b, const Point& c, const Point& d)
{
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det =
    alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  const double permanent = alift * (std::fabs(bdxcdy) + std::fabs(cdxbdy)) +
    blift * (std::fabs(cdxady) + std::fabs(adxcdy)) +
    clift * (std::fabs(adxbdy) + std::fabs(bdxady));
  const double slack = (1.0 + alift + blift + clift) * detail::kIncircleSlack;
  if (std::fabs(det) > detail::kIncircleBound * permanent + slack)
    return det;
  return detail::incircleFallback(a, b, c, d);
}

/// The determinant orient2d signs, with its magnitude too within about one
/// unit in the last place (evaluated exactly, then rounded): for computing
/// where two lines cross, where orient2d's estimate can be far off.
double orient2dAccurate(const Point& a, const Point& b, const Point& c);

inline int orientSign(const Point& a, const Point& b, const Point& c)
{
  const double o = orient2d(a, b, c);
  return (o > 0) - (o < 0);
}

/// x lies on the line through a and b exactly, or so close that a point
/// constructed on that line near x (a crossing with an edge of about
/// `length`) would round onto x: within a few ulps of x's coordinates plus of
/// `length`. Used to snap such vertices onto segments, a repair within rounding.
/// Takes o = orient2d(a, b, x) (exact sign, magnitude within a factor of 2)
/// and |b - a| (std::hypot), which a caller testing many points against one
/// line computes once. ulps: the tolerance in units of rounding.
inline bool onLineWithinRounding(
  double o, const Point& x, double length, double abLength, double ulps = 8)
{
  if (o == 0)
    return true;
  // (std::max, not std::fmax, a library call: the coordinates are finite.)
  const double scale = std::max(std::fabs(x.x), std::fabs(x.y)) + length;
  const double tolerance = ulps * DBL_EPSILON * scale;
  return std::fabs(o) <= tolerance * abLength;
}

} // namespace osm

#endif
