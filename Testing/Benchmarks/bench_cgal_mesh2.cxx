// Benchmark driver: CGAL Mesh_2, Delaunay refinement with the default criteria
// (shape bound 0.125, i.e. a minimum angle of about 20.7 degrees; no size bound
// unless --max-edge H gives one, on the longest edge of each triangle),
// timed from the input: building the constrained Delaunay triangulation (as
// bench_cgal_cdt), choosing the domain, and refining.
//
// The domain follows OSM's default (Auto), so that both mesh the same region:
// if the segments enclose a region, the faces reachable from the outside without
// crossing a segment are left out (CGAL's own default without seeds, like
// Triangle's -p); otherwise the convex hull is meshed, its edges being added as
// constraints (which is also what OSM does). In both cases hole seeds remove the
// region around them.
#include "CgalCommon.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <utility>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;

namespace
{

/// Sets in_domain = value on the faces reachable from start without crossing a
/// constrained edge (start included); returns how many finite faces it reached.
std::size_t flood(const Cdt& cdt, Cdt::Face_handle start, bool value)
{
  std::size_t finite = 0;
  std::vector<Cdt::Face_handle> stack{ start };
  start->set_in_domain(value);
  while (!stack.empty())
  {
    const Cdt::Face_handle f = stack.back();
    stack.pop_back();
    if (!cdt.is_infinite(f))
      ++finite;
    for (int i = 0; i < 3; ++i)
    {
      const Cdt::Face_handle g = f->neighbor(i);
      if (g->is_in_domain() != value && !cdt.is_constrained(Cdt::Edge(f, i)))
      {
        g->set_in_domain(value);
        stack.push_back(g);
      }
    }
  }
  return finite;
}

/// Marks the domain as described above; returns true for "enclosed".
bool markDomain(Cdt& cdt, const osm::Array<osm::Point>& holes)
{
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
    f->set_in_domain(true);
  const std::size_t outside = flood(cdt, cdt.infinite_face(), false);
  const bool enclosed = outside < cdt.number_of_faces();
  if (!enclosed)
  {
    // Nothing enclosed: mesh the convex hull, its edges becoming constraints.
    std::vector<std::pair<Cdt::Vertex_handle, Cdt::Vertex_handle>> hull;
    auto inf = cdt.incident_faces(cdt.infinite_vertex()), done = inf;
    do
    {
      const int i = inf->index(cdt.infinite_vertex());
      hull.emplace_back(inf->vertex(Cdt::ccw(i)), inf->vertex(Cdt::cw(i)));
    } while (++inf != done);
    for (const auto& e : hull)
      cdt.insert_constraint(e.first, e.second);
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
      f->set_in_domain(!cdt.is_infinite(f));
  }
  for (const osm::Point& h : holes)
  {
    const Cdt::Face_handle f = cdt.locate(K::Point_2(h.x, h.y));
    if (f != Cdt::Face_handle() && !cdt.is_infinite(f) && f->is_in_domain())
      flood(cdt, f, false);
  }
  return enclosed;
}

} // namespace

int main(int argc, char** argv)
{
  return osmbench::driverMain(
    argc, argv, "cgal-mesh2", [](const osm::Pslg& input, osmbench::RunOutput& out, bool wantMesh) {
      const osmbench::CgalInput<K::Point_2> in(input);
      Cdt cdt;
      out.memory.before();
      osmbench::Stopwatch clock;
      osmbench::insertAll(cdt, in);
      const double cdtSeconds = clock.seconds();
      const bool enclosed = markDomain(cdt, input.holes);
      // --max-edge H: CGAL's size bound, on the longest edge of each triangle.
      const Criteria criteria(0.125, out.number("--max-edge", 0.0));
      CGAL::refine_Delaunay_mesh_2(cdt, criteria, /*domain_specified=*/true);
      out.seconds = clock.seconds();
      out.cpuSeconds = clock.cpuSeconds();
      out.systemSeconds = clock.systemSeconds();
      out.memory.after();
      out.extra.add("cdt_seconds", cdtSeconds)
        .add("domain", enclosed ? "enclosed" : "hull")
        .add("all_faces", static_cast<std::size_t>(cdt.number_of_faces()));
      // The faces in the domain (and the vertices they use) are the output.
      out.mesh =
        osmbench::extract(cdt, [](Cdt::Finite_faces_iterator f) { return f->is_in_domain(); });
      out.vertices = out.mesh.vertices.size();
      out.triangles = out.mesh.triangles.size();
      if (wantMesh && enclosed)
      {
        // Input points on no face of the domain were left out on purpose.
        std::unordered_map<osm::Point, int, osmbench::PointHash> at;
        for (std::size_t v = 0; v < out.mesh.vertices.size(); ++v)
          at.emplace(out.mesh.vertices[v], static_cast<int>(v));
        out.inDomain.resize(input.points.size());
        for (std::size_t i = 0; i < input.points.size(); ++i)
          out.inDomain[i] = at.count(input.points[i]) ? 1 : 0;
      }
    });
}
