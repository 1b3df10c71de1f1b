// The independent mesh checker declared in Validate.h. It is the oracle of the mesher's
// tests, so it shares nothing with the mesher but the exact predicates: every decision that
// can be made exactly (orientation, containment, crossing, angular order) is made with
// orient2d. Only the fan angle sums and segment conformity use tolerances, the latter because
// the mesher's intersection points are rounded and so lie off their segments.
//
// Why the checks prove "non-overlapping cover" (check 4): positive orientation, manifold and
// consistently oriented edges and fans that wind once make the mesh locally injective; the
// covering count can then change only across boundary edges. If those neither cross nor touch
// a vertex, any overlap has a boundary vertex inside (or on) a triangle not incident to it,
// or two triangles overlapping at a shared vertex, which the vertex-in-triangle and fan checks
// catch. So large meshes test boundary vertices only, which keeps everything O(n log n).
#include "Validate.h"

#include "Predicates.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace osm
{
namespace
{

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegrees = 180.0 / kPi;

// ------------------------------------------------------------------------------ messages

/// Counts every failure but formats and keeps only the first few: a broken mesh of millions
/// of triangles must not cost millions of strings.
class Errors
{
public:
  Errors(ValidationReport& report, std::size_t cap)
    : report_(report)
    , cap_(cap)
  {}

  template <class Describe>
  void add(Describe&& describe)
  {
    report_.ok = false;
    ++report_.errorCount;
    if (report_.errors.size() < cap_)
      report_.errors.push_back(describe());
  }

private:
  ValidationReport& report_;
  std::size_t cap_;
};

/// Shortest text that reads back to the same double, so coordinates in messages are exact.
std::string num(double value)
{
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string text(const Point& p)
{
  return "(" + num(p.x) + ", " + num(p.y) + ")";
}

std::string text(const Triangle& t)
{
  return "(" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) +
    ")";
}

// ------------------------------------------------------------------------- exact helpers

int sign(double v)
{
  return (v > 0) - (v < 0);
}

/// For collinear o, p, q: whether o->p and o->q point the same way. Exact, because the sign
/// of a difference of two doubles is always exact.
bool sameDirection(const Point& o, const Point& p, const Point& q)
{
  return sign(p.x - o.x) == sign(q.x - o.x) && sign(p.y - o.y) == sign(q.y - o.y);
}

/// 0 if direction o->d is at an angle in [0, pi) counter-clockwise from o->ref, else 1.
int halfPlane(const Point& o, const Point& ref, const Point& d)
{
  const int s = orientSign(o, ref, d);
  if (s != 0)
    return s > 0 ? 0 : 1;
  return sameDirection(o, ref, d) ? 0 : 1;
}

/// Exact angular order around o: whether o->p comes strictly before o->q when turning
/// counter-clockwise from o->ref (ref itself being angle 0).
bool ccwBefore(const Point& o, const Point& ref, const Point& p, const Point& q)
{
  const int hp = halfPlane(o, ref, p), hq = halfPlane(o, ref, q);
  if (hp != hq)
    return hp < hq;
  return orientSign(o, p, q) > 0; // same half-plane: the turn is less than pi
}

/// Whether p lies on the open segment ab (collinear, inside its box, not an endpoint).
bool onOpenSegment(const Point& a, const Point& b, const Point& p)
{
  if (p == a || p == b || orientSign(a, b, p) != 0)
    return false;
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
    p.y <= std::max(a.y, b.y);
}

/// Whether segments ab and cd cross at a single point interior to both.
bool properlyCross(const Point& a, const Point& b, const Point& c, const Point& d)
{
  return orientSign(a, b, c) * orientSign(a, b, d) < 0 &&
    orientSign(c, d, a) * orientSign(c, d, b) < 0;
}

/// Whether p lies in the closed counter-clockwise triangle abc.
bool inClosedTriangle(const Point& a, const Point& b, const Point& c, const Point& p)
{
  return orientSign(a, b, p) >= 0 && orientSign(b, c, p) >= 0 && orientSign(c, a, p) >= 0;
}

/// Whether the line of an edge of counter-clockwise triangle a has all of b on its closed
/// right side. Two triangles have disjoint interiors iff such an edge exists in one of them
/// (separating axis theorem: the edges of the Minkowski difference are the triangles' edges).
bool edgeSeparates(const std::array<Point, 3>& a, const std::array<Point, 3>& b)
{
  for (int i = 0; i < 3; ++i)
  {
    const Point &p = a[i], &q = a[(i + 1) % 3];
    if (orientSign(p, q, b[0]) <= 0 && orientSign(p, q, b[1]) <= 0 && orientSign(p, q, b[2]) <= 0)
      return true;
  }
  return false;
}

/// Angle at o between o->p and o->q, in radians, accurate for tiny and near-flat angles.
double cornerAngle(const Point& o, const Point& p, const Point& q)
{
  const double ux = p.x - o.x, uy = p.y - o.y, vx = q.x - o.x, vy = q.y - o.y;
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy);
}

// --------------------------------------------------------------------------- box tree

struct Box
{
  double x0, y0, x1, y1;
};

Box boxOf(const Point& a, const Point& b)
{
  return { std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y) };
}

Box boxOf(const Point& a, const Point& b, const Point& c)
{
  return { std::min({ a.x, b.x, c.x }), std::min({ a.y, b.y, c.y }), std::max({ a.x, b.x, c.x }),
    std::max({ a.y, b.y, c.y }) };
}

/// Closed boxes meet (touching counts: a vertex on an edge must be found).
bool meet(const Box& a, const Box& b)
{
  return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
}

/// Open boxes meet (two triangles whose boxes only touch cannot overlap).
bool interiorsMeet(const Box& a, const Box& b)
{
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

/// A bounding-volume hierarchy built by median splits. Chosen over a uniform grid because
/// graded meshes put most items in a few cells of any uniform grid.
class BoxTree
{
public:
  explicit BoxTree(std::vector<Box> boxes)
    : boxes_(std::move(boxes))
    , items_(boxes_.size())
  {
    for (std::size_t i = 0; i < items_.size(); ++i)
      items_[i] = static_cast<int>(i);
    if (!items_.empty())
    {
      nodes_.emplace_back();
      build(0, 0, items_.size());
    }
  }

  /// Calls visit(i) for every item i whose box meets q.
  template <class Visit>
  void query(const Box& q, Visit&& visit) const
  {
    if (nodes_.empty())
      return;
    std::array<std::size_t, 128> stack; // median splits keep the depth near log2(n)
    std::size_t top = 0;
    stack[top++] = 0;
    while (top > 0)
    {
      const Node& node = nodes_[stack[--top]];
      if (!meet(node.box, q))
        continue;
      if (node.left == 0)
      {
        for (std::size_t i = node.begin; i < node.end; ++i)
          if (meet(boxes_[items_[i]], q))
            visit(items_[i]);
        continue;
      }
      stack[top++] = node.left + 1;
      stack[top++] = node.left;
    }
  }

private:
  static constexpr std::size_t kLeafSize = 8;

  struct Node
  {
    Box box{};
    std::size_t begin = 0, end = 0;
    std::size_t left = 0; ///< children at left and left + 1; 0 (the root) marks a leaf
  };

  void build(std::size_t node, std::size_t begin, std::size_t end)
  {
    Box box = boxes_[items_[begin]];
    for (std::size_t i = begin + 1; i < end; ++i)
    {
      const Box& b = boxes_[items_[i]];
      box = { std::min(box.x0, b.x0), std::min(box.y0, b.y0), std::max(box.x1, b.x1),
        std::max(box.y1, b.y1) };
    }
    nodes_[node].box = box;
    nodes_[node].begin = begin;
    nodes_[node].end = end;
    if (end - begin <= kLeafSize)
      return;
    // Split at the median centre along the longer side.
    const bool alongX = box.x1 - box.x0 >= box.y1 - box.y0;
    const auto centre = [&](int i) {
      const Box& b = boxes_[i];
      return alongX ? b.x0 + b.x1 : b.y0 + b.y1;
    };
    const std::size_t mid = begin + (end - begin) / 2;
    std::nth_element(items_.begin() + begin, items_.begin() + mid, items_.begin() + end,
      [&](int a, int b) { return centre(a) < centre(b); });
    const std::size_t left = nodes_.size();
    nodes_.resize(left + 2); // may reallocate: address nodes by index only
    nodes_[node].left = left;
    build(left, begin, mid);
    build(left + 1, mid, end);
  }

  std::vector<Box> boxes_;
  std::vector<int> items_;
  std::vector<Node> nodes_;
};

// ------------------------------------------------------------------------- mesh topology

/// The triangles plus what is derived from them. Corner c = 3t + k is vertex k of triangle
/// t; c is also the id of the half-edge from that vertex to the next one of t.
struct Mesh
{
  Mesh(const Array<Point>& p, const Array<Triangle>& t)
    : points(p)
    , triangles(t)
  {}

  const Array<Point>& points;
  const Array<Triangle>& triangles;
  std::vector<char> usable;     ///< per triangle: indices valid, coordinates finite
  std::vector<char> positive;   ///< per triangle: exact orient2d > 0
  std::vector<char> referenced; ///< per vertex: a corner of a usable triangle
  std::vector<int> firstCorner; ///< per vertex: offset of its corners in cornersAt
  std::vector<int> cornersAt;   ///< corners grouped by vertex, each group sorted by next vertex
  std::vector<int> twin;        ///< per half-edge: the opposite half-edge, or -1
  std::vector<char> boundary;   ///< per half-edge: no other triangle uses its edge
  std::vector<double> angle;    ///< per corner: its angle in radians

  int vertex(int c) const { return triangles[c / 3][c % 3]; }
  int nextVertex(int c) const { return triangles[c / 3][(c % 3 + 1) % 3]; }
  int prevVertex(int c) const { return triangles[c / 3][(c % 3 + 2) % 3]; }
  const Point& at(int v) const { return points[v]; }
  std::array<Point, 3> corners(std::size_t t) const
  {
    return { points[triangles[t][0]], points[triangles[t][1]], points[triangles[t][2]] };
  }
  std::string name(std::size_t t) const
  {
    return "triangle " + std::to_string(t) + " " + text(triangles[t]);
  }
  std::string vertexName(int v) const { return "vertex " + std::to_string(v) + " " + text(at(v)); }
};

/// Check 1: indices in range and distinct. Also refuses non-finite coordinates, on which no
/// predicate is meaningful. Only usable triangles take part in the later checks.
void checkIndices(Mesh& m, Errors& errors)
{
  const auto nv = static_cast<long long>(m.points.size());
  m.usable.assign(m.triangles.size(), 0);
  m.referenced.assign(m.points.size(), 0);
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
  {
    const Triangle& tri = m.triangles[t];
    const auto bad = std::find_if(tri.begin(), tri.end(), [&](int v) { return v < 0 || v >= nv; });
    if (bad != tri.end())
    {
      errors.add([&] {
        return m.name(t) + " has vertex index " + std::to_string(*bad) + " out of range [0, " +
          std::to_string(nv) + ")";
      });
      continue;
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0])
    {
      errors.add([&] { return m.name(t) + " repeats a vertex"; });
      continue;
    }
    const auto finite = [&](int v) { return std::isfinite(m.at(v).x) && std::isfinite(m.at(v).y); };
    if (!std::all_of(tri.begin(), tri.end(), finite))
    {
      errors.add([&] { return m.name(t) + " has a vertex with non-finite coordinates"; });
      continue;
    }
    m.usable[t] = 1;
    for (int v : tri)
      m.referenced[v] = 1;
  }
}

/// Check 2: exact positive orientation.
void checkOrientation(Mesh& m, Errors& errors)
{
  m.positive.assign(m.triangles.size(), 0);
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
  {
    if (!m.usable[t])
      continue;
    const auto p = m.corners(t);
    m.positive[t] = orient2d(p[0], p[1], p[2]) > 0;
    if (!m.positive[t])
      errors.add([&] { return m.name(t) + " has non-positive orientation"; });
  }
}

/// Groups the corners by vertex (CSR), sorted by next vertex so that the half-edges u->w of
/// any u and w are found by binary search: O(n log d) and no hashing.
void buildCorners(Mesh& m)
{
  m.firstCorner.assign(m.points.size() + 1, 0);
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (m.usable[t])
      for (int v : m.triangles[t])
        ++m.firstCorner[v + 1];
  for (std::size_t v = 0; v < m.points.size(); ++v)
    m.firstCorner[v + 1] += m.firstCorner[v];
  m.cornersAt.resize(m.firstCorner.back());
  std::vector<int> fill(m.firstCorner.begin(), m.firstCorner.end() - 1);
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (m.usable[t])
      for (int k = 0; k < 3; ++k)
        m.cornersAt[fill[m.triangles[t][k]]++] = static_cast<int>(3 * t) + k;
  for (std::size_t v = 0; v < m.points.size(); ++v)
    std::sort(m.cornersAt.begin() + m.firstCorner[v], m.cornersAt.begin() + m.firstCorner[v + 1],
      [&](int a, int b) { return m.nextVertex(a) < m.nextVertex(b); });
}

/// The half-edges u->w (as a range of cornersAt).
std::pair<const int*, const int*> halfEdges(const Mesh& m, int u, int w)
{
  const int* first = m.cornersAt.data() + m.firstCorner[u];
  const int* last = m.cornersAt.data() + m.firstCorner[u + 1];
  const int* lo =
    std::lower_bound(first, last, w, [&](int c, int x) { return m.nextVertex(c) < x; });
  const int* hi = std::upper_bound(lo, last, w, [&](int x, int c) { return x < m.nextVertex(c); });
  return { lo, hi };
}

/// Reports a broken edge once, from its smallest half-edge.
void reportEdge(const Mesh& m, int h, std::pair<const int*, const int*> same,
  std::pair<const int*, const int*> opposite, Errors& errors)
{
  std::vector<int> uses(same.first, same.second);
  uses.insert(uses.end(), opposite.first, opposite.second);
  std::sort(uses.begin(), uses.end());
  if (uses.front() != h)
    return;
  const int u = std::min(m.vertex(h), m.nextVertex(h)), w = std::max(m.vertex(h), m.nextVertex(h));
  std::string list;
  for (int c : uses)
    list += (list.empty() ? "" : ", ") + std::to_string(c / 3);
  const std::string edge = "edge (" + std::to_string(u) + ", " + std::to_string(w) + ")";
  if (uses.size() > 2)
    errors.add([&] {
      return edge + " is shared by " + std::to_string(uses.size()) + " triangles: " + list;
    });
  else
    errors.add([&] { return edge + " has the same direction in triangles " + list; });
}

/// Check 3: every edge in one triangle (boundary) or in two with opposite directions (twins).
void checkEdges(Mesh& m, Errors& errors)
{
  m.twin.assign(3 * m.triangles.size(), -1);
  m.boundary.assign(3 * m.triangles.size(), 0);
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
  {
    if (!m.usable[t])
      continue;
    for (int k = 0; k < 3; ++k)
    {
      const int h = static_cast<int>(3 * t) + k, u = m.vertex(h), w = m.nextVertex(h);
      const auto same = halfEdges(m, u, w), opposite = halfEdges(m, w, u);
      const auto nSame = same.second - same.first, nOpposite = opposite.second - opposite.first;
      if (nSame == 1 && nOpposite == 1)
        m.twin[h] = *opposite.first;
      else if (nSame == 1 && nOpposite == 0)
        m.boundary[h] = 1;
      else
        reportEdge(m, h, same, opposite, errors);
    }
  }
}

/// Check 7 (and the corner angles that check 4a sums): atan2(|cross|, dot) per corner.
void measureAngles(
  Mesh& m, const ValidationOptions& options, ValidationReport& report, Errors& errors)
{
  m.angle.assign(3 * m.triangles.size(), 0.0);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::size_t worst = 0, tooLarge = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
  {
    if (!m.usable[t])
      continue;
    const auto p = m.corners(t);
    double largest = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      const double a = cornerAngle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
      m.angle[3 * t + k] = a;
      lo = std::min(lo, a * kDegrees);
      largest = std::max(largest, a * kDegrees);
    }
    tooLarge += largest > options.maxAngleDeg;
    if (largest > hi)
    {
      hi = largest;
      worst = t;
    }
  }
  if (hi < lo)
    return; // no usable triangle: leave the report's zeros
  report.minAngleDeg = lo;
  report.maxAngleDeg = hi;
  if (hi > options.maxAngleDeg)
    errors.add([&] {
      return m.name(worst) + " has an angle of " + num(hi) + " degrees > " +
        num(options.maxAngleDeg) + " (" + std::to_string(tooLarge) +
        " triangle(s) exceed the bound)";
    });
}

/// Check 8: no edge longer than options.maxEdgeLength (squared lengths compared).
void checkEdgeLengths(const Mesh& m, const ValidationOptions& options, Errors& errors)
{
  if (!(options.maxEdgeLength > 0))
    return;
  const double bound2 = options.maxEdgeLength * options.maxEdgeLength;
  double longest2 = 0;
  std::size_t worst = 0, tooLong = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
  {
    if (!m.usable[t])
      continue;
    const auto p = m.corners(t);
    double l2 = 0;
    for (int k = 0; k < 3; ++k)
      l2 = std::max(l2, dist2(p[k], p[(k + 1) % 3]));
    tooLong += l2 > bound2;
    if (l2 > longest2)
    {
      longest2 = l2;
      worst = t;
    }
  }
  if (longest2 > bound2)
    errors.add([&] {
      return m.name(worst) + " has an edge of length " + num(std::sqrt(longest2)) + " > " +
        num(options.maxEdgeLength) + " (" + std::to_string(tooLong) +
        " triangle(s) exceed the maximum edge length)";
    });
}

// ------------------------------------------------------------------------------ vertex fans

/// The next corner counter-clockwise around the same vertex (across the edge to the corner's
/// previous vertex), or -1 at a boundary or broken edge.
int ccwCorner(const Mesh& m, int c)
{
  return m.twin[3 * (c / 3) + (c % 3 + 2) % 3];
}

/// The next corner clockwise around the same vertex, or -1.
int cwCorner(const Mesh& m, int c)
{
  const int h = m.twin[c];
  return h < 0 ? -1 : 3 * (h / 3) + (h % 3 + 1) % 3;
}

/// Triangles around a vertex glued by edges, in counter-clockwise order.
struct Fan
{
  std::vector<int> corners;
  bool closed = false;
};

/// Splits the corners around v into fans. Twins are an involution, so cw and ccw are inverse
/// partial permutations: each orbit is either a cycle (closed fan) or a path (open fan).
void collectFans(const Mesh& m, int v, std::vector<char>& visited, std::vector<Fan>& fans)
{
  fans.clear();
  for (int i = m.firstCorner[v]; i < m.firstCorner[v + 1]; ++i)
  {
    const int c = m.cornersAt[i];
    if (visited[c])
      continue;
    Fan fan;
    int start = c;
    for (int p = cwCorner(m, c); p >= 0 && !fan.closed; p = cwCorner(m, p))
    {
      fan.closed = p == c;
      start = p;
    }
    int cur = start;
    do
    {
      fan.corners.push_back(cur);
      visited[cur] = 1;
      cur = ccwCorner(m, cur);
    } while (cur >= 0 && cur != start);
    fans.push_back(std::move(fan));
  }
}

const Point& fanStart(const Mesh& m, const Fan& fan)
{
  return m.at(m.nextVertex(fan.corners.front()));
}

const Point& fanEnd(const Mesh& m, const Fan& fan)
{
  return m.at(m.prevVertex(fan.corners.back()));
}

/// Exact: the fan's rays advance strictly counter-clockwise and never pass its first ray
/// again. With positive triangles (each step under pi) this means it turns exactly 2 pi when
/// closed and less than 2 pi when open; any wrap shows up as a non-increasing step.
bool windsOnce(const Mesh& m, int v, const Fan& fan)
{
  const Point& o = m.at(v);
  const Point& ref = fanStart(m, fan);
  const Point* last = &ref;
  for (std::size_t i = 1; i < fan.corners.size(); ++i)
  {
    const Point& ray = m.at(m.nextVertex(fan.corners[i]));
    if (!ccwBefore(o, ref, *last, ray))
      return false;
    last = &ray;
  }
  return fan.closed || ccwBefore(o, ref, *last, fanEnd(m, fan));
}

void checkFan(const Mesh& m, int v, const Fan& fan, Errors& errors)
{
  const std::string size = std::to_string(fan.corners.size()) + " triangles";
  if (fan.closed)
  {
    double sum = 0.0;
    for (int c : fan.corners)
      sum += m.angle[c];
    if (std::fabs(sum - 2 * kPi) > 1e-6 * 2 * kPi)
    {
      errors.add([&] {
        return m.vertexName(v) + ": its closed fan of " + size + " has angles summing to " +
          num(sum * kDegrees) + " degrees, not 360";
      });
      return;
    }
  }
  if (!windsOnce(m, v, fan))
    errors.add([&] {
      return m.vertexName(v) + ": its " + (fan.closed ? "closed" : "open") + " fan of " + size +
        " overlaps itself";
    });
}

/// Several fans at one vertex (a "bowtie", where the domain's boundary touches itself) are
/// legal only if all are open and their sectors are disjoint: sorted by first ray around the
/// vertex, each must end strictly before the next one starts.
void checkFansApart(const Mesh& m, int v, std::vector<Fan>& fans, Errors& errors)
{
  const auto describe = [&](const char* what) {
    return m.vertexName(v) + ": " + std::to_string(fans.size()) + " fans of triangles meet there " +
      what;
  };
  if (std::any_of(fans.begin(), fans.end(), [](const Fan& f) { return f.closed; }))
  {
    errors.add([&] { return describe("and one is closed"); });
    return;
  }
  const Point o = m.at(v), ref = fanStart(m, fans.front());
  std::sort(fans.begin(), fans.end(),
    [&](const Fan& a, const Fan& b) { return ccwBefore(o, ref, fanStart(m, a), fanStart(m, b)); });
  for (std::size_t i = 0; i < fans.size(); ++i)
  {
    const bool inside = ccwBefore(o, ref, fanStart(m, fans[i]), fanEnd(m, fans[i]));
    const bool apart =
      i + 1 == fans.size() || ccwBefore(o, ref, fanEnd(m, fans[i]), fanStart(m, fans[i + 1]));
    if (!inside || !apart)
    {
      errors.add([&] { return describe("and overlap"); });
      return;
    }
  }
}

/// Check 4a: the triangles around every vertex form fans that wind once and do not overlap.
void checkFans(const Mesh& m, Errors& errors)
{
  std::vector<char> visited(3 * m.triangles.size(), 0);
  std::vector<Fan> fans;
  for (std::size_t v = 0; v < m.points.size(); ++v)
  {
    if (!m.referenced[v])
      continue;
    collectFans(m, static_cast<int>(v), visited, fans);
    for (const Fan& fan : fans)
      checkFan(m, static_cast<int>(v), fan, errors);
    if (fans.size() > 1)
      checkFansApart(m, static_cast<int>(v), fans, errors);
  }
}

// ------------------------------------------------------------------------------ the cover

/// A set of mesh vertices and a box tree over their points.
struct VertexSet
{
  std::vector<int> vertices;
  BoxTree tree;
};

VertexSet vertexSet(const Mesh& m, std::vector<int> vertices)
{
  std::vector<Box> boxes;
  boxes.reserve(vertices.size());
  for (int v : vertices)
    boxes.push_back(boxOf(m.at(v), m.at(v)));
  return { std::move(vertices), BoxTree(std::move(boxes)) };
}

std::vector<int> boundaryEdges(const Mesh& m)
{
  std::vector<int> edges;
  for (std::size_t h = 0; h < m.boundary.size(); ++h)
    if (m.boundary[h])
      edges.push_back(static_cast<int>(h));
  return edges;
}

std::vector<int> endpoints(const Mesh& m, const std::vector<int>& edges)
{
  std::vector<int> vertices;
  for (int h : edges)
  {
    vertices.push_back(m.vertex(h));
    vertices.push_back(m.nextVertex(h));
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return vertices;
}

std::string edgeName(const Mesh& m, int h)
{
  return "(" + std::to_string(m.vertex(h)) + ", " + std::to_string(m.nextVertex(h)) + ")";
}

/// Check 4b: boundary edges neither cross each other at a point interior to both nor pass
/// through a mesh vertex (which also covers an endpoint touching another edge).
void checkBoundary(
  const Mesh& m, const std::vector<int>& edges, const std::vector<int>& vertices, Errors& errors)
{
  std::vector<Box> boxes;
  for (int h : edges)
    boxes.push_back(boxOf(m.at(m.vertex(h)), m.at(m.nextVertex(h))));
  const BoxTree tree(boxes);
  for (std::size_t i = 0; i < edges.size(); ++i)
  {
    const int a = m.vertex(edges[i]), b = m.nextVertex(edges[i]);
    tree.query(boxes[i], [&](int j) {
      const int c = m.vertex(edges[j]), d = m.nextVertex(edges[j]);
      if (static_cast<std::size_t>(j) <= i || a == c || a == d || b == c || b == d)
        return;
      if (properlyCross(m.at(a), m.at(b), m.at(c), m.at(d)))
        errors.add([&] {
          return "boundary edges " + edgeName(m, edges[i]) + " and " + edgeName(m, edges[j]) +
            " cross";
        });
    });
  }
  for (int v : vertices)
    tree.query(boxOf(m.at(v), m.at(v)), [&](int i) {
      const int a = m.vertex(edges[i]), b = m.nextVertex(edges[i]);
      if (v != a && v != b && onOpenSegment(m.at(a), m.at(b), m.at(v)))
        errors.add(
          [&] { return m.vertexName(v) + " lies on boundary edge " + edgeName(m, edges[i]); });
    });
}

/// Check 4c: no vertex of the set lies in a closed positive triangle it is not a corner of.
void checkVerticesInTriangles(const Mesh& m, const VertexSet& set, Errors& errors)
{
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
  {
    if (!m.positive[t])
      continue;
    const Triangle& tri = m.triangles[t];
    const auto p = m.corners(t);
    set.tree.query(boxOf(p[0], p[1], p[2]), [&](int i) {
      const int v = set.vertices[i];
      if (v != tri[0] && v != tri[1] && v != tri[2] && inClosedTriangle(p[0], p[1], p[2], m.at(v)))
        errors.add([&] { return m.vertexName(v) + " lies in " + m.name(t); });
    });
  }
}

/// Check 4d: literally every pair of positive triangles (after a box test), as an oracle for
/// the indexed checks above.
void checkPairwiseOverlap(const Mesh& m, Errors& errors)
{
  std::vector<std::size_t> ids;
  std::vector<Box> boxes;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (m.positive[t])
    {
      const auto p = m.corners(t);
      ids.push_back(t);
      boxes.push_back(boxOf(p[0], p[1], p[2]));
    }
  for (std::size_t i = 0; i < ids.size(); ++i)
    for (std::size_t j = i + 1; j < ids.size(); ++j)
    {
      if (!interiorsMeet(boxes[i], boxes[j]))
        continue;
      const auto a = m.corners(ids[i]), b = m.corners(ids[j]);
      if (!edgeSeparates(a, b) && !edgeSeparates(b, a))
        errors.add([&] { return m.name(ids[i]) + " and " + m.name(ids[j]) + " overlap"; });
    }
}

/// Check 4b to 4d. Vertex-in-triangle covers all vertices up to the size limit; beyond it,
/// boundary vertices suffice for a complete check (see the top of this file).
void checkCover(const Mesh& m, const ValidationOptions& options, Errors& errors)
{
  std::vector<int> referenced;
  for (std::size_t v = 0; v < m.points.size(); ++v)
    if (m.referenced[v])
      referenced.push_back(static_cast<int>(v));
  const std::vector<int> edges = boundaryEdges(m);
  checkBoundary(m, edges, referenced, errors);
  const std::size_t n = m.triangles.size(), limit = options.bruteForceOverlapLimit;
  const bool small = n / 100 + (n % 100 != 0) <= limit; // n <= 100 * limit, without overflow
  checkVerticesInTriangles(
    m, vertexSet(m, small ? std::move(referenced) : endpoints(m, edges)), errors);
  if (n <= limit)
    checkPairwiseOverlap(m, errors);
}

// -------------------------------------------------------------------- input and conformity

/// Exact coordinates as a hash key; +0.0 added so that -0.0 and 0.0 are the same point.
struct PointKey
{
  std::uint64_t x, y;
  bool operator==(const PointKey& o) const { return x == o.x && y == o.y; }
};

PointKey keyOf(const Point& p)
{
  const double x = p.x + 0.0, y = p.y + 0.0;
  PointKey key{};
  std::memcpy(&key.x, &x, sizeof x);
  std::memcpy(&key.y, &y, sizeof y);
  return key;
}

struct PointKeyHash
{
  std::size_t operator()(const PointKey& k) const
  {
    // splitmix64 finaliser: coordinates on a grid differ in few, high bits.
    std::uint64_t h = k.x * 0x9E3779B97F4A7C15ull ^ (k.y + 0x632BE59BD9B4E019ull);
    h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
    return static_cast<std::size_t>(h ^ (h >> 31));
  }
};

using VertexMap = std::unordered_map<PointKey, int, PointKeyHash>;

/// Maps the mesh's vertices by exact coordinates. Two mesh vertices at the same point make
/// a crack or an overlap that no other check names as clearly, so they fail here.
VertexMap mapVertices(const Mesh& m, Errors& errors)
{
  VertexMap map;
  map.reserve(m.points.size());
  for (std::size_t v = 0; v < m.points.size(); ++v)
  {
    if (!m.referenced[v])
      continue;
    const auto [it, inserted] = map.emplace(keyOf(m.at(v)), static_cast<int>(v));
    if (!inserted)
      errors.add([&, first = it->second] {
        return "vertices " + std::to_string(first) + " and " + std::to_string(v) + " coincide at " +
          text(m.at(static_cast<int>(v)));
      });
  }
  return map;
}

int meshVertex(const VertexMap& map, const Point& p)
{
  const auto it = map.find(keyOf(p));
  return it == map.end() ? -1 : it->second;
}

/// Check 5.
void checkInputVertices(const Pslg& input, const VertexMap& map, Errors& errors)
{
  for (std::size_t i = 0; i < input.points.size(); ++i)
    if (meshVertex(map, input.points[i]) < 0)
      errors.add([&] {
        return "input point " + std::to_string(i) + " " + text(input.points[i]) +
          " is not a mesh vertex";
      });
}

/// Rounding allowed off a segment, in units of the coordinates' epsilon: the
/// stitching walk takes a point within 16 of them onto a segment of its
/// round, and that segment's ends may be crossings, rounded within 1 of the
/// input segment (a review: 16.1 at 1e8, where the mesh is made at the input's
/// own coordinates).
constexpr double kRoundingEpsilons = 17;

/// How far off segment ab point p may be from rounding alone: the mesher's points on a
/// segment are rounded, and so are its intersections with other lines.
double roundingSlack(const Point& a, const Point& b, const Point& p)
{
  const double scale = std::max({ std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y),
    std::fabs(p.x), std::fabs(p.y) });
  return 1e-9 * std::hypot(b.x - a.x, b.y - a.y) +
    kRoundingEpsilons * std::numeric_limits<double>::epsilon() * scale;
}

/// Searches a chain of mesh edges for input segment ab, from vertex A to vertex B. Each step
/// goes to a neighbour within the rounding tolerance of line ab and strictly further
/// along it. Depth first, nearest the line first, and back out of dead ends: where another input
/// segment runs within the tolerance of this one (two segments diverging by 1e-9 rad from a shared
/// end), the step most directly towards b could take its chain and get stuck, though this
/// segment's own chain was there. Each vertex is entered once, so the search is linear. Returns ""
/// or why no chain was found (from the furthest vertex reached). Vertices up to offset off the
/// line are also allowed (ValidationOptions::chainOffset).
std::string walkSegment(const Mesh& m, int A, int B, double offset)
{
  const Point &a = m.at(A), &b = m.at(B);
  const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
  // Per vertex on the current path, its untried neighbours as (distance to the line, vertex),
  // nearest last.
  std::vector<std::vector<std::pair<double, int>>> path;
  std::unordered_set<int> entered;
  int furthest = A;
  double furthestAlong = -std::numeric_limits<double>::infinity(), furthestOff = 0;
  const auto enter = [&](int u) {
    entered.insert(u);
    std::vector<std::pair<double, int>> next;
    const Point& pu = m.at(u);
    double nearestOff = std::numeric_limits<double>::infinity();
    for (int i = m.firstCorner[u]; i < m.firstCorner[u + 1]; ++i)
      for (int w : { m.nextVertex(m.cornersAt[i]), m.prevVertex(m.cornersAt[i]) })
      {
        if (w == B)
        {
          next.push_back({ -1.0, B }); // nearest of all: B ends the search
          continue;
        }
        const Point& pw = m.at(w);
        // Progress is measured by the step itself, not by parameters from a:
        // near a far-away a, steps below one ulp of the parameter would vanish.
        const double step = (pw.x - pu.x) * dx + (pw.y - pu.y) * dy;
        const double rest = (b.x - pw.x) * dx + (b.y - pw.y) * dy;
        if (!(step > 0 && rest > 0) || entered.count(w))
          continue;
        const double off = std::fabs(dx * (pw.y - a.y) - dy * (pw.x - a.x)) / len;
        if (off > std::max(offset, roundingSlack(a, b, pw)))
          nearestOff = std::min(nearestOff, off);
        else
          next.push_back({ off, w });
      }
    std::sort(next.begin(), next.end(), std::greater<>());
    const double along = (pu.x - a.x) * dx + (pu.y - a.y) * dy;
    if (along > furthestAlong)
    {
      furthest = u;
      furthestAlong = along;
      furthestOff = nearestOff;
    }
    path.push_back(std::move(next));
  };
  enter(A);
  while (!path.empty())
  {
    std::vector<std::pair<double, int>>& next = path.back();
    if (next.empty())
    {
      path.pop_back(); // a dead end: back out
      continue;
    }
    const int w = next.back().second;
    next.pop_back();
    if (w == B)
      return "";
    if (!entered.count(w))
      enter(w);
  }
  return "no mesh edge continues it from " + m.vertexName(furthest) +
    (std::isfinite(furthestOff)
        ? " (nearest forward neighbour is " + num(furthestOff) + " off the line)"
        : "");
}

/// Distance from p to the closed segment ab (the validator's own, as all but the predicates).
double segmentDistance(const Point& p, const Point& a, const Point& b)
{
  const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  const double t = l2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

/// The input segments, to ask which pass near a point.
class SegmentIndex
{
public:
  SegmentIndex(const Pslg& input, double reach)
    : input_(input)
    , reach_(reach)
    , tree_(boxes(input, reach))
  {}

  /// Whether p lies within reach of an input segment other than s (or a copy of it).
  bool nearOther(const Point& p, std::size_t s) const
  {
    const Point &a = end(s, 0), &b = end(s, 1);
    bool near = false;
    tree_.query({ p.x, p.y, p.x, p.y }, [&](int t) {
      const Point &c = end(t, 0), &d = end(t, 1);
      const bool same = (a == c && b == d) || (a == d && b == c);
      near = near || (!same && segmentDistance(p, c, d) <= reach_ + roundingSlack(c, d, p));
    });
    return near;
  }

private:
  const Point& end(std::size_t s, int k) const { return input_.points[input_.segments[s][k]]; }

  static std::vector<Box> boxes(const Pslg& input, double reach)
  {
    const auto n = static_cast<int>(input.points.size());
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<Box> out;
    for (const Segment& s : input.segments)
    {
      if (s[0] < 0 || s[1] < 0 || s[0] >= n || s[1] >= n)
      {
        out.push_back({ inf, inf, -inf, -inf }); // meets nothing: reported as out of range
        continue;
      }
      const Box b = boxOf(input.points[s[0]], input.points[s[1]]);
      out.push_back({ b.x0 - reach, b.y0 - reach, b.x1 + reach, b.y1 + reach });
    }
    return out;
  }

  const Pslg& input_;
  double reach_;
  BoxTree tree_;
};

/// Whether segment s (mesh vertices A and B) is a chain that a merge tolerance bent: every
/// vertex within offset of s and further along it than the one before, and the chain straight
/// (within the rounding allowance) except at bends, each bend a vertex within twice offset of
/// another input segment, where the crossing of the two was joined to a point near both (a
/// later round's crossing of two bent pieces may lie twice as far). Without that condition any
/// vertex near the line could complete a chain: a mesh whose edge on a segment was flipped
/// would pass. Depth first over (vertex, next vertex) steps, each taken once: linear in the
/// mesh edges near the segment, however many of their vertices may be bends.
bool bentChainExists(
  const Mesh& m, int A, int B, double offset, const SegmentIndex& others, std::size_t s)
{
  const Point &a = m.at(A), &b = m.at(B);
  const double dx = b.x - a.x, dy = b.y - a.y;
  std::unordered_map<int, bool> bends;
  const auto bendsAt = [&](int v) {
    const auto [it, fresh] = bends.try_emplace(v, false);
    if (fresh)
      it->second = others.nearOther(m.at(v), s);
    return it->second;
  };
  // Whether the chain p, u, w goes straight on at u.
  const auto straight = [&](int p, int u, int w) {
    const Point &pp = m.at(p), &pu = m.at(u), &pw = m.at(w);
    const double ex = pw.x - pp.x, ey = pw.y - pp.y;
    const double off = std::fabs(ex * (pu.y - pp.y) - ey * (pu.x - pp.x)) / std::hypot(ex, ey);
    return off <= 2 * roundingSlack(a, b, pu);
  };
  std::vector<std::pair<int, int>> todo{ { -1, A } }; // (previous vertex, vertex)
  std::unordered_set<std::uint64_t> taken;
  while (!todo.empty())
  {
    const auto [p, u] = todo.back();
    todo.pop_back();
    const bool turns = p < 0 || bendsAt(u);
    const Point& pu = m.at(u);
    for (int i = m.firstCorner[u]; i < m.firstCorner[u + 1]; ++i)
      for (int w : { m.nextVertex(m.cornersAt[i]), m.prevVertex(m.cornersAt[i]) })
      {
        const Point& pw = m.at(w);
        const bool forward = (pw.x - pu.x) * dx + (pw.y - pu.y) * dy > 0 &&
          (w == B || (b.x - pw.x) * dx + (b.y - pw.y) * dy > 0);
        if (!forward || segmentDistance(pw, a, b) > offset + roundingSlack(a, b, pw) ||
          !(turns || straight(p, u, w)))
          continue;
        if (w == B)
          return true;
        if (taken.insert(static_cast<std::uint64_t>(u) << 32 | static_cast<std::uint32_t>(w))
              .second)
          todo.push_back({ u, w });
      }
  }
  return false;
}

/// Check 6: input segments whose endpoints are mesh vertices are chains of mesh edges.
void checkConformity(
  const Pslg& input, const Mesh& m, const VertexMap& map, double offset, Errors& errors)
{
  const auto np = input.points.size();
  std::optional<SegmentIndex> others;
  if (offset > 0)
    others.emplace(input, 2 * offset);
  for (std::size_t s = 0; s < input.segments.size(); ++s)
  {
    const Segment& seg = input.segments[s];
    const std::string name = "segment " + std::to_string(s) + " (input points " +
      std::to_string(seg[0]) + ", " + std::to_string(seg[1]) + ")";
    if (seg[0] < 0 || seg[1] < 0 || static_cast<std::size_t>(seg[0]) >= np ||
      static_cast<std::size_t>(seg[1]) >= np)
    {
      errors.add([&] { return name + " has a point index out of range"; });
      continue;
    }
    const int A = meshVertex(map, input.points[seg[0]]), B = meshVertex(map, input.points[seg[1]]);
    if (A < 0 || B < 0 || A == B)
      continue; // not both in the mesh (or degenerate): nothing to conform to
    std::string why = walkSegment(m, A, B, 0);
    if (why.empty() || (offset > 0 && bentChainExists(m, A, B, offset, *others, s)))
      continue;
    if (offset > 0)
    {
      const std::string within = walkSegment(m, A, B, offset);
      why = !within.empty() ? within
                            : "its only chains within " + num(offset) +
          " of the line bend where no other input segment passes within " + num(2 * offset);
    }
    errors.add([&] { return name + " is not a chain of mesh edges: " + why; });
  }
}

/// The convex hull of the finite points, counter-clockwise, without collinear points (the
/// validator's own: Andrew's monotone chain with exact orientation).
std::vector<Point> convexHullOf(const Array<Point>& points)
{
  std::vector<Point> p;
  for (const Point& q : points)
    if (std::isfinite(q.x) && std::isfinite(q.y))
      p.push_back(q);
  std::sort(p.begin(), p.end(),
    [](const Point& a, const Point& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3)
    return p;
  std::vector<Point> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) // lower hull
  {
    while (k >= 2 && orientSign(hull[k - 2], hull[k - 1], p[i]) <= 0)
      --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) // upper hull
  {
    while (k >= lower && orientSign(hull[k - 2], hull[k - 1], p[i]) <= 0)
      --k;
    hull[k++] = p[i];
  }
  hull.resize(k - 1);
  return hull;
}

/// Check 9a: every boundary edge of the mesh lies along an input segment or, as allowed, an
/// edge of the input's convex hull or of the mesh's bounding rectangle (both ends within
/// reach of it, plus rounding: the line between them then is too).
void checkDomainBoundary(
  const Pslg& input, const Mesh& m, DomainBoundary allowed, double reach, Errors& errors)
{
  std::vector<std::array<Point, 2>> lines;
  const auto n = static_cast<int>(input.points.size());
  for (const Segment& s : input.segments)
    if (s[0] >= 0 && s[1] >= 0 && s[0] < n && s[1] < n)
      lines.push_back({ input.points[s[0]], input.points[s[1]] });
  if (allowed == DomainBoundary::SegmentsOrHull)
  {
    const std::vector<Point> hull = convexHullOf(input.points);
    for (std::size_t i = 0; hull.size() >= 2 && i < hull.size(); ++i)
      lines.push_back({ hull[i], hull[(i + 1) % hull.size()] });
  }
  if (allowed == DomainBoundary::SegmentsOrBox)
  {
    Box b{ std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
      -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity() };
    for (std::size_t v = 0; v < m.points.size(); ++v)
      if (m.referenced[v])
        b = { std::min(b.x0, m.at(v).x), std::min(b.y0, m.at(v).y), std::max(b.x1, m.at(v).x),
          std::max(b.y1, m.at(v).y) };
    const Point c[4] = { { b.x0, b.y0 }, { b.x1, b.y0 }, { b.x1, b.y1 }, { b.x0, b.y1 } };
    for (int i = 0; i < 4; ++i)
      lines.push_back({ c[i], c[(i + 1) % 4] });
  }
  // Boxes grown by the reach and the rounding allowance (roundingSlack's
  // terms from each side: the line's, and the edge's own coordinates').
  const auto grown = [](const Box& x, double by) {
    return Box{ x.x0 - by, x.y0 - by, x.x1 + by, x.y1 + by };
  };
  const auto ulps = [](const Point& a, const Point& b) {
    return kRoundingEpsilons * std::numeric_limits<double>::epsilon() *
      std::max({ std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y) });
  };
  std::vector<Box> boxes;
  for (const auto& [a, b] : lines)
    boxes.push_back(
      grown(boxOf(a, b), reach + 1e-9 * std::hypot(b.x - a.x, b.y - a.y) + ulps(a, b)));
  const BoxTree tree(boxes);
  for (int h : boundaryEdges(m))
  {
    const Point &p = m.at(m.vertex(h)), &q = m.at(m.nextVertex(h));
    bool along = false;
    tree.query(grown(boxOf(p, q), ulps(p, q)), [&](int i) {
      const auto& [a, b] = lines[i];
      along = along ||
        (segmentDistance(p, a, b) <= reach + roundingSlack(a, b, p) &&
          segmentDistance(q, a, b) <= reach + roundingSlack(a, b, q));
    });
    if (!along)
      errors.add([&] {
        return "boundary edge " + edgeName(m, h) + " from " + text(p) + " to " + text(q) +
          " lies along no input segment" +
          (allowed == DomainBoundary::SegmentsOrHull     ? " nor the convex hull"
              : allowed == DomainBoundary::SegmentsOrBox ? " nor the bounding rectangle"
                                                         : "") +
          ": a triangle is missing inside the domain, or one lies beyond it";
      });
  }
}

/// Check 9b: no hole seed lies in a (closed) triangle, unless it lies on an input segment
/// within the rounding allowance plus reach: the mesher then removes the region on one side
/// (with a warning), and the edges along the segment run between rounded points, so the seed
/// may fall inside a kept triangle beside them.
void checkHoles(const Pslg& input, const Mesh& m, double reach, Errors& errors)
{
  if (input.holes.empty())
    return;
  std::vector<Box> boxes;
  std::vector<std::size_t> ids;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (m.positive[t])
    {
      const auto p = m.corners(t);
      boxes.push_back(boxOf(p[0], p[1], p[2]));
      ids.push_back(t);
    }
  const BoxTree tree(boxes);
  const auto n = static_cast<int>(input.points.size());
  const auto onASegment = [&](const Point& h) {
    for (const Segment& s : input.segments)
      if (s[0] >= 0 && s[1] >= 0 && s[0] < n && s[1] < n)
      {
        const Point &a = input.points[s[0]], &b = input.points[s[1]];
        if (segmentDistance(h, a, b) <= reach + roundingSlack(a, b, h))
          return true;
      }
    return false;
  };
  for (std::size_t k = 0; k < input.holes.size(); ++k)
  {
    const Point& h = input.holes[k];
    std::optional<std::size_t> in;
    tree.query(boxOf(h, h), [&](int i) {
      const auto p = m.corners(ids[i]);
      if (!in && inClosedTriangle(p[0], p[1], p[2], h))
        in = ids[i];
    });
    if (in && !onASegment(h))
      errors.add([&] {
        return "hole seed " + std::to_string(k) + " " + text(h) + " lies in " + m.name(*in);
      });
  }
}

} // namespace

namespace
{

/// Power-of-two exponent that brings coordinates near 1 when they are so large
/// or small that the predicates' products would overflow or underflow; 0 otherwise.
int rescaleExponent(const Pslg& input, const Array<Point>& vertices)
{
  double m = 0;
  for (const Array<Point>* pts : { &input.points, &vertices })
    for (const Point& p : *pts)
      if (std::isfinite(p.x) && std::isfinite(p.y))
        m = std::max({ m, std::fabs(p.x), std::fabs(p.y) });
  int e = 0;
  if (m > 0x1p100 || (m > 0 && m < 0x1p-100))
    std::frexp(m, &e);
  return e;
}

Array<Point> scaled(const Array<Point>& pts, int e)
{
  Array<Point> out(pts);
  for (Point& p : out)
    p = { std::ldexp(p.x, -e), std::ldexp(p.y, -e) };
  return out;
}

/// The input with each segment split at the points within tol of it,
/// strictly between its ends, in order along it from its lower end in (x, y)
/// order, points equally far along in (x, y) order: what a merge tolerance
/// does to the segments (the mesher's Snap.h, here by brute force).
Pslg snapped(const Pslg& input, double tol)
{
  Pslg out = input;
  out.segments.clear();
  const int n = static_cast<int>(input.points.size());
  std::vector<std::pair<double, int>> cuts;
  for (const Segment& s : input.segments)
  {
    if (s[0] < 0 || s[1] < 0 || s[0] >= n || s[1] >= n)
    {
      out.segments.push_back(s); // reported as out of range
      continue;
    }
    const bool flip = input.points[s[1]] < input.points[s[0]];
    const int lower = flip ? s[1] : s[0], upper = flip ? s[0] : s[1];
    const Point &a = input.points[lower], &b = input.points[upper];
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const double ux = (b.x - a.x) / length, uy = (b.y - a.y) / length;
    cuts.clear();
    for (int i = 0; i < n; ++i)
    {
      const Point& p = input.points[i];
      const double along = (p.x - a.x) * ux + (p.y - a.y) * uy;
      const double off = (p.y - a.y) * ux - (p.x - a.x) * uy;
      if (i != s[0] && i != s[1] && along > 0 && along < length && std::fabs(off) <= tol)
        cuts.push_back({ along, i });
    }
    std::sort(cuts.begin(), cuts.end(), [&](const auto& x, const auto& y) {
      const Point &p = input.points[x.second], &q = input.points[y.second];
      return x.first != y.first ? x.first < y.first : !(p == q) ? p < q : x.second < y.second;
    });
    int from = lower;
    for (const auto& [along, i] : cuts)
    {
      out.segments.push_back({ from, i });
      from = i;
    }
    out.segments.push_back({ from, upper });
  }
  return out;
}

} // namespace

ValidationReport validate(const Pslg& input, const Array<Point>& vertices,
  const Array<Triangle>& triangles, const ValidationOptions& options)
{
  const RoundToNearest rounding;
  // Scaling by a power of two is exact and changes no predicate or angle.
  if (const int e = rescaleExponent(input, vertices); e != 0)
  {
    Pslg in = input;
    in.points = scaled(input.points, e);
    ValidationOptions o = options;
    o.maxEdgeLength = std::ldexp(options.maxEdgeLength, -e);
    o.snapTolerance = std::ldexp(options.snapTolerance, -e);
    o.chainOffset = std::ldexp(options.chainOffset, -e);
    for (Point& h : in.holes)
      h = { std::ldexp(h.x, -e), std::ldexp(h.y, -e) };
    ValidationReport r = validate(in, scaled(vertices, e), triangles, o);
    if (!r.ok)
      r.errors.push_back("(coordinates in these messages are scaled by 2^" + std::to_string(-e) +
        " for exact arithmetic)");
    return r;
  }
  ValidationReport report;
  report.triangles = triangles.size();
  Errors errors(report, options.maxErrorMessages);
  Mesh m(vertices, triangles);
  checkIndices(m, errors);     // 1
  checkOrientation(m, errors); // 2
  buildCorners(m);
  checkEdges(m, errors);                     // 3
  measureAngles(m, options, report, errors); // 7, and the angles that 4a sums
  checkEdgeLengths(m, options, errors);      // 8
  checkFans(m, errors);                      // 4a
  checkCover(m, options, errors);            // 4b, 4c, 4d
  const VertexMap map = mapVertices(m, errors);
  if (options.requireAllInputVertices)
    checkInputVertices(input, map, errors); // 5
  if (options.checkConformity)
    checkConformity(options.snapTolerance > 0 ? snapped(input, options.snapTolerance) : input, m,
      map, options.chainOffset, errors); // 6
  if (options.boundary != DomainBoundary::Unchecked)
    checkDomainBoundary(
      input, m, options.boundary, options.snapTolerance + options.chainOffset, errors); // 9a
  if (options.checkHoles)
    checkHoles(input, m, options.snapTolerance + options.chainOffset, errors); // 9b
  return report;
}

} // namespace osm
