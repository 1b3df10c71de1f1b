#include "NearMisses.h"

#include "Geometry.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <vector>

namespace osm
{

DanglingEnds::DanglingEnds(const OverlayEdges& ov, const Array<Point>& P,
  const Array<Segment>& segments, NearMissSearch search)
  : ov(ov)
  , P(P)
  , segments(segments)
  , search(search)
{
  if (!searching())
    return;
  endOf.assign(P.size(), -1);
  for (std::size_t s = 0; s < segments.size(); ++s)
    for (int v : segments[s])
      endOf[v] = endOf[v] == -1 ? static_cast<int>(s) : endOf[v] >= 0 ? -2 - endOf[v] : endOf[v];
}

/// Records end (dangling, its segment endOf[end]) as a near miss of segment
/// s, if both are the user's, within reach, and share no vertex (those meet
/// at a small angle, on purpose).
void DanglingEnds::add(int end, int s, Array<NearMiss>& out) const
{
  const int t = endOf[end];
  const auto inputs = static_cast<int>(search.inputSegments);
  if (t >= inputs || s >= inputs)
    return;
  const Segment &e = segments[t], &u = segments[s];
  if (e[0] == u[0] || e[0] == u[1] || e[1] == u[0] || e[1] == u[1])
    return;
  const double d = distanceToSegment(P[end], P[u[0]], P[u[1]]);
  if (d > 0 && d <= search.at(P[end]))
    out.push_back({ end, t, s, d });
}

/// An end a hair from another segment's end: the walk of neither crosses
/// the other's edges, but the overlay joins them (the nearest neighbour of a
/// point is a Delaunay neighbour), maybe through points in the gap that end
/// no segment (isolated input points, Steiner points): those within reach
/// are passed through.
void DanglingEnds::findAtEnds(Array<NearMiss>& out) const
{
  if (search.reach <= 0)
    return;
  Array<int> near; // the vertices within reach of v reached so far
  for (std::size_t v = 0; v < endOf.size(); ++v)
  {
    if (endOf[v] < 0)
      continue;
    const double reach = search.at(P[v]);
    near.assign(1, static_cast<int>(v));
    for (std::size_t k = 0; k < near.size() && k < 64; ++k)
      ov.forEachNeighbour(near[k], [&](int u) {
        if (dist2(P[v], P[u]) > reach * reach ||
          std::find(near.begin(), near.end(), u) != near.end())
          return;
        near.push_back(u);
        if (endOf[u] != -1)
          add(static_cast<int>(v), endOf[u] >= 0 ? endOf[u] : -2 - endOf[u], out);
      });
  }
}

/// Whether the end's own chain reaches the near segment within 64 times the
/// gap: a dense polyline turning back, or one whose last segments are shorter
/// than the reach, lies near its own earlier segments, not short of another
/// (a review). A loop that misses closing by the gap is far longer. ends:
/// (vertex, segment ending there), sorted; best and touched: scratch, all
/// infinite and empty between calls.
bool DanglingEnds::alongItsChain(const NearMiss& m, const Array<std::pair<int, int>>& ends,
  Array<double>& best, Array<int>& touched) const
{
  const double limit = 64 * m.distance;
  const Segment& target = segments[m.segment];
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  queue.push({ 0.0, m.end });
  best[m.end] = 0;
  touched.push_back(m.end);
  bool found = false;
  for (int pops = 0; !queue.empty() && pops < 256 && !found; ++pops)
  {
    const auto [d, v] = queue.top();
    queue.pop();
    found = v == target[0] || v == target[1];
    if (d > best[v])
      continue;
    for (auto it = std::lower_bound(ends.begin(), ends.end(), std::make_pair(v, -1));
         it != ends.end() && it->first == v; ++it)
    {
      const Segment& e = segments[it->second];
      const int u = e[0] == v ? e[1] : e[0];
      const double du = d + std::sqrt(dist2(P[v], P[u]));
      if (du <= limit && du < best[u])
      {
        if (best[u] == std::numeric_limits<double>::infinity())
          touched.push_back(u);
        best[u] = du;
        queue.push({ du, u });
      }
    }
  }
  for (int u : touched)
    best[u] = std::numeric_limits<double>::infinity();
  touched.clear();
  return found;
}

/// One near miss per end, the nearest (ties to the lower segment: the same
/// whatever the walk order), in the order of the ends.
void DanglingEnds::keepNearest(Array<NearMiss>& n)
{
  // Not an end that a segment passes through, nor one whose segment's other
  // end the near segment passes through (a small angle there), nor one whose
  // segment passes through an end of the near one (they meet there).
  std::sort(passes.begin(), passes.end());
  const auto passed = [&](int v, int s) {
    const auto it = std::lower_bound(passes.begin(), passes.end(), std::make_pair(v, s));
    return it != passes.end() && it->first == v && (s < 0 || it->second == s);
  };
  n.erase(std::remove_if(n.begin(), n.end(),
            [&](const NearMiss& m) {
              const Segment& e = segments[m.endSegment];
              const Segment& u = segments[m.segment];
              return passed(m.end, -1) || passed(e[0] == m.end ? e[1] : e[0], m.segment) ||
                passed(u[0], m.endSegment) || passed(u[1], m.endSegment);
            }),
    n.end());
  if (n.empty())
    return;
  // Nor a segment of the end's own chain (the segments by their ends, and
  // Dijkstra's distances along them; only where near misses are left).
  Array<std::pair<int, int>> ends;
  ends.reserve(2 * segments.size());
  for (std::size_t k = 0; k < segments.size(); ++k)
    for (int v : segments[k])
      ends.push_back({ v, static_cast<int>(k) });
  std::sort(ends.begin(), ends.end());
  Array<double> best(P.size(), std::numeric_limits<double>::infinity());
  Array<int> touched;
  n.erase(std::remove_if(n.begin(), n.end(),
            [&](const NearMiss& m) { return alongItsChain(m, ends, best, touched); }),
    n.end());
  std::sort(n.begin(), n.end(), [](const NearMiss& x, const NearMiss& y) {
    return x.end != y.end        ? x.end < y.end
      : x.distance != y.distance ? x.distance < y.distance
                                 : x.segment < y.segment;
  });
  n.erase(std::unique(n.begin(), n.end(),
            [](const NearMiss& x, const NearMiss& y) { return x.end == y.end; }),
    n.end());
}

} // namespace osm
