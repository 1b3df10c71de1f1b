// Benchmark driver: VTK's vtkDelaunay2D (ParaView's "Delaunay 2D") with the
// input segments as its constraint source: SetSourceData() with the line cells,
// which makes it recover them as edges. Default settings (Tolerance 1e-5 of the
// bounding box, Alpha 0, Offset 1); `--tolerance T` overrides the tolerance.
// Its output covers the convex hull of the points.
#include "VtkCommon.h"

#include <vtkDelaunay2D.h>

#include <cstdlib>

int main(int argc, char** argv)
{
  return osmbench::driverMain(argc, argv, "vtk-delaunay2d",
    [](const osm::Pslg& input, osmbench::RunOutput& out, bool wantMesh) {
      auto points = osmbench::toPolyData(input, false);
      auto lines = osmbench::toPolyData(input, true);
      vtkNew<vtkDelaunay2D> delaunay;
      delaunay->SetInputData(points);
      if (!input.segments.empty())
        delaunay->SetSourceData(lines);
      for (std::size_t i = 0; i + 1 < out.args.size(); ++i)
        if (out.args[i] == "--tolerance")
        {
          delaunay->SetTolerance(std::atof(out.args[i + 1].c_str()));
          out.extra.add("tolerance", delaunay->GetTolerance());
        }
      out.memory.before();
      osmbench::Stopwatch clock;
      delaunay->Update();
      out.seconds = clock.seconds();
      out.cpuSeconds = clock.cpuSeconds();
      out.systemSeconds = clock.systemSeconds();
      out.memory.after();
      vtkPolyData* result = delaunay->GetOutput();
      out.triangles = osmbench::countTriangles(result);
      // The output keeps every input point; those merged within the tolerance are
      // used by no triangle. Count the vertices that are used.
      out.mesh = osmbench::fromPolyData(result);
      std::vector<char> used(out.mesh.vertices.size(), 0);
      for (const osm::Triangle& t : out.mesh.triangles)
        used[t[0]] = used[t[1]] = used[t[2]] = 1;
      for (char u : used)
        out.vertices += u ? 1 : 0;
      (void)wantMesh;
    });
}
