// Benchmark driver: the core's plain Delaunay triangulation of the input points
// (osm::delaunayTriangulation: Hilbert order, walk, Bowyer-Watson), segments
// ignored. A reference for the triangulation layer beside CGAL's, not a mesher:
// its output includes the four corners of the padded box it starts from, so
// conformity is not checked (every input segment would be reported missing).
#include "BenchCommon.h"
#include "Delaunay.h"

int main(int argc, char** argv)
{
  return osmbench::driverMain(argc, argv, "osm-delaunay",
    [](const osm::Pslg& input, osmbench::RunOutput& out, bool wantMesh) {
      osm::Array<int> vertexOf;
      out.memory.before();
      osmbench::Stopwatch clock;
      osm::Triangulation t = osm::delaunayTriangulation(input.points, vertexOf);
      out.seconds = clock.seconds();
      out.cpuSeconds = clock.cpuSeconds();
      out.systemSeconds = clock.systemSeconds();
      out.memory.after();
      // Triangles touching the four box corners (vertices 0..3) are not part of
      // the triangulation of the points.
      osm::Array<osm::Triangle> tris;
      for (int s = 0; s < t.slots(); ++s)
      {
        if (!t.alive(s))
          continue;
        const int a = t.tri[s].v[0], b = t.tri[s].v[1], c = t.tri[s].v[2];
        if (a < 4 || b < 4 || c < 4)
          continue;
        tris.push_back({ a, b, c });
      }
      out.vertices = input.points.size();
      out.triangles = tris.size();
      if (wantMesh)
      {
        out.mesh.vertices = t.points;
        out.mesh.triangles = std::move(tris);
        // Only the points are triangulated: no segment is expected.
        out.inDomain.assign(input.points.size(), 0);
      }
    });
}
