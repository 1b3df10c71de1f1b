#include "SplitCrossings.h"

#include "Clean.h"
#include "Predicates.h"
#include "Statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace osm
{

namespace
{

/// Where p lies along segment s (a multiple of its projection on it).
double along(const Work& w, int s, const Point& p)
{
  const Point& a = w.points[w.segments[s][0]];
  const Point& b = w.points[w.segments[s][1]];
  return (p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y);
}

/// Crossing points closer than this many units of the last place of their
/// coordinates are one point (mergeNearCrossings). The overlay cannot keep
/// input points that close apart (it resolves 64 units), so merging them only
/// turns what would fail into a mesh.
constexpr double kCrossingMergeUlps = 32;

/// The unit of the last place at p's scale.
double ulpAt(const Point& p)
{
  return std::numeric_limits<double>::epsilon() * std::max(std::fabs(p.x), std::fabs(p.y));
}

/// The unit of the last place of crossing c's computation: its point is
/// placed along the shorter of its two segments, so it is off by a few units
/// at that segment's scale, not at its own (near the origin, its own is far
/// smaller: three segments through (0, 0) crossed 1e-16 apart, and the mesh
/// graded down to that). With a hull edge, whose ends are not at hand, p's.
double crossingUlp(const Work& w, const SegmentCrossing& c)
{
  const int n = static_cast<int>(w.segments.size());
  if (c.a >= n || c.b >= n)
    return ulpAt(c.p);
  const auto shorter = dist2(w.points[w.segments[c.a][0]], w.points[w.segments[c.a][1]]) <=
      dist2(w.points[w.segments[c.b][0]], w.points[w.segments[c.b][1]])
    ? c.a
    : c.b;
  return std::max({ ulpAt(c.p), ulpAt(w.points[w.segments[shorter][0]]),
    ulpAt(w.points[w.segments[shorter][1]]) });
}

/// Whether p, a crossing computed to within ulp, can stand for a crossing on
/// segment s: within a quarter of the merge distance of its line, and
/// strictly inside it, away from its ends. s bends to p, so that distance
/// is also at most 1.5 times as many units at s's own scale (12, where the
/// validator takes 16 as conforming): a segment far smaller than the one p
/// was computed on must not bend at the larger one's scale.
bool onSegment(const Work& w, int s, const Point& p, double crossingUlp)
{
  const Point &a = w.points[w.segments[s][0]], &b = w.points[w.segments[s][1]];
  const double own = std::max({ ulpAt(a), ulpAt(b), ulpAt(p) });
  const double ulp = std::min(std::max(crossingUlp, own), 1.5 * own);
  const double length = std::sqrt(dist2(a, b));
  const double t = along(w, s, p) / (length * length);
  const double margin = kCrossingMergeUlps * ulp / length;
  return std::fabs(orient2d(a, b, p)) / length <= kCrossingMergeUlps / 4 * ulp && t > margin &&
    t < 1 - margin;
}

/// Per crossing, the member of its class (root[k]) whose point serves the
/// whole class: the first that lies on every segment of the class (onSegment).
/// A class with no such point is not merged: each crossing keeps its own
/// point, and what cannot be meshed is said as before.
Array<int> representatives(
  const Work& w, const Array<SegmentCrossing>& crossings, const Array<int>& root)
{
  Array<int> byClass(crossings.size());
  for (std::size_t k = 0; k < byClass.size(); ++k)
    byClass[k] = static_cast<int>(k);
  std::stable_sort(byClass.begin(), byClass.end(), [&](int x, int y) { return root[x] < root[y]; });
  Array<int> best(crossings.size());
  Array<int> lines;
  for (std::size_t i = 0; i < byClass.size();)
  {
    std::size_t end = i;
    lines.clear();
    for (; end < byClass.size() && root[byClass[end]] == root[byClass[i]]; ++end)
      for (int s : { crossings[byClass[end]].a, crossings[byClass[end]].b })
        if (s < static_cast<int>(w.segments.size()))
          lines.push_back(s);
    int chosen = -1;
    for (std::size_t j = i; j < end && chosen < 0 && end - i > 1; ++j)
    {
      const Point& p = crossings[byClass[j]].p;
      const double ulp = crossingUlp(w, crossings[byClass[j]]);
      if (std::all_of(lines.begin(), lines.end(), [&](int s) { return onSegment(w, s, p, ulp); }))
        chosen = byClass[j];
    }
    for (std::size_t j = i; j < end; ++j)
      best[byClass[j]] = chosen >= 0 ? chosen : byClass[j];
    i = end;
  }
  return best;
}

/// A crossing on a segment, where along it (along()), for sorting.
struct CrossingCut
{
  int segment;
  double t;
  int crossing;
};

/// How far (in units of the last place of its computation) a crossing may
/// move to join another in joinIllConditioned: 256 covers two segments 0.2
/// degrees apart. Further, the segments are so nearly parallel that where
/// they meet barely matters to them but much to a third nearly parallel one
/// through the other point (a review: three such segments meshed apart, and
/// joined 3.5e-13 away they were refused).
constexpr double kIllConditionedJoinUlps = 256;

/// A crossing of two nearly parallel segments is placed far along them by
/// rounding, ill-conditioned (an ulp off their lines moves it by an ulp over
/// their angle): 1.5e-14, over 60 units in the last place, from the crossings
/// of a third segment through the same point, for two segments 0.1 degrees
/// apart, which no mesh in double precision then separates. Such a crossing,
/// alone in its class, joins the nearest class of two or more next to it
/// along one of its segments whose point lies on both of its segments
/// (onSegment) within kIllConditionedJoinUlps: they bend by as little as for
/// any merge.
void joinIllConditioned(const Work& w, const Array<SegmentCrossing>& crossings,
  const Array<CrossingCut>& cuts, Array<int>& best)
{
  const int n = static_cast<int>(w.segments.size());
  Array<int> classSize(crossings.size(), 0);
  for (int b : best)
    ++classSize[b];
  Array<int> target(crossings.size(), -1);
  auto consider = [&](int lone, int other) {
    const SegmentCrossing& c = crossings[lone];
    const int rep = best[other];
    if (best[lone] != lone || classSize[lone] != 1 || classSize[rep] < 2 || c.a >= n || c.b >= n)
      return;
    const Point& p = crossings[rep].p;
    const double ulp = crossingUlp(w, crossings[rep]);
    const double reach = kIllConditionedJoinUlps * std::max(ulp, crossingUlp(w, c));
    if (dist2(c.p, p) > reach * reach || !onSegment(w, c.a, p, ulp) || !onSegment(w, c.b, p, ulp))
      return;
    if (target[lone] < 0 || dist2(c.p, p) < dist2(c.p, crossings[target[lone]].p))
      target[lone] = rep;
  };
  for (std::size_t i = 1; i < cuts.size(); ++i)
  {
    if (cuts[i].segment != cuts[i - 1].segment)
      continue;
    consider(cuts[i - 1].crossing, cuts[i].crossing);
    consider(cuts[i].crossing, cuts[i - 1].crossing);
  }
  for (std::size_t k = 0; k < target.size(); ++k)
    if (target[k] >= 0)
      best[k] = target[k];
}

/// Per crossing, the crossing whose point it takes: crossings next to each
/// other along a segment and closer than kCrossingMergeUlps are one point.
/// Three or more segments through one point (the medians of a triangle, roads
/// at a junction) give a crossing per pair, rounded apart by a few units in
/// the last place; kept apart, they are features that no mesh in double
/// precision can hold.
Array<int> mergeNearCrossings(const Work& w, const Array<SegmentCrossing>& crossings)
{
  Array<int> root(crossings.size());
  for (std::size_t k = 0; k < root.size(); ++k)
    root[k] = static_cast<int>(k);
  auto find = [&](int k) {
    while (root[k] != k)
      k = root[k] = root[root[k]];
    return k;
  };
  Array<CrossingCut> cuts;
  for (std::size_t k = 0; k < crossings.size(); ++k)
    for (int s : { crossings[k].a, crossings[k].b })
      if (s < static_cast<int>(w.segments.size())) // not a hull edge
        cuts.push_back({ s, along(w, s, crossings[k].p), static_cast<int>(k) });
  std::sort(cuts.begin(), cuts.end(), [](const CrossingCut& x, const CrossingCut& y) {
    return x.segment != y.segment ? x.segment < y.segment : x.t < y.t;
  });
  for (std::size_t i = 1; i < cuts.size(); ++i)
  {
    if (cuts[i].segment != cuts[i - 1].segment)
      continue;
    const SegmentCrossing& p = crossings[cuts[i - 1].crossing];
    const SegmentCrossing& q = crossings[cuts[i].crossing];
    const double tolerance = kCrossingMergeUlps * std::max(crossingUlp(w, p), crossingUlp(w, q));
    if (dist2(p.p, q.p) <= tolerance * tolerance)
    {
      const int a = find(cuts[i - 1].crossing), b = find(cuts[i].crossing);
      root[std::max(a, b)] = std::min(a, b);
    }
  }
  for (std::size_t k = 0; k < root.size(); ++k)
    root[k] = find(static_cast<int>(k));
  Array<int> best = representatives(w, crossings, root);
  joinIllConditioned(w, crossings, cuts, best);
  return best;
}

/// Whether q lies in triangle abc (closed), which must not be degenerate.
bool inTriangle(const Point& a, const Point& b, const Point& c, const Point& q)
{
  const double o = orient2d(a, b, c), o1 = orient2d(a, b, q), o2 = orient2d(b, c, q),
               o3 = orient2d(c, a, q);
  return o != 0 && (o > 0 ? o1 >= 0 && o2 >= 0 && o3 >= 0 : o1 <= 0 && o2 <= 0 && o3 <= 0);
}

/// The seeds of w in the area that its segments swept as their ends moved
/// to where c put them (at a, b before; a2, b2 after): the triangles
/// (a, b, b2) and (a, b2, a2), as a join moves one end, rarely both.
SeedsAcross seedsAcrossJoins(const Work& w, const CleanPslg& c)
{
  SeedsAcross found;
  if (w.holes.empty() && w.regionSeeds.empty())
    return found;
  const auto moved = [&](int v) { return !(c.points[c.pointOf[v]] == w.points[v]); };
  Array<int> bent; // the segments with an end that moved: few
  for (std::size_t s = 0; s < w.segments.size(); ++s)
    if (moved(w.segments[s][0]) || moved(w.segments[s][1]))
      bent.push_back(static_cast<int>(s));
  auto check = [&](const Point& q, const char* kind, std::size_t k) {
    for (int s : bent)
    {
      const Segment& e = w.segments[s];
      const Point &a = w.points[e[0]], &b = w.points[e[1]];
      const Point &a2 = c.points[c.pointOf[e[0]]], &b2 = c.points[c.pointOf[e[1]]];
      if ((!(b == b2) && inTriangle(a, b, b2, q)) || (!(a == a2) && inTriangle(a, b2, a2, q)))
      {
        if (found.count++ == 0)
          found.example = std::string(kind) + " " + std::to_string(k) + " and segment " +
            std::to_string(w.segmentOrigin[s]);
        return;
      }
    }
  };
  for (std::size_t h = 0; h < w.holes.size(); ++h)
    check(w.holes[h], "hole", h);
  for (std::size_t r = 0; r < w.regionSeeds.size(); ++r)
    check(w.regionSeeds[r], "region", r);
  return found;
}

/// Which joins keep every segment within tol of its piece of the input: a
/// point may join another only if that lies within tol (and rounding) of the
/// pieces of all the segments through it. Without this a crossing of two
/// segments that an earlier round bent, itself up to tol off their pieces,
/// joined a point up to tol further (a review: pencils of lines at 1e-4,
/// chains up to 1.5 times the tolerance off their segments). Weak spots: of
/// segments that joins made the same, only the first one's piece counts
/// later; and a refused join can leave crossings that cross again until the
/// rounds give up (a review: 2 refusals more, 1 less, of 23,400 dense
/// pencils and junctions; 16 chains beyond the tolerance fewer).
JoinFilter withinTheirPieces(const Work& w, double tol)
{
  if (!(tol > 0))
    return {};
  Array<Array<int>> through(w.points.size()); // the segments through each point
  for (std::size_t s = 0; s < w.segments.size(); ++s)
    for (int v : w.segments[s])
      through[v].push_back(static_cast<int>(s));
  // Coordinates are scaled into [-1, 1): rounding is below 64 units there.
  const double reach = tol + 64 * std::numeric_limits<double>::epsilon();
  return [&w, through = std::move(through), reach](int i, int j) {
    for (int s : through[i])
    {
      const auto& [a, b] = w.piece[s];
      if (!(distanceToSegment(w.points[j], a, b) <= reach))
        return false;
    }
    return true;
  };
}

} // namespace

/// Split every segment at the points where others cross it.
void splitCrossings(Work& w, const Array<SegmentCrossing>& crossings, Statistics& stats)
{
  const Array<int> same = mergeNearCrossings(w, crossings);
  Array<int> vertexOf(crossings.size(), -1);
  Array<Array<std::pair<double, int>>> cuts(w.segments.size());
  for (std::size_t k = 0; k < crossings.size(); ++k)
  {
    const SegmentCrossing& c = crossings[k];
    int& v = vertexOf[same[k]];
    if (v < 0)
    {
      v = static_cast<int>(w.points.size());
      w.points.push_back(crossings[same[k]].p);
      w.isCrossingPoint.push_back(1);
    }
    for (int s : { c.a, c.b })
    {
      // Hull edges (numbered after the input's) are recomputed next round.
      if (s >= static_cast<int>(w.segments.size()))
        continue;
      cuts[s].push_back({ along(w, s, w.points[v]), v });
    }
    ++stats.crossingsSplit;
  }
  const std::size_t n = w.segments.size();
  for (std::size_t s = 0; s < n; ++s)
  {
    if (cuts[s].empty())
      continue;
    std::sort(cuts[s].begin(), cuts[s].end());
    // Merged crossings cut a segment once.
    cuts[s].erase(std::unique(cuts[s].begin(), cuts[s].end(),
                    [](const auto& x, const auto& y) { return x.second == y.second; }),
      cuts[s].end());
    int prev = w.segments[s][0];
    const int last = w.segments[s][1];
    for (std::size_t k = 0; k < cuts[s].size(); ++k)
    {
      const int v = cuts[s][k].second;
      if (k == 0)
        w.segments[s][1] = v;
      else
      {
        w.segments.push_back({ prev, v });
        w.segmentOrigin.push_back(w.segmentOrigin[s]);
        w.piece.push_back(w.piece[s]);
      }
      prev = v;
    }
    w.segments.push_back({ prev, last });
    w.segmentOrigin.push_back(w.segmentOrigin[s]);
    w.piece.push_back(w.piece[s]);
  }
}

/// Crossing points can coincide after rounding: merge them, drop what
/// degenerates. With a merge tolerance (tol, scaled), the crossings within it
/// of a point join it (the crossings of segments meant to meet at one point,
/// digitised apart). Input points, pairwise further apart than tol, come
/// first and stay where they are: a crossing joins them, not they it. No
/// segment is split at the points within tol of it, as in the input: a
/// crossing within tol of a third segment, but not of its crossings, would
/// bend it into a sliver with theirs, thinner than the tolerance and than
/// what the crossings left (a review: 52 of 12,600 generated inputs then
/// refused, and aust.poly at 1e-4 of its extent crossed anew every round).
/// Returns how many points joined another (at tol > 0; else coincided);
/// seeds receives the hole and region seeds that segments bent across.
std::size_t mergeEqualPoints(Work& w, double tol, SeedsAcross& seeds)
{
  Pslg p{ w.points, w.segments, {} };
  CleanPslg c;
  Statistics ignored;
  std::vector<std::string> ignoredWarnings;
  cleanPslg(p, c, ignored, ignoredWarnings, tol, {}, false, withinTheirPieces(w, tol));
  if (tol > 0 && c.points.size() < w.points.size())
    seeds = seedsAcrossJoins(w, c);
  // A point is the split's own only if every point merged into it is.
  Array<char> crossing(c.points.size(), 1);
  for (std::size_t i = 0; i < w.points.size(); ++i)
    crossing[c.pointOf[i]] &= w.isCrossingPoint[i];
  Array<int> origin;
  Array<std::array<Point, 2>> piece;
  for (int o : c.segmentOrigin)
  {
    origin.push_back(w.segmentOrigin[o]);
    piece.push_back(w.piece[o]);
  }
  const std::size_t joined = w.points.size() - c.points.size();
  w.points = std::move(c.points);
  w.isCrossingPoint = std::move(crossing);
  w.segments = std::move(c.segments);
  w.segmentOrigin = std::move(origin);
  w.piece = std::move(piece);
  return joined;
}

} // namespace osm
