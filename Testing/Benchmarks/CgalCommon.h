// CGAL helpers shared by the two CGAL drivers (benchmark-only: CGAL is GPL and
// is never linked into the plugin or the module).
#ifndef osm_bench_CgalCommon_h
#define osm_bench_CgalCommon_h

#include "BenchCommon.h"

#include <unordered_map>
#include <utility>
#include <vector>

namespace osmbench
{

/// The input in the form CGAL's bulk insertion takes: points and index pairs.
template <typename Point2>
struct CgalInput
{
  std::vector<Point2> points;
  std::vector<std::pair<std::size_t, std::size_t>> segments;
  explicit CgalInput(const osm::Pslg& p)
  {
    points.reserve(p.points.size());
    for (const osm::Point& q : p.points)
      points.emplace_back(q.x, q.y);
    segments.reserve(p.segments.size());
    for (const osm::Segment& s : p.segments)
      segments.emplace_back(static_cast<std::size_t>(s[0]), static_cast<std::size_t>(s[1]));
  }
};

/// Bulk insertion: points in spatial-sort order (Hilbert), then the constraints.
/// (CGAL's insert_constraints() inserts nothing when there is no constraint.)
template <typename Cdt, typename Point2>
void insertAll(Cdt& cdt, const CgalInput<Point2>& in)
{
  if (in.segments.empty())
    cdt.insert(in.points.begin(), in.points.end());
  else
    cdt.insert_constraints(
      in.points.begin(), in.points.end(), in.segments.begin(), in.segments.end());
}

/// The finite faces accepted by keep(face) as a MeshOut (indices of the used vertices).
template <typename Cdt, typename Keep>
MeshOut extract(const Cdt& cdt, Keep keep)
{
  MeshOut m;
  std::unordered_map<const void*, int> index;
  index.reserve(cdt.number_of_vertices() * 2);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    if (!keep(f))
      continue;
    osm::Triangle t;
    for (int i = 0; i < 3; ++i)
    {
      const auto v = f->vertex(i);
      const auto it = index.find(&*v);
      if (it != index.end())
        t[i] = it->second;
      else
      {
        t[i] = static_cast<int>(m.vertices.size());
        index.emplace(&*v, t[i]);
        m.vertices.push_back({ v->point().x(), v->point().y() });
      }
    }
    m.triangles.push_back(t);
  }
  return m;
}

} // namespace osmbench

#endif
