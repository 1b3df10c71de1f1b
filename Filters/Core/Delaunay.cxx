#include "Delaunay.h"

#include "SpatialSort.h"

#include <algorithm>
#include <cmath>

namespace osm
{

Triangulation delaunayTriangulation(const std::vector<Point>& points, std::vector<int>& vertexOf)
{
  Triangulation T;
  vertexOf.assign(points.size(), -1);
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  if (!points.empty())
  {
    xmin = xmax = points[0].x;
    ymin = ymax = points[0].y;
  }
  for (const Point& p : points)
  {
    xmin = std::min(xmin, p.x);
    xmax = std::max(xmax, p.x);
    ymin = std::min(ymin, p.y);
    ymax = std::max(ymax, p.y);
  }
  const double h = 2.0 * std::max({ xmax - xmin, ymax - ymin, 1e-300 });
  const double cx = 0.5 * (xmin + xmax), cy = 0.5 * (ymin + ymax);
  const int c0 = T.addPoint({ cx - h, cy - h }), c1 = T.addPoint({ cx + h, cy - h });
  const int c2 = T.addPoint({ cx + h, cy + h }), c3 = T.addPoint({ cx - h, cy + h });
  const int t0 = T.newTriangle(c0, c1, c2), t1 = T.newTriangle(c0, c2, c3);
  T.link(t0, t1);
  std::vector<int> cavity, created;
  int last = t0;
  for (int i : hilbertOrder(points))
  {
    const int start = T.locate(points[i], T.alive(last) ? last : T.vtri[c0]);
    if (start < 0 || !T.cavityOf(points[i], start, cavity))
      continue; // outside (impossible) or a duplicate: left out
    const int v = T.addPoint(points[i]);
    if (!T.insertIntoCavity(v, cavity, created))
    {
      T.points.pop_back();
      T.vtri.pop_back();
      continue;
    }
    vertexOf[i] = v;
    last = created.front();
  }
  return T;
}

} // namespace osm
