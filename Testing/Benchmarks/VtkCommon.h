// VTK helpers shared by the VTK drivers: the input as vtkPolyData, and the
// triangles of an output back in the common form.
#ifndef osm_bench_VtkCommon_h
#define osm_bench_VtkCommon_h

#include "BenchCommon.h"

#include <vtkCellArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace osmbench
{

/// The input points (double precision, z = 0) and, if withLines, its segments as line cells.
inline vtkSmartPointer<vtkPolyData> toPolyData(const osm::Pslg& p, bool withLines)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(p.points.size()));
  for (std::size_t i = 0; i < p.points.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), p.points[i].x, p.points[i].y, 0.0);
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  if (withLines)
  {
    vtkNew<vtkCellArray> lines;
    lines->AllocateExact(
      static_cast<vtkIdType>(p.segments.size()), 2 * static_cast<vtkIdType>(p.segments.size()));
    for (const osm::Segment& s : p.segments)
    {
      const vtkIdType ids[2] = { s[0], s[1] };
      lines->InsertNextCell(2, ids);
    }
    data->SetLines(lines);
  }
  return data;
}

/// Number of triangles among the polygons of a polydata.
inline std::size_t countTriangles(vtkPolyData* out)
{
  std::size_t n = 0;
  vtkCellArray* polys = out->GetPolys();
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(npts, pts);)
    n += npts == 3 ? 1 : 0;
  return n;
}

/// Every point and every triangle of a polydata.
inline MeshOut fromPolyData(vtkPolyData* out)
{
  MeshOut m;
  const vtkIdType n = out->GetNumberOfPoints();
  m.vertices.resize(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    m.vertices[static_cast<std::size_t>(i)] = { x[0], x[1] };
  }
  vtkCellArray* polys = out->GetPolys();
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(npts, pts);)
    if (npts == 3)
      m.triangles.push_back(
        { static_cast<int>(pts[0]), static_cast<int>(pts[1]), static_cast<int>(pts[2]) });
  return m;
}

} // namespace osmbench

#endif
