#include "SpatialSort.h"

#include "HugePages.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace osm
{

namespace
{

/// One level of the Hilbert curve. The frame left by the levels above (state:
/// bit 0 swapped x <-> y, bit 1 both coordinates mirrored) and the cell's
/// bits at this level give the key digit (its quadrant along the curve) and
/// the frame for the next level: the lower quadrants turn the frame (both swap
/// it, the right one also mirrors it).
struct HilbertStep
{
  std::uint32_t digit, state;
};

constexpr HilbertStep hilbertStep(std::uint32_t state, std::uint32_t bx, std::uint32_t by)
{
  const std::uint32_t swapped = state & 1u, complemented = state >> 1;
  const std::uint32_t rx = (swapped ? by : bx) ^ complemented;
  const std::uint32_t ry = (swapped ? bx : by) ^ complemented;
  return { (3u * rx) ^ ry, (swapped ^ ry ^ 1u) | ((complemented ^ (rx & (ry ^ 1u))) << 1) };
}

/// Four levels at once: for a state and 4 bits of x and of y, the 8 key bits
/// and the next state. A key then costs 4 table lookups instead of 16 levels.
/// Built at compile time: at run time it cost about 100,000 instructions per
/// process, 2% of meshing a small input such as A.poly.
struct HilbertTable
{
  std::array<std::uint16_t, 4 * 256> entry{};

  constexpr HilbertTable()
  {
    for (std::uint32_t state = 0; state < 4; ++state)
      for (std::uint32_t xs = 0; xs < 16; ++xs)
        for (std::uint32_t ys = 0; ys < 16; ++ys)
        {
          std::uint32_t s = state, digits = 0;
          for (int level = 3; level >= 0; --level)
          {
            const HilbertStep step = hilbertStep(s, (xs >> level) & 1u, (ys >> level) & 1u);
            digits |= step.digit << (2 * level);
            s = step.state;
          }
          entry[(state << 8) | (xs << 4) | ys] = static_cast<std::uint16_t>(digits | (s << 8));
        }
  }
};

/// Position of cell (x, y) along the Hilbert curve filling a 2^16 x 2^16 grid.
std::uint32_t hilbertKey(const HilbertTable& table, std::uint32_t x, std::uint32_t y)
{
  std::uint32_t key = 0, state = 0;
  for (int shift = 12; shift >= 0; shift -= 4)
  {
    const std::uint32_t e =
      table.entry[(state << 8) | (((x >> shift) & 15u) << 4) | ((y >> shift) & 15u)];
    key |= (e & 255u) << (2 * shift);
    state = e >> 8;
  }
  return key;
}

} // namespace

Array<int> hilbertOrder(const Point* points, std::size_t n)
{
  Array<int> order;
  order.assign(n, 0);
  if (n == 0)
    return order;
  struct Range
  {
    const Point *first, *last;
    const Point* begin() const { return first; }
    const Point* end() const { return last; }
  };
  const Bounds b = boundsOf(Range{ points, points + n });
  const double size = std::max(b.width(), b.height());
  const double scale = size > 0 ? 65535.0 / size : 0.0;
  static constexpr HilbertTable table{};
  Array<std::uint32_t> keys;
  keys.assign(n, std::uint32_t{ 0 });
  for (std::size_t i = 0; i < n; ++i)
  {
    const auto x = static_cast<std::uint32_t>((points[i].x - b.lo.x) * scale);
    const auto y = static_cast<std::uint32_t>((points[i].y - b.lo.y) * scale);
    keys[i] = hilbertKey(table, std::min(x, 65535u), std::min(y, 65535u));
  }
  // Stable LSD radix sort of the indices by key: ties keep input order, as a
  // sort of (key, index) pairs would, in linear time. Small inputs take 8
  // bits a pass, so the counters cost nothing next to them.
  const int bits = n < 65536 ? 8 : 16;
  const std::uint32_t mask = (1u << bits) - 1;
  Array<int> from;
  from.assign(n, 0);
  for (std::size_t i = 0; i < from.size(); ++i)
    from[i] = static_cast<int>(i);
  Array<std::size_t> count(std::size_t(mask) + 2);
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
