// Benchmark driver: the VTK filter vtkOverlayStitchMesher around the same core,
// timed around Update(): converting the vtkPolyData input, the core, and building
// the outputs (mesh with its point and cell arrays, field data). By default the
// Edges and Overlay outputs are off, so that it produces what bench_osm does;
// `--all-outputs` keeps the filter's defaults (both on). The core's own time in
// the same run (field data SecondsTotal) is reported as core_seconds, so the
// filter's overhead is measured within one process. `--point-data` gives the
// input points a scalar (their x), which the filter then interpolates onto the
// mesh (InterpolatePointData): what that costs. `--no-cell-data` turns
// PassCellData off (it fills the Edges output's InputCellId): with
// `--all-outputs`, what that costs.
#include "VtkCommon.h"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkOverlayStitchMesher.h>
#include <vtkPointData.h>

int main(int argc, char** argv)
{
  return osmbench::driverMain(
    argc, argv, "vtk-osm", [](const osm::Pslg& input, osmbench::RunOutput& out, bool wantMesh) {
      auto lines = osmbench::toPolyData(input, true);
      const bool pointData = out.has("--point-data");
      if (pointData)
      {
        vtkNew<vtkDoubleArray> x;
        x->SetName("X");
        x->SetNumberOfTuples(lines->GetNumberOfPoints());
        for (vtkIdType i = 0; i < lines->GetNumberOfPoints(); ++i)
          x->SetValue(i, lines->GetPoint(i)[0]);
        lines->GetPointData()->SetScalars(x);
      }
      vtkNew<vtkOverlayStitchMesher> mesher;
      mesher->SetInputData(lines);
      for (const osm::Point& h : input.holes)
        mesher->AddHolePoint(h.x, h.y);
      const bool all = out.has("--all-outputs");
      mesher->SetGenerateEdges(all);
      mesher->SetGenerateOverlay(all);
      mesher->SetPassCellData(!out.has("--no-cell-data"));
      out.memory.before();
      osmbench::Stopwatch clock;
      mesher->Update();
      out.seconds = clock.seconds();
      out.cpuSeconds = clock.cpuSeconds();
      out.systemSeconds = clock.systemSeconds();
      out.memory.after();
      vtkPolyData* result = mesher->GetOutput();
      out.triangles = osmbench::countTriangles(result);
      out.vertices = static_cast<std::size_t>(result->GetNumberOfPoints());
      vtkDataArray* total = result->GetFieldData()->GetArray("SecondsTotal");
      if (!total || out.triangles == 0)
      {
        out.ok = false;
        out.error = "the filter produced no mesh";
        return;
      }
      out.extra.add("core_seconds", total->GetTuple1(0))
        .add("all_outputs", all)
        .add("point_data", pointData);
      if (wantMesh)
      {
        out.mesh = osmbench::fromPolyData(result);
        // The filter does not say which input points its domain left out: take
        // those found in the mesh as the domain's, and check the segments between them.
        std::unordered_map<osm::Point, int, osmbench::PointHash> at;
        for (std::size_t v = 0; v < out.mesh.vertices.size(); ++v)
          at.emplace(out.mesh.vertices[v], static_cast<int>(v));
        out.inDomain.resize(input.points.size());
        for (std::size_t i = 0; i < input.points.size(); ++i)
          out.inDomain[i] = at.count(input.points[i]) ? 1 : 0;
      }
    });
}
