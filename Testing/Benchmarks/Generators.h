// Generated benchmark inputs, shared by every driver so that each tool meshes
// exactly the same PSLG. Everything here is deterministic and independent of
// the standard library's random engines and distributions (whose output is
// implementation-defined): with one C library (cos, sin and pow come from it),
// the same spec gives the same coordinates, bit for bit, in every driver.
//
// Specs (N = number of input vertices, seed = any unsigned integer):
//   points:N:seed           N uniform random points in the unit square, no segments.
//   random-segments:N:seed  N/2 segments, each strictly inside its own cell of a
//                           grid with about twice as many cells as segments:
//                           random centre, direction and length (0.2 to 0.5 of
//                           a cell). Segments in distinct cells cannot cross or
//                           touch, so the PSLG is valid by construction, and
//                           building it is O(N).
//   spread:N:seed           Like random-segments, but each segment's length is
//                           log-uniform over six decades (a cell's 0.5 down to
//                           0.5e-6): the shortest segment is about 1e-6 of the
//                           grid step, so the spread (diameter / shortest
//                           segment) grows to about 1e6 * sqrt(N).
#ifndef osm_bench_Generators_h
#define osm_bench_Generators_h

#include "Pslg.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace osmbench
{

/// SplitMix64: a tiny, well-mixed 64-bit generator with a fully specified output.
class Random
{
public:
  explicit Random(std::uint64_t seed)
    : state(seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull)
  {}
  std::uint64_t next()
  {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1), a multiple of 2^-53.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform integer in [0, n), n > 0 (the modulo bias is below 2^-40 for n < 2^24).
  std::uint64_t below(std::uint64_t n) { return next() % n; }

private:
  std::uint64_t state;
};

inline osm::Pslg randomPoints(std::size_t n, std::uint64_t seed)
{
  Random rng(seed);
  osm::Pslg p;
  p.points.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const double x = rng.uniform();
    const double y = rng.uniform();
    p.points.push_back({ x, y });
  }
  return p;
}

/// n/2 segments in distinct cells of a k x k grid over the unit square. With
/// logDecades > 0 the length is multiplied by 10^(-logDecades * u), u uniform.
inline osm::Pslg gridSegments(std::size_t n, std::uint64_t seed, double logDecades)
{
  const std::size_t m = n / 2;
  osm::Pslg p;
  if (m == 0)
    return p;
  std::size_t k = static_cast<std::size_t>(std::ceil(std::sqrt(2.0 * static_cast<double>(m))));
  if (k * k < m)
    ++k;
  const double h = 1.0 / static_cast<double>(k);
  Random rng(seed);
  // The first m entries of a partial Fisher-Yates shuffle: m distinct cells.
  std::vector<std::uint32_t> cells(k * k);
  for (std::size_t c = 0; c < cells.size(); ++c)
    cells[c] = static_cast<std::uint32_t>(c);
  for (std::size_t i = 0; i < m; ++i)
  {
    const std::size_t j = i + static_cast<std::size_t>(rng.below(cells.size() - i));
    std::swap(cells[i], cells[j]);
  }
  p.points.reserve(2 * m);
  p.segments.reserve(m);
  const double twoPi = 2.0 * std::acos(-1.0);
  for (std::size_t i = 0; i < m; ++i)
  {
    const std::size_t cx = cells[i] % k, cy = cells[i] / k;
    // Centre within 0.2 h of the cell's centre, half-length at most 0.25 h:
    // both endpoints stay at least 0.05 h inside the cell.
    const double x = (static_cast<double>(cx) + 0.5 + rng.uniform(-0.2, 0.2)) * h;
    const double y = (static_cast<double>(cy) + 0.5 + rng.uniform(-0.2, 0.2)) * h;
    const double angle = twoPi * rng.uniform();
    double half = rng.uniform(0.1, 0.25) * h;
    if (logDecades > 0)
      half = 0.25 * h * std::pow(10.0, -logDecades * rng.uniform());
    const double dx = half * std::cos(angle), dy = half * std::sin(angle);
    const int a = static_cast<int>(p.points.size());
    p.points.push_back({ x - dx, y - dy });
    p.points.push_back({ x + dx, y + dy });
    p.segments.push_back({ a, a + 1 });
  }
  return p;
}

/// Parse "family:N:seed"; returns false (and an error) for anything else.
inline bool generate(const std::string& spec, osm::Pslg& out, std::string& error)
{
  const std::size_t c1 = spec.find(':');
  const std::size_t c2 = c1 == std::string::npos ? c1 : spec.find(':', c1 + 1);
  if (c2 == std::string::npos)
  {
    error = "not a generator spec (family:N:seed): " + spec;
    return false;
  }
  const std::string family = spec.substr(0, c1);
  std::size_t n = 0;
  std::uint64_t seed = 0;
  try
  {
    n = static_cast<std::size_t>(std::stod(spec.substr(c1 + 1, c2 - c1 - 1)));
    seed = std::stoull(spec.substr(c2 + 1));
  }
  catch (...)
  {
    error = "bad size or seed in generator spec: " + spec;
    return false;
  }
  if (family == "points")
    out = randomPoints(n, seed);
  else if (family == "random-segments")
    out = gridSegments(n, seed, 0.0);
  else if (family == "spread")
    out = gridSegments(n, seed, 6.0);
  else
  {
    error = "unknown generator family '" + family + "' (points, random-segments, spread)";
    return false;
  }
  return true;
}

} // namespace osmbench

#endif
