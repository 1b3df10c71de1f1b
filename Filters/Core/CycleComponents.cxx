#include "CycleComponents.h"

#include <algorithm>
#include <cmath>

namespace osm
{
namespace
{

/// The segments at each vertex, as rows of a compressed array.
struct Incidence
{
  Incidence(std::size_t pointCount, const Array<Segment>& segments)
    : start(pointCount + 1, 0)
    , items(2 * segments.size())
  {
    for (const Segment& s : segments)
      ++start[s[0] + 1], ++start[s[1] + 1];
    for (std::size_t v = 0; v < pointCount; ++v)
      start[v + 1] += start[v];
    Array<int> fill(start.begin(), start.end() - 1);
    for (std::size_t k = 0; k < segments.size(); ++k)
      for (int v : segments[k])
        items[fill[v]++] = static_cast<int>(k);
  }
  Array<int> start, items;
};

/// Per segment, whether it is a bridge: Tarjan's low points, by a depth-first
/// search with an explicit stack. The tree edge a vertex was reached by is
/// skipped by its id, so a second segment with the same ends is a back edge.
Array<char> bridges(std::size_t pointCount, const Array<Segment>& segments, const Incidence& at)
{
  Array<int> order(pointCount, -1), low(pointCount, 0);
  Array<char> bridge(segments.size(), 0);
  struct Frame
  {
    int v, via, next; // vertex, segment it was reached by, next incidence
  };
  Array<Frame> stack;
  int time = 0;
  for (std::size_t root = 0; root < pointCount; ++root)
  {
    if (order[root] >= 0 || at.start[root] == at.start[root + 1])
      continue;
    order[root] = low[root] = time++;
    stack.push_back({ static_cast<int>(root), -1, at.start[root] });
    while (!stack.empty())
    {
      Frame& f = stack.back();
      if (f.next < at.start[f.v + 1])
      {
        const int e = at.items[f.next++];
        if (e == f.via)
          continue;
        const int u = segments[e][0] == f.v ? segments[e][1] : segments[e][0];
        if (order[u] < 0)
        {
          order[u] = low[u] = time++;
          stack.push_back({ u, e, at.start[u] });
        }
        else
          low[f.v] = std::min(low[f.v], order[u]);
        continue;
      }
      const Frame done = f;
      stack.pop_back();
      if (stack.empty())
        break;
      const int parent = stack.back().v;
      low[parent] = std::min(low[parent], low[done.v]);
      if (low[done.v] > order[parent])
        bridge[done.via] = 1;
    }
  }
  return bridge;
}

} // namespace

CycleComponents cycleComponents(std::size_t pointCount, const Array<Segment>& segments)
{
  const Incidence at(pointCount, segments);
  const Array<char> bridge = bridges(pointCount, segments, at);
  CycleComponents out;
  out.component.assign(segments.size(), -1);
  // Flood each component over its non-bridge segments from its first one.
  Array<int> pending;
  for (std::size_t first = 0; first < segments.size(); ++first)
  {
    if (bridge[first] || out.component[first] >= 0)
      continue;
    const int id = static_cast<int>(out.count++);
    out.component[first] = id;
    pending.assign(segments[first].begin(), segments[first].end());
    while (!pending.empty())
    {
      const int v = pending.back();
      pending.pop_back();
      for (int k = at.start[v]; k < at.start[v + 1]; ++k)
      {
        const int e = at.items[k];
        if (bridge[e] || out.component[e] >= 0)
          continue;
        out.component[e] = id;
        const int u = segments[e][0] == v ? segments[e][1] : segments[e][0];
        pending.push_back(u);
      }
    }
  }
  return out;
}

Array<Bounds> cycleBounds(
  const Array<Point>& points, const Array<Segment>& segments, const CycleComponents& cycles)
{
  Array<Bounds> boxes(cycles.count, emptyBounds());
  for (std::size_t k = 0; k < segments.size(); ++k)
    if (const int c = cycles.component[k]; c >= 0)
      for (int v : segments[k])
        extend(boxes[c], points[v]);
  return boxes;
}

Array<double> simpleCycleAreas(
  const Array<Point>& points, const Array<Segment>& segments, const CycleComponents& cycles)
{
  Array<int> degree(points.size(), 0); // segments on cycles at each point
  for (std::size_t k = 0; k < segments.size(); ++k)
    if (cycles.component[k] >= 0)
      ++degree[segments[k][0]], ++degree[segments[k][1]];
  Array<double> area(cycles.count, 0.0);
  for (std::size_t k = 0; k < segments.size(); ++k)
    if (const int c = cycles.component[k]; c >= 0 && area[c] >= 0)
      if (degree[segments[k][0]] != 2 || degree[segments[k][1]] != 2)
        area[c] = -1.0;
  // Walk each simple cycle from its first segment; the other segment at each
  // point is its next one.
  const Incidence at(points.size(), segments);
  Array<char> started(cycles.count, 0);
  for (std::size_t first = 0; first < segments.size(); ++first)
  {
    const int c = cycles.component[first];
    if (c < 0 || area[c] < 0 || started[c])
      continue;
    started[c] = 1;
    double twice = 0;
    int e = static_cast<int>(first), v = segments[first][1], from = segments[first][0];
    for (;;)
    {
      twice += points[from].x * points[v].y - points[v].x * points[from].y;
      if (v == segments[first][0])
        break;
      int next = -1;
      for (int i = at.start[v]; i < at.start[v + 1] && next < 0; ++i)
        if (at.items[i] != e && cycles.component[at.items[i]] == c)
          next = at.items[i];
      e = next;
      from = v;
      v = segments[e][0] == v ? segments[e][1] : segments[e][0];
    }
    area[c] = 0.5 * std::abs(twice);
  }
  return area;
}

} // namespace osm
