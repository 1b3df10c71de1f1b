#include "Domain.h"

#include "HugePages.h"
#include "Predicates.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <numeric>
#include <optional>

namespace osm
{

namespace
{

/// Pairs (hi, id) grouped into rows by lo in [0, n), each row in the order
/// emitted (a stable counting sort). forEach(emit) calls emit(lo, hi, id) for
/// every item, and must do so identically on both of its calls.
template <typename ForEach>
void bucketByLo(int n, ForEach&& forEach, Array<int>& start, Array<std::array<int, 2>>& items)
{
  start.assign(static_cast<std::size_t>(n) + 1, 0);
  forEach([&](int lo, int, int) { ++start[lo + 1]; });
  for (int v = 0; v < n; ++v)
    start[v + 1] += start[v];
  items.reserve(static_cast<std::size_t>(start[n]));
  items.resize(start[n]);
  Array<int> fill(start.begin(), start.end() - 1);
  forEach([&](int lo, int hi, int id) { items[fill[lo]++] = { hi, id }; });
}

/// Neighbour across each triangle edge (edge i opposite vertex i), -1 on the
/// boundary, and whether each edge is one of the constrained (lo, hi) pairs.
/// Linear time whatever the vertex degrees: the edges are bucketed by their
/// smaller vertex, and each bucket is matched on the larger vertex through
/// arrays stamped with the bucket's vertex. Edges with the same ends pair in
/// triangle order, each with the previous one. Edges given in known are taken
/// from it and not matched; its arrays become the result's, so that the
/// overlay's adjacency is extended, not copied.
KnownAdjacency adjacency(const Array<Triangle>& tris, const Array<Segment>& constrained,
  KnownAdjacency known, RunContext& run)
{
  int n = 0; // vertices 0..n-1
  for (const Triangle& t : tris)
    n = std::max({ n, t[0] + 1, t[1] + 1, t[2] + 1 });
  const int nk = static_cast<int>(known.nbr.size());
  KnownAdjacency a = std::move(known);
  a.nbr.resize(tris.size(), { -1, -1, -1 });
  a.constrained.resize(tris.size(), 0);
  Array<int> edgeStart, constrainedStart;
  Array<std::array<int, 2>> edges, constrainedEdges;
  bucketByLo(
    n,
    [&](auto&& emit) {
      for (int t = 0; t < static_cast<int>(tris.size()); ++t)
        for (int i = 0; i < 3; ++i)
        {
          run.pollEvery(1u << 18);
          if (t < nk && a.nbr[t][i] != KnownAdjacency::kUnknownNeighbour)
            continue;
          const int u = tris[t][(i + 1) % 3], v = tris[t][(i + 2) % 3];
          emit(std::min(u, v), std::max(u, v), 3 * t + i);
        }
    },
    edgeStart, edges);
  run.report(0.15);
  for (int t = 0; t < nk; ++t)
    for (int& u : a.nbr[t])
      if (u == KnownAdjacency::kUnknownNeighbour)
        u = -1;
  bucketByLo(
    n,
    [&](auto&& emit) {
      for (const Segment& s : constrained)
        if (0 <= s[0] && s[0] <= s[1] && s[1] < n) // others match no edge
          emit(s[0], s[1], 0);
    },
    constrainedStart, constrainedEdges);
  // Per larger vertex hi, valid while its stamp is the current lo: (lo, hi) is
  // constrained; the last edge seen with ends (lo, hi).
  Array<int> constrainedStamp, lastStamp, last;
  constrainedStamp.assign(static_cast<std::size_t>(n), -1);
  lastStamp.assign(static_cast<std::size_t>(n), -1);
  last.assign(static_cast<std::size_t>(n), -1);
  for (int lo = 0; lo < n; ++lo)
  {
    run.tickWith([&] { return 0.2 + 0.2 * double(lo) / double(n); }, 1u << 16);
    for (int k = constrainedStart[lo]; k < constrainedStart[lo + 1]; ++k)
      constrainedStamp[constrainedEdges[k][0]] = lo;
    for (int k = edgeStart[lo]; k < edgeStart[lo + 1]; ++k)
    {
      const int hi = edges[k][0], e = edges[k][1];
      const int t = e / 3, i = e % 3;
      const std::uint8_t bit = static_cast<std::uint8_t>(1u << i);
      a.constrained[t] =
        constrainedStamp[hi] == lo ? a.constrained[t] | bit : a.constrained[t] & ~bit;
      if (lastStamp[hi] == lo)
      {
        a.nbr[t][i] = last[hi] / 3;
        a.nbr[last[hi] / 3][last[hi] % 3] = t;
      }
      lastStamp[hi] = lo;
      last[hi] = e;
    }
  }
  return a;
}

/// The component of every triangle, among the triangles joined across
/// unconstrained edges, named by its smallest triangle index. Union-find in
/// index order touches memory in (spatial) order, where a flood jumps around.
/// Both sides of an edge agree whether it is constrained: one side decides.
Array<int> components(const KnownAdjacency& a, RunContext& run)
{
  const int n = static_cast<int>(a.nbr.size());
  Array<int> root;
  root.assign(static_cast<std::size_t>(n), 0);
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](int t) {
    while (root[t] != t)
      t = root[t] = root[root[t]]; // path halving
    return t;
  };
  for (int t = 0; t < n; ++t)
  {
    run.tickWith([&] { return 0.4 + 0.3 * double(t) / double(n); }, 1u << 16);
    for (int i = 0; i < 3; ++i)
    {
      const int u = a.nbr[t][i];
      if (u < 0 || u > t || ((a.constrained[t] >> i) & 1))
        continue;
      // The smaller index becomes the root: links only ever point down.
      const int ru = find(u), rt = find(t);
      if (ru < rt)
        root[rt] = ru;
      else
        root[ru] = rt;
    }
  }
  for (int t = 0; t < n; ++t)
    root[t] = root[root[t]]; // root[t] <= t is final already
  return root;
}

/// Whether the closed counter-clockwise triangle t holds q.
bool closureHolds(const Array<Point>& P, const Triangle& t, const Point& q)
{
  const Point &a = P[t[0]], &b = P[t[1]], &d = P[t[2]];
  return orient2d(a, b, q) >= 0 && orient2d(b, d, q) >= 0 && orient2d(d, a, q) >= 0;
}

/// Finds the triangle under a point among those not removed: a uniform grid
/// of their bounding boxes, about one cell per triangle, so locating many hole
/// seeds stays linear. Triangles removed before it is built (the exterior)
/// are left out: they include the largest ones, where the box is padded, which
/// would each cover a large share of the cells. removed is per component.
class TriangleGrid
{
public:
  TriangleGrid(const Array<Point>& P, const Array<Triangle>& tris, const Array<int>& component,
    const Array<char>& removed)
    : P(P)
    , tris(tris)
  {
    Array<int> candidates;
    for (int t = 0; t < static_cast<int>(tris.size()); ++t)
      if (!removed[component[t]])
        candidates.push_back(t);
    if (candidates.empty())
    {
      lo = hi = Point{ 0, 0 };
      start.assign(2, 0);
      return;
    }
    lo = hi = P[tris[candidates.front()][0]];
    for (int t : candidates)
      for (int v : tris[t])
      {
        lo = { std::min(lo.x, P[v].x), std::min(lo.y, P[v].y) };
        hi = { std::max(hi.x, P[v].x), std::max(hi.y, P[v].y) };
      }
    n = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(candidates.size()))));
    start.assign(static_cast<std::size_t>(n) * n + 1, 0);
    for (int pass = 0; pass < 2; ++pass)
    {
      Array<int> fill(start.begin(), start.end() - 1);
      for (int t : candidates)
        forCells(t, [&](std::size_t c) {
          if (pass == 0)
            ++start[c + 1];
          else
            items[fill[c]++] = t;
        });
      if (pass == 0)
      {
        for (std::size_t c = 0; c + 1 < start.size(); ++c)
          start[c + 1] += start[c];
        items.resize(start.back());
      }
    }
  }

  /// A triangle not removed whose closure contains q, or -1.
  int find(const Point& q, const Array<int>& component, const Array<char>& removed) const
  {
    if (q.x < lo.x || q.x > hi.x || q.y < lo.y || q.y > hi.y)
      return -1;
    const std::size_t c =
      static_cast<std::size_t>(cell(q.y, lo.y, hi.y)) * n + cell(q.x, lo.x, hi.x);
    for (int k = start[c]; k < start[c + 1]; ++k)
    {
      const int t = items[k];
      if (!removed[component[t]] && closureHolds(P, tris[t], q))
        return t;
    }
    return -1;
  }

private:
  int cell(double v, double a, double b) const
  {
    const double f = b > a ? (v - a) / (b - a) : 0.0;
    return std::min(n - 1, std::max(0, static_cast<int>(f * n)));
  }

  template <typename F>
  void forCells(int t, F&& f) const
  {
    const Point &a = P[tris[t][0]], &b = P[tris[t][1]], &c = P[tris[t][2]];
    const int x0 = cell(std::min({ a.x, b.x, c.x }), lo.x, hi.x);
    const int x1 = cell(std::max({ a.x, b.x, c.x }), lo.x, hi.x);
    const int y0 = cell(std::min({ a.y, b.y, c.y }), lo.y, hi.y);
    const int y1 = cell(std::max({ a.y, b.y, c.y }), lo.y, hi.y);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        f(static_cast<std::size_t>(y) * n + x);
  }

  const Array<Point>& P;
  const Array<Triangle>& tris;
  Point lo, hi;
  int n = 1;
  Array<int> start;
  Array<int> items;
};

/// The first triangle (lowest index) not removed whose closure contains q,
/// or -1: what TriangleGrid::find returns, by a scan of all the triangles.
int findByScan(const Array<Point>& P, const Array<Triangle>& tris, const Point& q,
  const Array<int>& component, const Array<char>& removed)
{
  for (int t = 0; t < static_cast<int>(tris.size()); ++t)
  {
    if (removed[component[t]])
      continue;
    const Point &a = P[tris[t][0]], &b = P[tris[t][1]], &d = P[tris[t][2]];
    if (q.x < std::min({ a.x, b.x, d.x }) || q.x > std::max({ a.x, b.x, d.x }) ||
      q.y < std::min({ a.y, b.y, d.y }) || q.y > std::max({ a.y, b.y, d.y }))
      continue;
    if (closureHolds(P, tris[t], q))
      return t;
  }
  return -1;
}

/// Whether edge i of triangle t is constrained (either side may say so).
bool isConstrained(const KnownAdjacency& a, int t, int i)
{
  if ((a.constrained[t] >> i) & 1)
    return true;
  const int u = a.nbr[t][i];
  for (int j = 0; u >= 0 && j < 3; ++j)
    if (a.nbr[u][j] == t && ((a.constrained[u] >> j) & 1))
      return true;
  return false;
}

/// The triangles not removed around vertex v of triangle t, each once:
/// rotating one way through the neighbours across v's edges, and the other
/// way from t if the first stops at the box.
Array<int> fanAround(const Array<Triangle>& tris, const KnownAdjacency& a, int t, int v,
  const Array<int>& component, const Array<char>& removed)
{
  Array<int> fan;
  auto keep = [&](int u) {
    if (!removed[component[u]])
      fan.push_back(u);
  };
  auto next = [&](int u, int turn) { return a.nbr[u][(cornerOf(tris[u], v) + turn) % 3]; };
  const int n = static_cast<int>(tris.size());
  keep(t);
  for (int u = next(t, 2), steps = 0; u >= 0 && steps < n; u = next(u, 2), ++steps)
  {
    if (u == t)
      return fan; // closed around v
    keep(u);
  }
  for (int u = next(t, 1), steps = 0; u >= 0 && steps < n; u = next(u, 1), ++steps)
    keep(u);
  return fan;
}

/// Whether direction v->p comes before v->q counter-clockwise from +x
/// (+x itself first), exactly.
bool beforeFromPlusX(const Point& v, const Point& p, const Point& q)
{
  auto half = [&v](const Point& w) { return w.y > v.y || (w.y == v.y && w.x > v.x) ? 0 : 1; };
  return half(p) != half(q) ? half(p) < half(q) : orient2d(v, p, q) > 0;
}

/// Of the fan's triangles around v, the one whose corner
/// at v holds the direction +x, its first edge included; else (+x leads out
/// of the domain) the first counter-clockwise from +x.
int fanTriangleAtPlusX(
  const Array<Point>& P, const Array<Triangle>& tris, const Array<int>& fan, int v)
{
  const Point& o = P[v];
  const Point east = justRightOf(o);
  auto firstEdgeEnd = [&](int u) { return P[tris[u][(cornerOf(tris[u], v) + 1) % 3]]; };
  int first = -1;
  for (const int u : fan)
  {
    const Point &p = firstEdgeEnd(u), &r = P[tris[u][(cornerOf(tris[u], v) + 2) % 3]];
    if (orient2d(o, p, east) >= 0 && orient2d(o, r, east) < 0)
      return u;
    if (first < 0 || beforeFromPlusX(o, p, firstEdgeEnd(first)))
      first = u;
  }
  return first;
}

/// Whether the direction +x from a point on line b->c leads to its left, or
/// runs along it with its left above (exactly).
bool plusXEntersLeft(const Point& b, const Point& c)
{
  const double side = orient2d(b, c, justRightOf(b));
  return side != 0 ? side > 0 : c.x > b.x;
}

/// Where the search that found q in the closure of triangle t met a segment
/// between two regions, the triangle whose region q goes to, else -1. q lies,
/// within rounding, on a constrained edge of t with triangles of another
/// region on its other side, or at a vertex where constrained edges end and
/// triangles of two regions meet. The rule holds in every mesh of the input
/// (the meshing rounds differ): the region the direction +x from q enters,
/// the one above where a segment runs along +x (at a vertex, the first
/// counter-clockwise from +x if +x leads out of the domain). A seed on the
/// domain's boundary or on a dangling segment is not in doubt.
int seedSide(const Array<Point>& P, const Array<Triangle>& tris, const KnownAdjacency& a, int t,
  const Point& q, const Array<char>& constrainedEnd, const Array<int>& component,
  const Array<char>& removed)
{
  for (int i = 0; i < 3; ++i)
  {
    const int v = tris[t][i];
    if (P[v] == q && constrainedEnd[v])
    {
      const Array<int> fan = fanAround(tris, a, t, v, component, removed);
      const bool twoRegions = std::any_of(
        fan.begin(), fan.end(), [&](int u) { return component[u] != component[fan.front()]; });
      return twoRegions ? fanTriangleAtPlusX(P, tris, fan, v) : -1;
    }
    if (!isConstrained(a, t, i))
      continue;
    const int u = a.nbr[t][i];
    if (u < 0 || removed[component[u]] || component[u] == component[t])
      continue;
    const Point &b = P[tris[t][(i + 1) % 3]], &c = P[tris[t][(i + 2) % 3]];
    const double length = std::hypot(c.x - b.x, c.y - b.y);
    if (onLineWithinRounding(orient2d(b, c, q), q, length, length))
      return plusXEntersLeft(b, c) ? t : u; // t lies left of b->c
  }
  return -1;
}

/// Whether q, found in the closure of triangle t, lies within rounding on a
/// side of t on the domain's boundary (no remaining triangle beyond it), or
/// at a corner of t on it (a review: t may touch the boundary there only).
bool onBoundary(const Array<Point>& P, const Array<Triangle>& tris, const KnownAdjacency& a, int t,
  const Point& q, const Array<int>& component, const Array<char>& removed)
{
  const auto gone = [&](int u) { return u < 0 || removed[component[u]]; };
  for (const int v : tris[t])
  {
    if (!(P[v] == q))
      continue;
    int u = t;
    for (std::size_t steps = 0; steps < tris.size(); ++steps)
    {
      u = a.nbr[u][(cornerOf(tris[u], v) + 2) % 3];
      if (gone(u))
        return true;
      if (u == t)
        break; // remaining triangles all around v
    }
  }
  for (int i = 0; i < 3; ++i)
  {
    if (!gone(a.nbr[t][i]))
      continue;
    const Point &b = P[tris[t][(i + 1) % 3]], &c = P[tris[t][(i + 2) % 3]];
    const double length = std::hypot(c.x - b.x, c.y - b.y);
    if (onLineWithinRounding(orient2d(b, c, q), q, length, length))
      return true;
  }
  return false;
}

} // namespace

Carving carveDomain(const Array<Point>& P, const Array<Triangle>& tris,
  const Array<Segment>& constrained, bool removeExterior, const Array<Point>& holes,
  KnownAdjacency known, const Array<Point>& regionSeeds, RunContext& run)
{
  // Each step is linear in the triangles; an abort is polled between them.
  const KnownAdjacency a = adjacency(tris, constrained, std::move(known), run);
  run.report(0.4);
  Array<int> component = components(a, run);
  run.report(0.7);
  Array<char> removed; // per component
  removed.assign(tris.size(), char{ 0 });
  if (removeExterior)
    for (int t = 0; t < static_cast<int>(tris.size()); ++t)
      if (a.nbr[t][0] < 0 || a.nbr[t][1] < 0 || a.nbr[t][2] < 0)
        removed[component[t]] = 1;
  Carving out;
  out.enclosedNothing = removeExterior;
  for (std::size_t t = 0; t < tris.size() && out.enclosedNothing; ++t)
    out.enclosedNothing = removed[component[t]] != 0;
  // A few seeds are found faster by scanning than by building the grid.
  std::optional<TriangleGrid> grid;
  auto locate = [&](const Point& q) {
    return grid ? grid->find(q, component, removed) : findByScan(P, tris, q, component, removed);
  };
  Array<char> constrainedEnd; // per vertex, made for the first seed found
  auto sideOf = [&](int t, const Point& q) {
    if (constrainedEnd.empty())
    {
      constrainedEnd.assign(P.size(), char{ 0 });
      for (const Segment& s : constrained)
        constrainedEnd[s[0]] = constrainedEnd[s[1]] = 1;
    }
    return seedSide(P, tris, a, t, q, constrainedEnd, component, removed);
  };
  if (!holes.empty())
  {
    if (holes.size() > kHoleSeedsScanned)
      grid.emplace(P, tris, component, removed);
    // Every seed is placed before any region goes, so that the regions
    // removed do not depend on the seeds' order (a review: a seed on a
    // segment took whichever side an earlier seed had not removed, and the
    // holes (1.5, 0.5), (1, 0.5) emptied a mesh the other order did not).
    Array<int> target(holes.size(), -1);
    for (std::size_t h = 0; h < holes.size(); ++h)
    {
      int t = locate(holes[h]);
      if (t >= 0)
      {
        if (const int side = sideOf(t, holes[h]); side >= 0)
        {
          out.seedsOnSegments.push_back(static_cast<int>(h));
          t = side;
        }
        else if (onBoundary(P, tris, a, t, holes[h], component, removed))
          out.seedsOnBoundary.push_back(static_cast<int>(h));
      }
      target[h] = t;
    }
    // A second seed in a region is one too many, as one outside the domain.
    for (std::size_t h = 0; h < holes.size(); ++h)
      if (target[h] < 0 || removed[component[target[h]]])
        out.unusedHoles.push_back(static_cast<int>(h));
      else
        removed[component[target[h]]] = 1;
    // One too many is said so, not also to have removed its region (a review).
    out.seedsOnBoundary.erase(
      std::remove_if(out.seedsOnBoundary.begin(), out.seedsOnBoundary.end(),
        [&](
          int h) { return std::binary_search(out.unusedHoles.begin(), out.unusedHoles.end(), h); }),
      out.seedsOnBoundary.end());
  }
  // The grid skips the triangles removed when it was built, and no others.
  if (!grid && regionSeeds.size() > kHoleSeedsScanned)
    grid.emplace(P, tris, component, removed);
  for (std::size_t k = 0; k < regionSeeds.size(); ++k)
  {
    int t = locate(regionSeeds[k]);
    if (const int side = t >= 0 ? sideOf(t, regionSeeds[k]) : -1; side >= 0)
    {
      out.regionSeedsOnSegments.push_back(static_cast<int>(k));
      t = side;
    }
    out.seedRegion.push_back(t);
  }
  // A constrained edge between removed triangles (or a removed one and the
  // box's outside) is a piece of a segment that the domain leaves out:
  // counted once, from its smaller triangle.
  for (int t = 0; t < static_cast<int>(tris.size()); ++t)
  {
    if (!removed[component[t]])
      continue;
    for (int i = 0; i < 3; ++i)
    {
      const int u = a.nbr[t][i];
      if (!isConstrained(a, t, i) || (u >= 0 && (!removed[component[u]] || u < t)))
        continue;
      out.droppedConstrained.push_back({ tris[t][(i + 1) % 3], tris[t][(i + 2) % 3] });
    }
  }
  // Regions are numbered in the order of their smallest triangle index: a
  // component's root comes before its other triangles, which take its id.
  run.report(0.85);
  int next = 0;
  out.regionId = std::move(component);
  for (int t = 0; t < static_cast<int>(tris.size()); ++t)
  {
    const int root = out.regionId[t];
    out.regionId[t] = root != t ? out.regionId[root] : removed[t] ? -1 : next++;
  }
  out.regions = static_cast<std::size_t>(next);
  for (int& r : out.seedRegion)
    r = r < 0 ? -1 : out.regionId[r];
  return out;
}

namespace
{

/// The points that may be hull vertices: all but those strictly inside the
/// polygon of the extreme points in 8 directions (Akl and Toussaint), which
/// for most inputs leaves few to sort. The extremes of x + y and x - y come
/// from rounded sums; any points of the set in counter-clockwise order would
/// do: a point strictly left of every edge of such a closed polygon is
/// strictly inside the hull.
Array<int> hullCandidates(const Array<Point>& P)
{
  if (P.empty())
    return {};
  // Directions counter-clockwise from -x; the components are 0 or ±1, so
  // each projection is the rounded sum of (at most) two exact terms.
  constexpr std::array<std::array<double, 2>, 8> direction{ { { -1, 0 }, { -1, -1 }, { 0, -1 },
    { 1, -1 }, { 1, 0 }, { 1, 1 }, { 0, 1 }, { -1, 1 } } };
  std::array<int, 8> extreme{};
  std::array<double, 8> best{};
  for (int i = 0; i < static_cast<int>(P.size()); ++i)
    for (int k = 0; k < 8; ++k)
    {
      const double along = direction[k][0] * P[i].x + direction[k][1] * P[i].y;
      if (i == 0 || along > best[k])
      {
        best[k] = along;
        extreme[k] = i;
      }
    }
  // A point extreme in consecutive directions would give an empty edge.
  Array<int> polygon;
  for (int k = 0; k < 8; ++k)
    if (polygon.empty() || P[extreme[k]] != P[polygon.back()])
      polygon.push_back(extreme[k]);
  while (polygon.size() > 1 && P[polygon.back()] == P[polygon.front()])
    polygon.pop_back();
  const std::size_t m = polygon.size();
  Array<int> out;
  for (int i = 0; i < static_cast<int>(P.size()); ++i)
  {
    bool inside = m >= 3;
    for (std::size_t k = 0; k < m && inside; ++k)
      inside = orient2d(P[polygon[k]], P[polygon[(k + 1) % m]], P[i]) > 0;
    if (!inside)
      out.push_back(i);
  }
  return out;
}

/// x lies between a and b along the line through them (ab: |b - a|), within
/// the rounding onLineWithinRounding allows across it.
bool alongSegment(const Point& a, const Point& b, const Point& x, double ab)
{
  const double scale = std::max(std::fabs(x.x), std::fabs(x.y)) + ab;
  const double slack = 8 * DBL_EPSILON * scale * ab;
  const double ux = b.x - a.x, uy = b.y - a.y;
  const double along = (x.x - a.x) * ux + (x.y - a.y) * uy; // |x - a| cos * ab
  return along >= -slack && along <= ab * ab + slack;
}

} // namespace

Array<int> convexHull(const Array<Point>& P)
{
  Array<int> order = hullCandidates(P);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return P[a] < P[b]; });
  if (order.size() < 3)
    return order;
  Array<int> hull(2 * order.size());
  std::size_t k = 0;
  for (int i : order) // lower hull
  {
    while (k >= 2 && orient2d(P[hull[k - 2]], P[hull[k - 1]], P[i]) <= 0)
      --k;
    hull[k++] = i;
  }
  for (std::size_t j = order.size() - 1, lower = k + 1; j-- > 0;) // upper hull
  {
    const int i = order[j];
    while (k >= lower && orient2d(P[hull[k - 2]], P[hull[k - 1]], P[i]) <= 0)
      --k;
    hull[k++] = i;
  }
  hull.resize(k - 1);
  return hull;
}

Array<int> hullBoundary(const Array<Point>& P)
{
  const Array<int> hull = convexHull(P);
  const int h = static_cast<int>(hull.size());
  if (h < 3)
    return hull;
  // The hull runs counter-clockwise from its smallest point (x, then y): up to
  // the largest point m along the lower chain, back along the upper one. So
  // each other point lies, in that order, within one lower and one upper edge.
  const auto less = [&](int a, int b) { return P[a] < P[b]; };
  const int m = static_cast<int>(std::max_element(hull.begin(), hull.end(), less) - hull.begin());
  const Array<int> lower(hull.begin(), hull.begin() + m + 1);
  Array<int> upper{ hull[0] }; // the upper chain reversed: increasing too
  for (int k = h - 1; k >= m; --k)
    upper.push_back(hull[k]);
  // Per point: 1 a corner of the lower chain only, 2 of the upper one only, 3 both ends.
  Array<char> onHull(P.size(), 0);
  for (int k = 0; k < h; ++k)
    onHull[hull[k]] = k == 0 || k == m ? 3 : k < m ? 1 : 2;
  // near[k]: points within rounding of hull edge k (from hull[k] to hull[k+1]).
  Array<Array<int>> near(h);
  // The chains' edge lengths, once: every other point is tested against one
  // edge of each chain, and a hypot call per test was most of this function.
  const auto edgeLengths = [&](const Array<int>& chain) {
    Array<double> length(chain.size() - 1);
    for (std::size_t i = 0; i + 1 < chain.size(); ++i)
    {
      const Point &a = P[chain[i]], &b = P[chain[i + 1]];
      length[i] = std::hypot(b.x - a.x, b.y - a.y);
    }
    return length;
  };
  const Array<double> lowerLength = edgeLengths(lower), upperLength = edgeLengths(upper);
  // The hull edge index near which point p lies within rounding, or -1. The
  // chain's order finds the edge whose ends' x bracket p's; a nearly vertical
  // edge brackets points far beyond its ends, near its line but not near the
  // edge, so p must also lie between the ends along the edge.
  const auto nearEdge = [&](const Array<int>& chain, int p, bool isLower) {
    const auto it = std::upper_bound(chain.begin(), chain.end(), p, less);
    if (it == chain.begin() || it == chain.end())
      return -1;
    const int i = static_cast<int>(it - chain.begin()) - 1;
    const Point &a = P[chain[i]], &b = P[chain[i + 1]];
    const double length = (isLower ? lowerLength : upperLength)[i];
    if (!onLineWithinRounding(orient2d(a, b, P[p]), P[p], length, length) ||
      !alongSegment(a, b, P[p], length))
      return -1;
    return isLower ? i : h - 1 - i;
  };
  // A point near both chains, or a corner of one chain near the other: the
  // hull is thinner than rounding there. Its segments would pass through the
  // points inside it, and it would enclose no area: no hull boundary, and the
  // box domain serves.
  for (int p = 0; p < static_cast<int>(P.size()); ++p)
  {
    if (onHull[p] == 3)
      continue;
    if (onHull[p])
    {
      if ((onHull[p] == 1 ? nearEdge(upper, p, false) : nearEdge(lower, p, true)) >= 0)
        return {};
      continue;
    }
    const int lo = nearEdge(lower, p, true), up = nearEdge(upper, p, false);
    if (lo >= 0 && up >= 0)
      return {};
    if (lo >= 0)
      near[lo].push_back(p);
    else if (up >= 0)
      near[up].push_back(p);
  }
  Array<int> boundary;
  for (int k = 0; k < h; ++k)
  {
    boundary.push_back(hull[k]);
    Array<int>& extra = near[k];
    std::sort(extra.begin(), extra.end(), less); // along the edge
    if (k >= m)
      std::reverse(extra.begin(), extra.end());
    boundary.insert(boundary.end(), extra.begin(), extra.end());
  }
  return boundary;
}

bool segmentsEncloseRegion(std::size_t pointCount, const Array<Segment>& segments)
{
  Array<int> parent(pointCount);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int v) {
    while (parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const Segment& s : segments)
  {
    const int a = root(s[0]), b = root(s[1]);
    if (a == b)
      return true;
    parent[a] = b;
  }
  return false;
}

} // namespace osm
