// Benchmark driver: CGAL's constrained Delaunay triangulation of the input alone
// (no refinement): Epick kernel, exact predicates, points bulk-inserted in
// spatial-sort order, then the segments as constraints. Its output is every
// finite face (the convex hull), about 2n triangles.
#include "CgalCommon.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Cdt =
  CGAL::Constrained_Delaunay_triangulation_2<K, CGAL::Default, CGAL::Exact_predicates_tag>;

int main(int argc, char** argv)
{
  return osmbench::driverMain(
    argc, argv, "cgal-cdt", [](const osm::Pslg& input, osmbench::RunOutput& out, bool wantMesh) {
      const osmbench::CgalInput<K::Point_2> in(input);
      Cdt cdt;
      out.memory.before();
      osmbench::Stopwatch clock;
      osmbench::insertAll(cdt, in);
      out.seconds = clock.seconds();
      out.cpuSeconds = clock.cpuSeconds();
      out.systemSeconds = clock.systemSeconds();
      out.memory.after();
      out.vertices = cdt.number_of_vertices();
      out.triangles = cdt.number_of_faces();
      if (wantMesh)
        out.mesh = osmbench::extract(cdt, [](Cdt::Finite_faces_iterator) { return true; });
    });
}
