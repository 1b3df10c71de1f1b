// Sine, cosine and arcsine by their Taylor series, for the few constants the
// mesher derives from the overlay's minimum angle and for the filter of its
// angle statistics.
//
// Why not libm: its first call in a process faults in its code and tables one
// page at a time, which took 0.13-0.3 ms for sin and asin together on the
// benchmark machine, a quarter of the time of meshing a small input. These
// are a few multiply-adds, and do not depend on the platform's libm. They are
// for the ranges below only; atan2, used on every mesh angle, stays libm's.
#ifndef osm_Series_h
#define osm_Series_h

#include <array>
#include <cstddef>

namespace osm
{
namespace series
{

/// The double nearest to π (std::acos(-1.0)).
constexpr double kPi = 3.141592653589793;

namespace detail
{
constexpr std::size_t kTerms = 16;

/// (-1)^k / (2k + 1)! for k = 1 ... kTerms: the sine's terms after x.
constexpr std::array<double, kTerms> sineCoefficients()
{
  std::array<double, kTerms> c{};
  double f = 1.0;
  for (std::size_t k = 1; k <= kTerms; ++k)
  {
    f /= -static_cast<double>((2 * k) * (2 * k + 1));
    c[k - 1] = f;
  }
  return c;
}

/// (-1)^k / (2k)! for k = 1 ... kTerms: the cosine's terms after 1.
constexpr std::array<double, kTerms> cosineCoefficients()
{
  std::array<double, kTerms> c{};
  double f = 1.0;
  for (std::size_t k = 1; k <= kTerms; ++k)
  {
    f /= -static_cast<double>((2 * k - 1) * (2 * k));
    c[k - 1] = f;
  }
  return c;
}

constexpr std::size_t kArcsineTerms = 32;

/// (2k)! / (4^k (k!)^2 (2k + 1)) for k = 1 ... kArcsineTerms: the arcsine's
/// terms after z.
constexpr std::array<double, kArcsineTerms> arcsineCoefficients()
{
  std::array<double, kArcsineTerms> c{};
  double central = 1.0; // (2k)! / (4^k (k!)^2)
  for (std::size_t k = 1; k <= kArcsineTerms; ++k)
  {
    central *= static_cast<double>(2 * k - 1) / static_cast<double>(2 * k);
    c[k - 1] = central / static_cast<double>(2 * k + 1);
  }
  return c;
}

/// c[0] + c[1] t + c[2] t^2 + ..., by Horner's rule from the smallest term.
template <std::size_t N>
constexpr double horner(const std::array<double, N>& c, double t)
{
  double s = 0.0;
  for (std::size_t k = N; k-- > 0;)
    s = s * t + c[k];
  return s;
}
} // namespace detail

/// sin x for |x| <= π: within an ulp for |x| <= 1, two to π/2, 2e-15 beyond.
/// The terms after x are summed first and added to it last, so that the
/// result is rounded about once.
constexpr double sin(double x)
{
  constexpr auto c = detail::sineCoefficients();
  const double x2 = x * x;
  return x + x * (x2 * detail::horner(c, x2));
}

/// cos x for |x| <= π, within 1e-15 (within an ulp for |x| <= 1).
constexpr double cos(double x)
{
  constexpr auto c = detail::cosineCoefficients();
  const double x2 = x * x;
  return 1.0 + x2 * detail::horner(c, x2);
}

/// asin z for |z| <= 0.55, within an ulp.
constexpr double asin(double z)
{
  constexpr auto c = detail::arcsineCoefficients();
  const double z2 = z * z;
  return z + z * (z2 * detail::horner(c, z2));
}

} // namespace series
} // namespace osm

#endif
