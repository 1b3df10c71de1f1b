#include "Interpolation.h"

#include "Delaunay.h"
#include "Predicates.h"
#include "SpatialSort.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace osm
{
namespace
{

/// Where p projects onto the segment ab (a != b): 0 at a, 1 at b, clamped.
double along(const Point& p, const Point& a, const Point& b)
{
  const double dx = b.x - a.x, dy = b.y - a.y;
  return std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
}

/// The valid input segments in grid cells of about their own spacing, each in
/// every cell its reach-wide neighbourhood meets: the cell of a point lists
/// every segment within reach of it.
class SegmentGrid
{
public:
  SegmentGrid(const Pslg& input, double reach)
    : in(input)
    , reach(reach)
  {
    Array<int> valid;
    Bounds b = emptyBounds();
    double length = 0;
    const int n = static_cast<int>(in.points.size());
    for (int s = 0; s < static_cast<int>(in.segments.size()); ++s)
    {
      const Segment& e = in.segments[s];
      if (e[0] < 0 || e[1] < 0 || e[0] >= n || e[1] >= n || in.points[e[0]] == in.points[e[1]])
        continue;
      valid.push_back(s);
      extend(b, in.points[e[0]]);
      extend(b, in.points[e[1]]);
      length += std::sqrt(dist2(in.points[e[0]], in.points[e[1]]));
    }
    if (valid.empty())
      return;
    box = { { b.lo.x - reach, b.lo.y - reach }, { b.hi.x + reach, b.hi.y + reach } };
    // About two cells per segment, however the segments are spread, and at
    // least half a segment's mean length: a segment then covers a few cells.
    const double m = 2.0 * static_cast<double>(valid.size());
    cell = std::max({ std::sqrt(box.width() * box.height() / m),
      std::max(box.width(), box.height()) / m, length / m });
    nx = static_cast<int>(box.width() / cell) + 1;
    ny = static_cast<int>(box.height() / cell) + 1;
    Array<std::pair<int, int>> entries; // (cell, segment)
    for (int s : valid)
      cover(s, entries);
    std::sort(entries.begin(), entries.end());
    entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
    start.assign(static_cast<std::size_t>(nx) * ny + 1, 0);
    for (const auto& e : entries)
      ++start[e.first + 1];
    for (std::size_t c = 1; c < start.size(); ++c)
      start[c] += start[c - 1];
    ids.reserve(entries.size());
    for (const auto& e : entries)
      ids.push_back(e.second);
  }

  /// The input segment nearest p if within reach, else -1; t is p's
  /// position along it (0 at its first point, 1 at its second).
  int nearest(const Point& p, double& t) const
  {
    if (ids.empty() || p.x < box.lo.x || p.y < box.lo.y || p.x > box.hi.x || p.y > box.hi.y)
      return -1;
    const std::size_t c = cellOf(p);
    int best = -1;
    double bestDistance2 = reach * reach;
    for (std::size_t k = start[c]; k < start[c + 1]; ++k)
    {
      const Segment& e = in.segments[ids[k]];
      const Point &a = in.points[e[0]], &b = in.points[e[1]];
      const double u = along(p, a, b);
      const double d2 = dist2(p, { a.x + u * (b.x - a.x), a.y + u * (b.y - a.y) });
      if (d2 <= bestDistance2)
      {
        best = ids[k];
        bestDistance2 = d2;
        t = u;
      }
    }
    return best;
  }

private:
  const Pslg& in;
  double reach;
  Bounds box{};
  double cell = 1;
  int nx = 0, ny = 0;
  Array<std::size_t> start;
  Array<int> ids;

  std::size_t cellOf(const Point& p) const
  {
    const int i = std::min(nx - 1, static_cast<int>((p.x - box.lo.x) / cell));
    const int j = std::min(ny - 1, static_cast<int>((p.y - box.lo.y) / cell));
    return static_cast<std::size_t>(j) * nx + i;
  }

  /// Lists s in the cells its reach-wide neighbourhood meets, a piece of at
  /// most a cell's length at a time (so a long diagonal takes a band of
  /// cells, not its bounding box's).
  void cover(int s, Array<std::pair<int, int>>& entries) const
  {
    const Point a = in.points[in.segments[s][0]], b = in.points[in.segments[s][1]];
    const int pieces = static_cast<int>(std::ceil(std::sqrt(dist2(a, b)) / cell)) + 1;
    for (int k = 0; k < pieces; ++k)
    {
      const double t0 = double(k) / pieces, t1 = double(k + 1) / pieces;
      const Point p = { a.x + t0 * (b.x - a.x), a.y + t0 * (b.y - a.y) };
      const Point q = { a.x + t1 * (b.x - a.x), a.y + t1 * (b.y - a.y) };
      const auto lo = cellIndex({ std::min(p.x, q.x) - reach, std::min(p.y, q.y) - reach });
      const auto hi = cellIndex({ std::max(p.x, q.x) + reach, std::max(p.y, q.y) + reach });
      for (int j = lo.second; j <= hi.second; ++j)
        for (int i = lo.first; i <= hi.first; ++i)
          entries.push_back({ j * nx + i, s });
    }
  }

  std::pair<int, int> cellIndex(const Point& p) const
  {
    auto clampTo = [](double x, int n) {
      return x <= 0 ? 0 : x >= n - 1 ? n - 1 : static_cast<int>(x);
    };
    return { clampTo((p.x - box.lo.x) / cell, nx), clampTo((p.y - box.lo.y) / cell, ny) };
  }
};

/// A power of two that brings the largest coordinate of a and b near 1
/// (within the normal range of powers of two).
double unitScale(const Array<Point>& a, const Array<Point>& b)
{
  double largest = 0;
  for (const Array<Point>* points : { &a, &b })
    for (const Point& p : *points)
      largest = std::max({ largest, std::abs(p.x), std::abs(p.y) });
  // Within the normal range: subnormal coordinates come near 1e-12, enough.
  return largest > 0 && std::isfinite(largest)
    ? std::ldexp(1.0, std::clamp(-std::ilogb(largest), -1000, 1000))
    : 1.0;
}

/// The points of input times scale, and its segments.
Pslg scaledBy(const Pslg& input, double scale)
{
  Pslg scaled;
  scaled.points.reserve(input.points.size());
  for (const Point& q : input.points)
    scaled.points.push_back({ q.x * scale, q.y * scale });
  scaled.segments = input.segments;
  return scaled;
}

/// The distance within which a vertex lies on a segment: the tolerance, and
/// at least what rounding a stitch vertex moves it by.
double onSegmentReach(const Pslg& input, double tolerance)
{
  const Bounds b = boundsOf(input.points);
  const double magnitude =
    std::max({ std::abs(b.lo.x), std::abs(b.lo.y), std::abs(b.hi.x), std::abs(b.hi.y) });
  const double extent = std::max(b.width(), b.height());
  return std::max({ tolerance, 1e-9 * extent,
    64 * std::numeric_limits<double>::epsilon() * magnitude, std::numeric_limits<double>::min() });
}

/// The terms of p in triangle t of T, from those of its known vertices
/// (knownOf: T's vertex to mesh vertex, -1 for the box corners): barycentric
/// where all three are known, else along the known edge or at the known
/// vertex.
template <typename KnownTerms>
void termsIn(const Triangulation& T, int t, const Point& p, const Array<int>& knownOf,
  const KnownTerms& knownTerms, VertexTerms& out)
{
  int real[3];
  int count = 0;
  for (int i = 0; i < 3; ++i)
    if (knownOf[T.tri[t].v[i]] >= 0)
      real[count++] = i;
  double lambda[3] = { 0, 0, 0 };
  if (count == 3)
  {
    const Point &a = T.vertex(t, 0), &b = T.vertex(t, 1), &c = T.vertex(t, 2);
    auto cross = [](const Point& o, const Point& u, const Point& v) {
      return (u.x - o.x) * (v.y - o.y) - (u.y - o.y) * (v.x - o.x);
    };
    lambda[0] = std::max(0.0, cross(p, b, c));
    lambda[1] = std::max(0.0, cross(a, p, c));
    lambda[2] = std::max(0.0, cross(a, b, p));
  }
  else if (count == 2)
  {
    const double s = along(p, T.vertex(t, real[0]), T.vertex(t, real[1]));
    lambda[real[0]] = 1 - s;
    lambda[real[1]] = s;
  }
  else if (count == 1)
    lambda[real[0]] = 1;
  if (count == 0)
    return; // no known vertex (a triangulation with none in it): no terms
  double sum = lambda[0] + lambda[1] + lambda[2];
  if (sum <= 0) // p on a vertex within rounding: take the nearest
  {
    int nearest = real[0];
    for (int k = 1; k < count; ++k)
      if (dist2(p, T.vertex(t, real[k])) < dist2(p, T.vertex(t, nearest)))
        nearest = real[k];
    lambda[nearest] = sum = 1;
  }
  for (int i = 0; i < 3; ++i)
    if (lambda[i] > 0)
    {
      VertexTerms k;
      knownTerms(static_cast<std::size_t>(knownOf[T.tri[t].v[i]]), k);
      for (int j = 0; j < k.count; ++j)
        out.add(k.point[j], lambda[i] / sum * k.weight[j]);
    }
}

/// A live triangle of T whose closure holds p, found by a walk from start;
/// beyond the padded box, the one the walk left by. Every triangle by brute
/// force where the walk fails (only on an invalid triangulation).
int triangleHolding(const Triangulation& T, const Point& p, int start)
{
  int exit = -1;
  const int t = T.locate(p, start, &exit);
  if (t >= 0)
    return t;
  if (t == -1 && exit >= 0)
    return exit / 3;
  for (int u = 0; u < T.slots(); ++u)
    if (T.alive(u) && orient2d(T.vertex(u, 0), T.vertex(u, 1), p) >= 0 &&
      orient2d(T.vertex(u, 1), T.vertex(u, 2), p) >= 0 &&
      orient2d(T.vertex(u, 2), T.vertex(u, 0), p) >= 0)
      return u;
  return start;
}

} // namespace

void VertexTerms::add(int p, double w)
{
  if (w <= 0)
    return;
  for (int k = 0; k < count; ++k)
    if (point[k] == p)
    {
      weight[k] += w;
      return;
    }
  point[count] = p;
  weight[count++] = w;
}

bool visitInputWeights(
  const Pslg& input, const Result& result, double tolerance, const TermsVisitor& visit)
{
  const pages::Reuse reuse; // the scratch arrays in huge pages, freed ones used again
  const Array<Point>& vertices = result.mesh.vertices;
  const std::size_t n = vertices.size();
  Array<int> inputPoint(n, -1);
  for (std::size_t i = 0; i < result.inputVertex.size(); ++i)
  {
    const int v = result.inputVertex[i];
    if (v >= 0 && inputPoint[v] < 0)
      inputPoint[v] = static_cast<int>(i);
  }

  // Coordinates scaled by a power of two (exactly) to magnitudes about 1,
  // so that no square or circumcircle test overflows, at 1e300 or 1e-300.
  const double scale = unitScale(input.points, vertices);
  const Pslg scaled = scaledBy(input, scale);
  auto at = [&](std::size_t v) { return Point{ vertices[v].x * scale, vertices[v].y * scale }; };

  // Input vertices and points on segments: their own terms, visited at once
  // and kept as (input point or segment, position along it) for the others.
  const SegmentGrid grid(scaled, onSegmentReach(scaled, tolerance * scale));
  Array<int> unknown;
  Array<Point> knownPoints;
  Array<int> knownSegment;  // per known point: its segment, or -1
  Array<double> knownAlong; // its position along that segment, or its input point
  auto knownTerms = [&](std::size_t k, VertexTerms& t) {
    if (knownSegment[k] < 0)
      t.add(static_cast<int>(knownAlong[k]), 1.0);
    else
    {
      const Segment& e = input.segments[knownSegment[k]];
      t.add(e[0], 1 - knownAlong[k]);
      t.add(e[1], knownAlong[k]);
    }
  };
  for (std::size_t v = 0; v < n; ++v)
  {
    // Overlay Steiner points lie on a segment only by chance; the others
    // are looked up.
    double t = 0;
    const bool lookUp = inputPoint[v] < 0 && result.vertexOrigin[v] != VertexOrigin::Overlay;
    const int segment = lookUp ? grid.nearest(at(v), t) : -1;
    if (inputPoint[v] < 0 && segment < 0)
    {
      unknown.push_back(static_cast<int>(v));
      continue;
    }
    knownPoints.push_back(at(v));
    knownSegment.push_back(segment);
    knownAlong.push_back(segment < 0 ? inputPoint[v] : t);
    VertexTerms terms;
    terms.vertex = v;
    terms.inputPoint = inputPoint[v];
    terms.segment = segment;
    knownTerms(knownPoints.size() - 1, terms);
    if (!visit(terms))
      return false;
  }
  if (unknown.empty())
    return true;

  // The others: within the Delaunay triangle of the known points that holds them.
  Array<int> knownOf;
  Triangulation T;
  if (!knownPoints.empty())
  {
    Array<int> vertexOf;
    // Corners far away: a triangle with a corner then lies beyond a hull
    // edge of the known points (to within 2^-26 of their extent), so the
    // triangles without one cover their hull.
    T = delaunayTriangulation(knownPoints, vertexOf, 0x1p26);
    knownOf.assign(T.points.size(), -1);
    for (std::size_t k = 0; k < vertexOf.size(); ++k)
      if (vertexOf[k] >= 0)
        knownOf[vertexOf[k]] = static_cast<int>(k);
  }
  Array<Point> unknownPoints;
  unknownPoints.reserve(unknown.size());
  for (int v : unknown)
    unknownPoints.push_back(at(v));
  int start = 0;
  while (start < T.slots() && !T.alive(start))
    ++start;
  for (int k : hilbertOrder(unknownPoints))
  {
    VertexTerms terms;
    terms.vertex = static_cast<std::size_t>(unknown[k]);
    if (knownPoints.size() == 1) // no extent to pad: that point's value everywhere
      knownTerms(0, terms);
    else if (start < T.slots())
    {
      start = triangleHolding(T, unknownPoints[k], start);
      termsIn(T, start, unknownPoints[k], knownOf, knownTerms, terms);
    }
    if (!visit(terms))
      return false;
  }
  return true;
}

Array<int> segmentsUnder(const Pslg& input, const Array<Point>& points, double tolerance)
{
  const double scale = unitScale(input.points, points);
  const Pslg scaled = scaledBy(input, scale);
  const SegmentGrid grid(scaled, onSegmentReach(scaled, tolerance * scale));
  Array<int> under;
  under.reserve(points.size());
  for (const Point& p : points)
  {
    double t = 0;
    under.push_back(grid.nearest({ p.x * scale, p.y * scale }, t));
  }
  return under;
}

} // namespace osm
