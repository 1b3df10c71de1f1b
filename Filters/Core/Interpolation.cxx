#include "Interpolation.h"

#include "Delaunay.h"
#include "Predicates.h"
#include "SpatialSort.h"

#include <algorithm>
#include <cmath>

namespace osm
{
namespace
{

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

/// Twice the signed area of abc, to 1e-12 of itself: in doubles, whose
/// error is up to about 3.3e-16 of |l| + |r|, or exactly where that could be
/// more (in slivers, where the fuzzer found weights off by 1e-9 of the field;
/// a bound of 1e-14 of |l| + |r| left weights off by 1e-4 in a triangle of
/// three nearly collinear input points, found by a user review).
double twiceArea(const Point& a, const Point& b, const Point& c)
{
  const double l = (b.x - a.x) * (c.y - a.y), r = (b.y - a.y) * (c.x - a.x);
  return std::abs(l - r) > 3.3e-4 * (std::abs(l) + std::abs(r)) ? l - r : orient2dAccurate(a, b, c);
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
    lambda[0] = std::max(0.0, twiceArea(p, b, c));
    lambda[1] = std::max(0.0, twiceArea(a, p, c));
    lambda[2] = std::max(0.0, twiceArea(a, b, p));
  }
  else if (count == 2)
  {
    const double s = projectionOnSegment(p, T.vertex(t, real[0]), T.vertex(t, real[1]));
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

namespace
{

/// The terms of the mesh's vertices: input vertices and points on segments
/// first, their own terms, kept as (input point or segment, position along
/// it) for the others, which lie within the Delaunay triangle of those
/// points that holds them.
class InputWeights
{
public:
  InputWeights(const Pslg& input, const Result& result);
  bool visitKnown(const TermsVisitor& visit);
  bool visitOthers(const TermsVisitor& visit) const;

private:
  Point scaled(const Point& p) const { return { p.x * scale, p.y * scale }; }
  int segmentOf(std::size_t v) const;
  int carried(int p) const;
  void knownTerms(std::size_t k, VertexTerms& t) const;

  const Pslg& input;
  const Result& result;
  Array<int> inputPoint; // per mesh vertex: the first input point there, or -1
  double scale = 1;
  Array<int> unknown;
  Array<Point> knownPoints;
  Array<int> knownSegment;  // per known point: its segment, or -1
  Array<double> knownAlong; // its position along that segment, or its input point
};

InputWeights::InputWeights(const Pslg& input, const Result& result)
  : input(input)
  , result(result)
  , inputPoint(result.mesh.vertices.size(), -1)
  // Coordinates scaled by a power of two (exactly) to magnitudes about 1,
  // so that no circumcircle test overflows, at 1e300 or 1e-300.
  , scale(unitScale(input.points, result.mesh.vertices))
{
  for (std::size_t i = 0; i < result.inputVertex.size(); ++i)
  {
    const int v = result.inputVertex[i];
    if (v >= 0 && inputPoint[v] < 0)
      inputPoint[v] = static_cast<int>(i);
  }
}

/// The segment the mesher found vertex v on, if it is a segment of length.
int InputWeights::segmentOf(std::size_t v) const
{
  const bool segmentsKnown = result.vertexSegment.size() == result.mesh.vertices.size();
  const int s = segmentsKnown ? result.vertexSegment[v] : -1;
  const int points = static_cast<int>(input.points.size());
  if (s < 0 || s >= static_cast<int>(input.segments.size()))
    return -1;
  const Segment& e = input.segments[s];
  return e[0] >= 0 && e[1] >= 0 && e[0] < points && e[1] < points &&
      input.points[e[0]] != input.points[e[1]]
    ? s
    : -1;
}

/// A segment's end merged into an earlier point (given twice, or within the
/// merge tolerance) has that point's tuple at its vertex: the points along
/// the segment take it too (a review: a field ran to the dropped copy's
/// value, then jumped at the vertex), and are placed along the segment
/// between the points kept (a merge within a tolerance moves its ends).
int InputWeights::carried(int p) const
{
  const int v =
    static_cast<std::size_t>(p) < result.inputVertex.size() ? result.inputVertex[p] : -1;
  return v >= 0 && inputPoint[v] >= 0 ? inputPoint[v] : p;
}

void InputWeights::knownTerms(std::size_t k, VertexTerms& t) const
{
  if (knownSegment[k] < 0)
    t.add(static_cast<int>(knownAlong[k]), 1.0);
  else
  {
    const Segment& e = input.segments[knownSegment[k]];
    t.add(carried(e[0]), 1 - knownAlong[k]);
    t.add(carried(e[1]), knownAlong[k]);
  }
}

/// Visits the input vertices and the points on segments; lists the others.
bool InputWeights::visitKnown(const TermsVisitor& visit)
{
  const Array<Point>& vertices = result.mesh.vertices;
  for (std::size_t v = 0; v < vertices.size(); ++v)
  {
    const Point p = scaled(vertices[v]);
    const int segment = inputPoint[v] >= 0 ? -1 : segmentOf(v);
    if (inputPoint[v] < 0 && segment < 0)
    {
      unknown.push_back(static_cast<int>(v));
      continue;
    }
    const Segment e = segment >= 0 ? input.segments[segment] : Segment{ 0, 0 };
    knownPoints.push_back(p);
    knownSegment.push_back(segment);
    knownAlong.push_back(segment < 0 ? inputPoint[v]
                                     : projectionOnSegment(p, scaled(input.points[carried(e[0])]),
                                         scaled(input.points[carried(e[1])])));
    VertexTerms terms;
    terms.vertex = v;
    terms.inputPoint = inputPoint[v];
    terms.segment = segment;
    knownTerms(knownPoints.size() - 1, terms);
    if (!visit(terms))
      return false;
  }
  return true;
}

/// Visits the others: within the Delaunay triangle of the known points that
/// holds them.
bool InputWeights::visitOthers(const TermsVisitor& visit) const
{
  if (unknown.empty())
    return true;
  Array<int> knownOf;
  Triangulation T;
  if (!knownPoints.empty())
  {
    Array<int> vertexOf;
    // Corners very far away: a triangle with a corner then lies beyond a
    // hull edge of the known points to within 2^-200 of their extent (the
    // circle through an edge and a corner is a half-plane but for that), far
    // below rounding, so the triangles without one cover their hull. (2^26
    // left pockets 0.0002 deep along a hull edge 127,000 long, which the
    // fuzzer found.) The coordinates are about 1, so the exact predicates'
    // products, up to 2^800, cannot overflow.
    T = delaunayTriangulation(knownPoints, vertexOf, 0x1p200);
    knownOf.assign(T.points.size(), -1);
    for (std::size_t k = 0; k < vertexOf.size(); ++k)
      if (vertexOf[k] >= 0)
        knownOf[vertexOf[k]] = static_cast<int>(k);
  }
  Array<Point> unknownPoints;
  unknownPoints.reserve(unknown.size());
  for (int v : unknown)
    unknownPoints.push_back(scaled(result.mesh.vertices[v]));
  int start = 0;
  while (start < T.slots() && !T.alive(start))
    ++start;
  const auto terms = [this](std::size_t k, VertexTerms& t) { knownTerms(k, t); };
  for (int k : hilbertOrder(unknownPoints))
  {
    VertexTerms t;
    t.vertex = static_cast<std::size_t>(unknown[k]);
    if (knownPoints.size() == 1) // no extent to pad: that point's value everywhere
      knownTerms(0, t);
    else if (start < T.slots())
    {
      start = triangleHolding(T, unknownPoints[k], start);
      termsIn(T, start, unknownPoints[k], knownOf, terms, t);
    }
    if (!visit(t))
      return false;
  }
  return true;
}

} // namespace

bool visitInputWeights(const Pslg& input, const Result& result, const TermsVisitor& visit)
{
  const RoundToNearest rounding;
  const pages::Reuse reuse; // the scratch arrays in huge pages, freed ones used again
  InputWeights weights(input, result);
  return weights.visitKnown(visit) && weights.visitOthers(visit);
}

} // namespace osm
