#include "SpatialSort.h"

#include <algorithm>
#include <cstdint>

namespace osm
{

namespace
{

/// Position of cell (x, y) along the Hilbert curve filling a 2^16 x 2^16 grid.
std::uint64_t hilbertKey(std::uint32_t x, std::uint32_t y)
{
  std::uint64_t key = 0;
  for (std::uint32_t s = 1u << 15; s > 0; s >>= 1)
  {
    const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    key += static_cast<std::uint64_t>(s) * s * ((3 * rx) ^ ry);
    // Rotate the quadrant so the curve stays continuous.
    if (ry == 0)
    {
      if (rx == 1)
      {
        x = s - 1 - (x & (s - 1));
        y = s - 1 - (y & (s - 1));
      }
      std::swap(x, y);
    }
  }
  return key;
}

} // namespace

std::vector<int> hilbertOrder(const std::vector<Point>& points)
{
  std::vector<int> order(points.size());
  if (points.empty())
    return order;
  const Bounds b = boundsOf(points);
  const double size = std::max(b.width(), b.height());
  const double scale = size > 0 ? 65535.0 / size : 0.0;
  std::vector<std::pair<std::uint64_t, int>> keys(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const auto x = static_cast<std::uint32_t>((points[i].x - b.lo.x) * scale);
    const auto y = static_cast<std::uint32_t>((points[i].y - b.lo.y) * scale);
    keys[i] = { hilbertKey(std::min(x, 65535u), std::min(y, 65535u)), static_cast<int>(i) };
  }
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 0; i < keys.size(); ++i)
    order[i] = keys[i].second;
  return order;
}

} // namespace osm
