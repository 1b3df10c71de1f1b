#include "SpatialSort.h"

#include <algorithm>
#include <cstdint>

namespace osm
{

namespace
{

/// Position of cell (x, y) along the Hilbert curve filling a 2^16 x 2^16 grid.
/// Each level picks a quadrant (2 bits of the key) in the frame left by the
/// levels above: the frame is the grid, swapped (x <-> y) or not, complemented
/// (both coordinates mirrored) or not. Branch-free: the quadrant bits are
/// random, so branches on them would mostly be mispredicted.
std::uint32_t hilbertKey(std::uint32_t x, std::uint32_t y)
{
  std::uint32_t key = 0, swapped = 0, complemented = 0;
  for (int level = 15; level >= 0; --level)
  {
    const std::uint32_t bx = (x >> level) & 1u, by = (y >> level) & 1u;
    const std::uint32_t rx = (swapped ? by : bx) ^ complemented;
    const std::uint32_t ry = (swapped ? bx : by) ^ complemented;
    key |= ((3u * rx) ^ ry) << (2 * level);
    // The lower quadrants turn the frame: both swap it, the right one mirrors it.
    swapped ^= ry ^ 1u;
    complemented ^= rx & (ry ^ 1u);
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
  std::vector<std::uint32_t> keys(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const auto x = static_cast<std::uint32_t>((points[i].x - b.lo.x) * scale);
    const auto y = static_cast<std::uint32_t>((points[i].y - b.lo.y) * scale);
    keys[i] = hilbertKey(std::min(x, 65535u), std::min(y, 65535u));
  }
  // Stable LSD radix sort of the indices by key: ties keep input order, as a
  // sort of (key, index) pairs would, in linear time. Small inputs take 8
  // bits a pass, so the counters cost nothing next to them.
  const int bits = points.size() < 65536 ? 8 : 16;
  const std::uint32_t mask = (1u << bits) - 1;
  std::vector<int> from(points.size());
  for (std::size_t i = 0; i < from.size(); ++i)
    from[i] = static_cast<int>(i);
  std::vector<std::size_t> count(std::size_t(mask) + 2);
  for (int shift = 0; shift < 32; shift += bits)
  {
    std::fill(count.begin(), count.end(), 0);
    for (int i : from)
      ++count[((keys[i] >> shift) & mask) + 1];
    for (std::size_t k = 1; k < count.size(); ++k)
      count[k] += count[k - 1];
    for (int i : from)
      order[count[(keys[i] >> shift) & mask]++] = i;
    from.swap(order);
  }
  order.swap(from);
  return order;
}

} // namespace osm
