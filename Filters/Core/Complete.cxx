#include "Complete.h"

#include "Clean.h"
#include "HugePages.h"
#include "Predicates.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace osm
{

namespace
{
/// Completion is O(k^3) in the face size k; the theory says k <= 6.
constexpr std::size_t kLargestFaceHandled = 400;
} // namespace

double maxAngle(const Point& a, const Point& b, const Point& c)
{
  // The largest angle lies opposite the longest edge. An edge shorter than it
  // by a relative 1e-9 in squared length faces an angle smaller by far more
  // than angleAt's rounding (at least 5e-10 tan 60 degrees radians), so its
  // atan2 can be skipped: one call instead of three, the same maximum. Where
  // squared lengths over- or underflow, all three are computed. (angleRange
  // takes either angle where edges tie within rounding; the search compares
  // these maxima for ties, so it needs exactly the largest.)
  const double la = dist2(b, c), lb = dist2(c, a), lc = dist2(a, b);
  const double longest = std::max({ la, lb, lc });
  const bool all = !(longest > 1e-290 && longest < 1e290);
  const double cut = (1.0 - 1e-9) * longest;
  double m = 0.0;
  if (all || la >= cut)
    m = angleAt(c, a, b);
  if (all || lb >= cut)
    m = std::max(m, angleAt(a, b, c));
  if (all || lc >= cut)
    m = std::max(m, angleAt(b, c, a));
  return m;
}

namespace
{

/// Does the open segment from polygon vertex i to j lie inside the polygon?
/// orient(a, b, c) is orientSign of polygon vertices a, b and c.
template <class Orient>
bool isDiagonal(const Array<Point>& P, int i, int j, const Orient& orient)
{
  const int k = static_cast<int>(P.size());
  // Inside the interior cone at each end (a straight angle is a half-plane).
  for (int end = 0; end < 2; ++end)
  {
    const int a = end == 0 ? i : j, b = end == 0 ? j : i;
    const int prev = (a + k - 1) % k, next = (a + 1) % k;
    const int turn = orient(prev, a, next);
    const int toNext = orient(a, next, b);
    const int fromPrev = orient(prev, a, b);
    const bool inside = turn > 0 ? (toNext > 0 && fromPrev > 0)
      : turn < 0                 ? (toNext > 0 || fromPrev > 0)
                                 : toNext > 0;
    if (!inside)
      return false;
  }
  // No vertex on it and no boundary edge across it.
  for (int m = 0; m < k; ++m)
  {
    if (m == i || m == j)
      continue;
    const int o = orient(i, j, m);
    if (o == 0 && std::min(P[i].x, P[j].x) <= P[m].x && P[m].x <= std::max(P[i].x, P[j].x) &&
      std::min(P[i].y, P[j].y) <= P[m].y && P[m].y <= std::max(P[i].y, P[j].y))
      return false;
    const int n = (m + 1) % k;
    if (n == i || n == j)
      continue;
    const int o2 = orient(i, j, n);
    if (o != 0 && o2 != 0 && o != o2 && orient(m, n, i) * orient(m, n, j) < 0)
      return false;
  }
  return true;
}

/// The orientations of a quadrilateral's vertex triples: four exact tests
/// answer all of them, as an exact sign only changes with the triple's order.
struct QuadrilateralOrientation
{
  std::array<int, 4> sign; ///< of the three vertices other than m, in increasing order

  explicit QuadrilateralOrientation(const Array<Point>& P)
    : sign{ orientSign(P[1], P[2], P[3]), orientSign(P[0], P[2], P[3]),
      orientSign(P[0], P[1], P[3]), orientSign(P[0], P[1], P[2]) }
  {}

  /// orientSign(P[a], P[b], P[c]) for three different vertices.
  int operator()(int a, int b, int c) const
  {
    int parity = 1;
    if (a > b)
      std::swap(a, b), parity = -parity;
    if (b > c)
      std::swap(b, c), parity = -parity;
    if (a > b)
      std::swap(a, b), parity = -parity;
    return parity * sign[6 - a - b - c];
  }
};

/// The dynamic program below unrolled for a quadrilateral, the usual face
/// (53,370 of us48.poly's 53,428): the same tests in the same order, hence the
/// same triangles, without its arrays, loops and stack, and with four exact
/// orientation tests instead of 24. c02 is the cost of the chain 0..2 closed
/// by the chord 0-2 (apex 1), c13 that of 1..3 (apex 2).
bool triangulateQuadrilateral(const Array<Point>& P, const Array<int>& ids, Array<Triangle>& out)
{
  const double inf = std::numeric_limits<double>::infinity();
  const QuadrilateralOrientation orient(P);
  // An angle is never infinite, and the program's max(0, NaN) is 0: a chain's
  // cost, once found, is finite.
  double c02 = inf, c13 = inf;
  if (isDiagonal(P, 0, 2, orient) && orient(0, 1, 2) > 0)
    c02 = std::max(0.0, maxAngle(P[0], P[1], P[2]));
  if (isDiagonal(P, 1, 3, orient) && orient(1, 2, 3) > 0)
    c13 = std::max(0.0, maxAngle(P[1], P[2], P[3]));
  // The chord 0-3 closes the chain 0..3 with apex 1 (then the chain 1..3) or
  // apex 2 (then 0..2); a tie keeps apex 1.
  double best = inf;
  int apex = -1;
  if (c13 < inf && orient(0, 1, 3) > 0)
  {
    best = std::max(c13, maxAngle(P[0], P[1], P[3]));
    apex = 1;
  }
  if (c02 < best && orient(0, 2, 3) > 0)
    if (const double c = std::max(c02, maxAngle(P[0], P[2], P[3])); c < best)
    {
      best = c;
      apex = 2;
    }
  if (best == inf)
    return false;
  if (apex == 1)
  {
    out.push_back({ ids[0], ids[1], ids[3] });
    out.push_back({ ids[1], ids[2], ids[3] });
  }
  else
  {
    out.push_back({ ids[0], ids[2], ids[3] });
    out.push_back({ ids[0], ids[1], ids[2] });
  }
  return true;
}

} // namespace

bool triangulateMinMaxAngle(const Array<Point>& P, const Array<int>& ids, Array<Triangle>& out)
{
  MinMaxScratch scratch;
  return triangulateMinMaxAngle(P, ids, out, scratch);
}

bool triangulateMinMaxAngle(
  const Array<Point>& P, const Array<int>& ids, Array<Triangle>& out, MinMaxScratch& scratch)
{
  if (P.size() == 4)
    return triangulateQuadrilateral(P, ids, out);
  return triangulateMinMaxAngleByProgram(P, ids, out, scratch);
}

bool triangulateMinMaxAngleByProgram(
  const Array<Point>& P, const Array<int>& ids, Array<Triangle>& out, MinMaxScratch& scratch)
{
  const int k = static_cast<int>(P.size());
  const double inf = std::numeric_limits<double>::infinity();
  const auto orient = [&P](int a, int b, int c) { return orientSign(P[a], P[b], P[c]); };
  // ok[i][j]: the chord i-j is a polygon edge or an interior diagonal.
  Array<char>& ok = scratch.ok;
  ok.assign(k * k, 0);
  for (int i = 0; i < k; ++i)
    for (int j = i + 1; j < k; ++j)
      ok[i * k + j] = (j == i + 1 || (i == 0 && j == k - 1)) ? 1 : isDiagonal(P, i, j, orient);
  // cost[i][j]: best largest angle triangulating the chain i..j closed by chord i-j.
  Array<double>& cost = scratch.cost;
  Array<int>& apex = scratch.apex;
  cost.assign(k * k, inf);
  apex.assign(k * k, -1);
  for (int i = 0; i + 1 < k; ++i)
    cost[i * k + i + 1] = 0;
  for (int len = 2; len < k; ++len)
  {
    for (int i = 0; i + len < k; ++i)
    {
      const int j = i + len;
      if (!ok[i * k + j])
        continue;
      for (int m = i + 1; m < j; ++m)
      {
        const double sub = std::max(cost[i * k + m], cost[m * k + j]);
        if (sub >= cost[i * k + j] || orientSign(P[i], P[m], P[j]) <= 0)
          continue;
        const double c = std::max(sub, maxAngle(P[i], P[m], P[j]));
        if (c < cost[i * k + j])
        {
          cost[i * k + j] = c;
          apex[i * k + j] = m;
        }
      }
    }
  }
  if (cost[k - 1] == inf)
    return false;
  Array<std::pair<int, int>>& stack = scratch.stack;
  stack.assign(1, { 0, k - 1 });
  while (!stack.empty())
  {
    const auto [i, j] = stack.back();
    stack.pop_back();
    if (j - i < 2)
      continue;
    const int m = apex[i * k + j];
    out.push_back({ ids[i], ids[m], ids[j] });
    stack.push_back({ i, m });
    stack.push_back({ m, j });
  }
  return true;
}

namespace
{

/// Neighbours of each vertex sorted counter-clockwise, in CSR form.
struct Rotation
{
  Array<int> start;
  Array<int> to;
  Array<int> twin;    ///< half-edge v->u for half-edge u->v
  Array<char> closed; ///< its face (on its left) is intact or outside: not traced
};

bool upperHalf(const Point& c, const Point& p)
{
  return p.y > c.y || (p.y == c.y && p.x > c.x);
}

/// The rotation system of the edges that bound a face still to be traced.
Rotation buildRotation(const PlanarGraph& g, RunContext& run)
{
  const int n = static_cast<int>(g.points.size());
  const int ne = static_cast<int>(g.edges.size());
  Rotation r;
  r.start.assign(n + 1, 0);
  for (int e = 0; e < ne; ++e)
  {
    if (!g.openSides[e])
      continue;
    ++r.start[g.edges[e][0] + 1];
    ++r.start[g.edges[e][1] + 1];
  }
  for (int v = 0; v < n; ++v)
    r.start[v + 1] += r.start[v];
  // Each half-edge carries its edge through the angular sort, so the two
  // half-edges of an edge find each other in one linear pass afterwards.
  Array<std::array<int, 2>> half(r.start[n]); // (head, edge)
  Array<int> fill(r.start.begin(), r.start.end() - 1);
  for (int e = 0; e < ne; ++e)
  {
    if (!g.openSides[e])
      continue;
    half[fill[g.edges[e][0]]++] = { g.edges[e][1], e };
    half[fill[g.edges[e][1]]++] = { g.edges[e][0], e };
  }
  run.poll();
  for (int v = 0; v < n; ++v)
  {
    run.pollEvery(1u << 16);
    const Point& c = g.points[v];
    std::sort(half.begin() + r.start[v], half.begin() + r.start[v + 1],
      [&](const std::array<int, 2>& ha, const std::array<int, 2>& hb) {
        const Point &a = g.points[ha[0]], &b = g.points[hb[0]];
        const bool ua = upperHalf(c, a), ub = upperHalf(c, b);
        if (ua != ub)
          return ua;
        return orientSign(c, a, b) > 0;
      });
  }
  r.to.resize(half.size());
  r.twin.assign(half.size(), -1);
  r.closed.resize(half.size());
  Array<int> firstHalf(g.edges.size(), -1);
  for (int h = 0; h < static_cast<int>(half.size()); ++h)
  {
    run.pollEvery(1u << 16);
    r.to[h] = half[h][0];
    const int e = half[h][1];
    // A half-edge's face is on its left: the edge's left side if it runs forward.
    r.closed[h] = !(g.openSides[e] & (g.edges[e][1] == half[h][0] ? OpenLeft : OpenRight));
    int& first = firstHalf[half[h][1]];
    if (first < 0)
      first = h;
    else
    {
      r.twin[h] = first;
      r.twin[first] = h;
    }
  }
  return r;
}

/// Vertex at the tail of half-edge h.
int tailOf(const Rotation& r, int h)
{
  return r.to[r.twin[h]];
}

/// A face no more than this many units in the last place of the largest
/// coordinate across is below what the stitched points resolve: a crossing
/// with a segment that spans the input is placed to within a few units of
/// the segment's scale, not of the face's.
constexpr double kResolvedUlps = 4096;

/// The smallest distance from a vertex of polygon to a side not at it.
double smallestGap(const Array<Point>& polygon)
{
  const std::size_t n = polygon.size();
  double gap = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < n; ++j)
  {
    const Point& a = polygon[j];
    const Point& b = polygon[(j + 1) % n];
    const double dx = b.x - a.x, dy = b.y - a.y, length2 = dx * dx + dy * dy;
    for (std::size_t i = 0; i < n; ++i)
    {
      if (i == j || i == (j + 1) % n)
        continue;
      const Point& p = polygon[i];
      const double t =
        length2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / length2, 0.0, 1.0) : 0.0;
      gap = std::min(gap, std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy)));
    }
  }
  return gap;
}

/// Why a face could not be triangulated. A face near the resolution of the
/// input's scale (tiny segments at the crossing of long ones, 1e-13 from it
/// at coordinates about 1) is distorted by the rounding of the points placed
/// on the long ones, and may not be simple (Properties.TinySegmentsAt...: a
/// face 2e-14 across ran twice through crossings of long segments 1e-18
/// apart); else it is a defect of ours.
Stop untriangulable(const Array<Point>& points, const Array<Point>& polygon)
{
  double scale = 0, across = 0;
  for (const Point& p : points)
    scale = std::max({ scale, std::fabs(p.x), std::fabs(p.y) });
  for (std::size_t i = 0; i < polygon.size(); ++i)
    for (std::size_t j = i + 1; j < polygon.size(); ++j)
      across = std::max(across, std::sqrt(dist2(polygon[i], polygon[j])));
  const double resolved = kResolvedUlps * std::numeric_limits<double>::epsilon() * scale;
  const std::string face =
    "a face of the stitched mesh with " + std::to_string(polygon.size()) + " sides";
  if (across <= resolved)
    return Stop{ std::string(kPointsTooCloseSubject) +
        " together than double precision resolves at the input's scale (" + face + ", " +
        roughNumber(across / scale) + " of the mesh's extent across, could not be triangulated)",
      true, polygon[0], { -1, -1 }, Stop::Remedy::MergePoints };
  // A wide face can be distorted too: by a point too near a long segment
  // (found by a review, as an "internal error": a point 7e-13 from a segment
  // 7e5 long).
  const double gap = smallestGap(polygon);
  if (gap <= resolved)
    return Stop{ "input points and segments come closer than double precision resolves at the "
                 "input's scale (" +
        face + ", a vertex " +
        (gap > 0 ? roughNumber(gap / scale) + " of the mesh's extent from" : "on") +
        " a side, could not be triangulated)",
      true, polygon[0], { -1, -1 }, Stop::Remedy::JoinSegments };
  return Stop{ "internal error: " + face + " could not be triangulated", true, polygon[0] };
}

} // namespace

Completion complete(PlanarGraph& g, Statistics& stats, RunContext& run)
{
  // This round's counts, as stitch's.
  stats.facesCompleted = stats.largestFace = 0;
  Completion out;
  out.triangles = std::move(g.intact);
  if (!out.triangles.empty())
    stats.largestFace = std::max<std::size_t>(stats.largestFace, 3);
  // Reports split the phase: rotation, tracing, triangulating (a review
  // measured 0.3 s without a report at 4.5 million triangles, for an abort
  // set from another thread to wait).
  Rotation r = buildRotation(g, run);
  run.report(0.2);
  const int nh = static_cast<int>(r.to.size());
  for (std::size_t e = 0; e < g.edges.size(); ++e)
    if (g.constrained[e])
      out.constrainedEdges.push_back(
        { std::min(g.edges[e][0], g.edges[e][1]), std::max(g.edges[e][0], g.edges[e][1]) });
  // Trace every open face: after u->v, turn to the edge clockwise-next from
  // v->u. Half-edges of intact triangles and of the box's outside start seen.
  // Faces are stored flat (faceStart, faceVertices) to avoid an allocation each.
  Array<char> seen = std::move(r.closed);
  Array<int> faceStart{ 0 }, faceVertices;
  faceVertices.reserve(nh);
  for (int h0 = 0; h0 < nh; ++h0)
  {
    run.tickWith([&] { return 0.2 + 0.3 * double(h0) / double(nh); }, 1u << 16);
    if (seen[h0])
      continue;
    int h = h0;
    do
    {
      seen[h] = 1;
      const int v = r.to[h];
      faceVertices.push_back(tailOf(r, h));
      const int back = r.twin[h]; // v->u, inside v's rotation
      h = back == r.start[v] ? r.start[v + 1] - 1 : back - 1;
    } while (!seen[h]);
    if (h != h0)
      throw Stop{ "internal error: a face to complete runs into an intact triangle" };
    faceStart.push_back(static_cast<int>(faceVertices.size()));
  }
  // A face of k sides gives k - 2 triangles.
  out.triangles.reserve(out.triangles.size() + faceVertices.size() - 2 * (faceStart.size() - 1));
  Array<Point> polygon;
  MinMaxScratch scratch;
  Array<int> face;
  for (std::size_t f = 0; f + 1 < faceStart.size(); ++f)
  {
    run.tickWith([&] { return 0.5 + 0.5 * double(f) / double(faceStart.size()); }, 1u << 10);
    face.assign(faceVertices.begin() + faceStart[f], faceVertices.begin() + faceStart[f + 1]);
    stats.largestFace = std::max(stats.largestFace, face.size());
    if (face.size() == 3)
    {
      if (orientSign(g.points[face[0]], g.points[face[1]], g.points[face[2]]) <= 0)
        throw Stop{ "internal error: a stitched face is not positively oriented" };
      out.triangles.push_back({ face[0], face[1], face[2] });
      continue;
    }
    ++stats.facesCompleted;
    // Lemma 1 bounds faces by 6 sides; the cubic search must never stall a run.
    if (face.size() > kLargestFaceHandled)
      throw Stop{ "stitching left a face with " + std::to_string(face.size()) +
        " sides (the paper's bound is 6), more than the completion handles (" +
        std::to_string(kLargestFaceHandled) + ")" };
    polygon.clear();
    for (int v : face)
      polygon.push_back(g.points[v]);
    if (!triangulateMinMaxAngle(polygon, face, out.triangles, scratch))
      throw untriangulable(g.points, polygon);
  }
  return out;
}

} // namespace osm
