// Basic geometry types shared by every part of the OSM core.
#ifndef osm_Geometry_h
#define osm_Geometry_h

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace osm
{

struct Point
{
  double x = 0.0;
  double y = 0.0;
};

inline bool operator==(const Point& a, const Point& b)
{
  return a.x == b.x && a.y == b.y;
}
inline bool operator!=(const Point& a, const Point& b)
{
  return !(a == b);
}
inline bool operator<(const Point& a, const Point& b)
{
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

inline double dist2(const Point& a, const Point& b)
{
  const double dx = a.x - b.x, dy = a.y - b.y;
  return dx * dx + dy * dy;
}

/// Where p projects onto the closed segment ab: 0 at a, 1 at b, clamped (0
/// when a == b).
inline double projectionOnSegment(const Point& p, const Point& a, const Point& b)
{
  const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  return l2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
}

/// Distance from p to the closed segment ab.
inline double distanceToSegment(const Point& p, const Point& a, const Point& b)
{
  const double t = projectionOnSegment(p, a, b);
  return std::hypot(p.x - (a.x + t * (b.x - a.x)), p.y - (a.y + t * (b.y - a.y)));
}

/// Angle at b in triangle (a, b, c), in radians, robust for tiny and near-flat
/// angles; the edge vectors are rescaled first so that products cannot overflow
/// (coordinates up to the double range) or underflow.
inline double angleAt(const Point& a, const Point& b, const Point& c)
{
  double ux = a.x - b.x, uy = a.y - b.y, vx = c.x - b.x, vy = c.y - b.y;
  const double su = std::fmax(std::fabs(ux), std::fabs(uy));
  const double sv = std::fmax(std::fabs(vx), std::fabs(vy));
  if (su > 0 && sv > 0)
  {
    ux /= su;
    uy /= su;
    vx /= sv;
    vy /= sv;
  }
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy);
}

/// Smallest and largest angle of triangle (p0, p1, p2), in radians, as
/// angleAt gives them. They sit opposite the shortest and the longest edge,
/// so two angleAt calls do instead of three; where two edges tie within
/// rounding either of their angles may be taken (they differ by an ulp), and
/// where squared lengths over- or underflow all three are compared.
inline void angleRange(const Point& p0, const Point& p1, const Point& p2, double& lo, double& hi)
{
  const Point* p[3] = { &p0, &p1, &p2 };
  auto at = [&](int k) { return angleAt(*p[(k + 2) % 3], *p[k], *p[(k + 1) % 3]); };
  const double opposite[3] = { dist2(p1, p2), dist2(p2, p0), dist2(p0, p1) };
  int shortest = 0;
  int longest = 0;
  bool usable = true;
  for (int k = 0; k < 3; ++k)
  {
    usable = usable && std::isfinite(opposite[k]) && opposite[k] > 0;
    shortest = opposite[k] < opposite[shortest] ? k : shortest;
    longest = opposite[k] > opposite[longest] ? k : longest;
  }
  if (usable)
  {
    lo = at(shortest);
    hi = at(longest);
    return;
  }
  lo = hi = at(0);
  for (int k = 1; k < 3; ++k)
  {
    lo = std::fmin(lo, at(k));
    hi = std::fmax(hi, at(k));
  }
}

/// Axis-aligned bounds of a set of points.
struct Bounds
{
  Point lo, hi;
  double width() const { return hi.x - lo.x; }
  double height() const { return hi.y - lo.y; }
};

/// Whether the triangle abc lies beyond one side of the bounds (a cheap test
/// that misses some triangles outside them).
inline bool outsideBounds(const Point& a, const Point& b, const Point& c, const Bounds& r)
{
  return std::max({ a.x, b.x, c.x }) < r.lo.x || std::min({ a.x, b.x, c.x }) > r.hi.x ||
    std::max({ a.y, b.y, c.y }) < r.lo.y || std::min({ a.y, b.y, c.y }) > r.hi.y;
}

/// Grows b to take in p.
inline void extend(Bounds& b, const Point& p)
{
  b.lo = { std::fmin(b.lo.x, p.x), std::fmin(b.lo.y, p.y) };
  b.hi = { std::fmax(b.hi.x, p.x), std::fmax(b.hi.y, p.y) };
}

/// Whether inner lies within outer (boundaries included).
inline bool within(const Bounds& inner, const Bounds& outer)
{
  return inner.lo.x >= outer.lo.x && inner.lo.y >= outer.lo.y && inner.hi.x <= outer.hi.x &&
    inner.hi.y <= outer.hi.y;
}

/// Bounds that take in nothing yet: extending them by p gives p's.
inline Bounds emptyBounds()
{
  constexpr double inf = std::numeric_limits<double>::infinity();
  return { { inf, inf }, { -inf, -inf } };
}

/// Bounds of points (all zero for none).
template <typename Points>
Bounds boundsOf(const Points& points)
{
  Bounds b = emptyBounds();
  bool any = false;
  for (const Point& p : points)
    extend(b, p), any = true;
  return any ? b : Bounds{};
}

using Segment = std::array<int, 2>;
using Triangle = std::array<int, 3>;

/// The index of vertex v among triangle t's corners, or -1.
inline int cornerOf(const Triangle& t, int v)
{
  return t[0] == v ? 0 : t[1] == v ? 1 : t[2] == v ? 2 : -1;
}

/// A point exactly in the direction +x from p (one ulp to its right), for
/// exact orientation tests against that direction however large p.x is.
inline Point justRightOf(const Point& p)
{
  return { std::nextafter(p.x, std::numeric_limits<double>::infinity()), p.y };
}

} // namespace osm

#endif
