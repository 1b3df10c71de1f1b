#include "Delaunay.h"

#include "Predicates.h"
#include "SpatialSort.h"

#include <algorithm>
#include <cmath>

namespace osm
{

Triangulation delaunayTriangulation(
  const Array<Point>& points, Array<int>& vertexOf, double padding)
{
  const RoundToNearest rounding;
  Triangulation T;
  T.reserve(points.size() + 4, 2 * points.size() + 2); // a triangulation's size: no copies
  vertexOf.assign(points.size(), -1);
  const Bounds b = boundsOf(points);
  const double h = padding * std::max({ b.width(), b.height(), 1e-300 });
  const double cx = 0.5 * (b.lo.x + b.hi.x), cy = 0.5 * (b.lo.y + b.hi.y);
  const int c0 = T.addPoint({ cx - h, cy - h }), c1 = T.addPoint({ cx + h, cy - h });
  const int c2 = T.addPoint({ cx + h, cy + h }), c3 = T.addPoint({ cx - h, cy + h });
  const int t0 = T.newTriangle(c0, c1, c2), t1 = T.newTriangle(c0, c2, c3);
  T.link(t0, t1);
  Triangulation::Cavity cavity;
  Array<int> created;
  int last = t0;
  for (int i : hilbertOrder(points))
  {
    // last is alive: a failed insertion changes nothing.
    const int start = T.locate(points[i], last);
    if (start < 0 || !T.cavityOf(points[i], start, cavity))
      continue; // outside (impossible) or a duplicate: left out
    const int v = T.addPoint(points[i]);
    if (!T.insertIntoCavity(v, cavity, created))
    {
      T.points.pop_back();
      continue;
    }
    vertexOf[i] = v;
    last = created.front();
  }
  return T;
}

} // namespace osm
