// Benchmark driver: the OSM core, osm::mesh() with default options, except that
// the phase-1 overlay and the classified edges are not kept (the mesh only, as
// the other tools return). Also reports the per-phase seconds of Result::stats.
// --max-edge H: no edge longer than H (Options::maxEdgeLength).
#include "BenchCommon.h"
#include "Mesher.h"

int main(int argc, char** argv)
{
  return osmbench::driverMain(
    argc, argv, "osm", [](const osm::Pslg& input, osmbench::RunOutput& out, bool wantMesh) {
      osm::Options options;
      options.keepOverlay = false;
      options.keepEdges = false;
      options.maxEdgeLength = out.number("--max-edge", 0.0);
      out.memory.before();
      osmbench::Stopwatch clock;
      osm::Result result = osm::mesh(input, options);
      out.seconds = clock.seconds();
      out.cpuSeconds = clock.cpuSeconds();
      out.systemSeconds = clock.systemSeconds();
      out.memory.after();
      out.ok = result.ok;
      out.error = result.error;
      out.vertices = result.mesh.vertices.size();
      out.triangles = result.mesh.triangles.size();
      const osm::Statistics& st = result.stats;
      out.extra.add("phase_clean", st.secondsClean)
        .add("phase_overlay", st.secondsOverlay)
        .add("phase_stitch", st.secondsStitch)
        .add("phase_complete", st.secondsComplete)
        .add("phase_domain", st.secondsDomain)
        .add("phase_total", st.secondsTotal)
        .add("overlay_triangles", st.overlayTriangles)
        .add("steiner_overlay", st.overlaySteinerPoints)
        .add("stitch_vertices", st.stitchVertices)
        .add("largest_face", st.largestFace);
      if (wantMesh && result.ok)
      {
        out.inDomain.resize(input.points.size());
        for (std::size_t i = 0; i < input.points.size(); ++i)
          out.inDomain[i] = result.inputVertex[i] >= 0;
        out.mesh.vertices = std::move(result.mesh.vertices);
        out.mesh.triangles = std::move(result.mesh.triangles);
      }
    });
}
