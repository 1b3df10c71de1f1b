// The Taylor series against libm over the ranges the mesher uses them in.
#include "Mesher.h"
#include "Overlay.h"
#include "Series.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

namespace
{
using namespace osm;

/// Distance in units in the last place between two finite doubles of one sign.
std::int64_t ulps(double a, double b)
{
  std::int64_t x, y;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x > y ? x - y : y - x;
}

struct Worst
{
  std::int64_t ulps = 0;
  double abs = 0.0;
};

template <class Ours, class Libm>
Worst compare(Ours ours, Libm libm, double lo, double hi)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> d(lo, hi);
  Worst w;
  for (int i = 0; i < 200000; ++i)
  {
    const double x = i == 0 ? lo : i == 1 ? hi : d(rng);
    const double a = ours(x), b = libm(x);
    w.ulps = std::max(w.ulps, ulps(a, b));
    w.abs = std::max(w.abs, std::fabs(a - b));
  }
  return w;
}

TEST(Series, PiIsTheDoubleNearestToPi)
{
  EXPECT_EQ(series::kPi, std::acos(-1.0));
}

TEST(Series, SineWithinAnUlpUpToOneRadianAndTwoToAQuarterTurn)
{
  auto ours = [](double x) { return series::sin(x); };
  auto libm = [](double x) { return std::sin(x); };
  EXPECT_LE(compare(ours, libm, 0.0, 1.0).ulps, 1);
  EXPECT_LE(compare(ours, libm, -1.0, 0.0).ulps, 1);
  EXPECT_LE(compare(ours, libm, 1.0, series::kPi / 2).ulps, 2);
  EXPECT_LE(compare(ours, libm, 0.0, series::kPi).abs, 2e-15);
}

TEST(Series, CosineWithinAnUlpUpToOneRadianAnd1e15ToPi)
{
  auto ours = [](double x) { return series::cos(x); };
  auto libm = [](double x) { return std::cos(x); };
  EXPECT_LE(compare(ours, libm, 0.0, 1.0).ulps, 1);
  EXPECT_LE(compare(ours, libm, 0.0, series::kPi).abs, 1e-15);
  EXPECT_LE(compare(ours, libm, -series::kPi, 0.0).abs, 1e-15);
}

TEST(Series, ArcsineWithinAnUlp)
{
  auto ours = [](double z) { return series::asin(z); };
  auto libm = [](double z) { return std::asin(z); };
  EXPECT_LE(compare(ours, libm, 0.0, 0.55).ulps, 1);
  EXPECT_LE(compare(ours, libm, -0.55, 0.0).ulps, 1);
}

/// The mesher's constants as they were computed with libm.
double libmGamma(double deg)
{
  return 1.0 / (2.0 * std::sin(deg * std::acos(-1.0) / 180.0));
}

double libmPredictedMaxAngle(double deg)
{
  const double pi = std::acos(-1.0), theta1 = deg * pi / 180.0, gamma = libmGamma(deg);
  return 180.0 - std::asin(1.0 / (2.0 * gamma * (2.0 * gamma + std::cos(theta1)))) * 180.0 / pi;
}

TEST(Series, TheMeshersConstantsAsWithLibm)
{
  // The same doubles at whole degrees (the default 30° among them); within an
  // ulp or two of Γ and of the bound at any angle.
  for (int deg = 1; deg <= 35; ++deg)
  {
    const double theta1 = deg * series::kPi / 180.0;
    EXPECT_EQ(series::sin(theta1), std::sin(theta1)) << deg;
    EXPECT_EQ(series::cos(theta1), std::cos(theta1)) << deg;
    EXPECT_EQ(gammaForMinAngle(deg), libmGamma(deg)) << deg;
    EXPECT_EQ(predictedMaxAngleDeg(deg), libmPredictedMaxAngle(deg)) << deg;
  }
  for (double deg = 1.0; deg <= 60.0; deg += 1.0 / 64)
  {
    EXPECT_LE(ulps(gammaForMinAngle(deg), libmGamma(deg)), 2) << deg;
    EXPECT_LE(ulps(predictedMaxAngleDeg(deg), libmPredictedMaxAngle(deg)), 2) << deg;
  }
  EXPECT_NEAR(predictedMaxAngleDeg(30.0), 169.95, 0.01);
  // osm-mesh's --gamma goes back to θ1 through the inverse, on the whole range.
  for (double deg = 1.0; deg <= 35.0; deg += 1.0 / 64)
    EXPECT_NEAR(minAngleForGamma(gammaForMinAngle(deg)), deg, 1e-12) << deg;
  EXPECT_NEAR(minAngleForGamma(1.0), 30.0, 1e-12);
}

} // namespace
