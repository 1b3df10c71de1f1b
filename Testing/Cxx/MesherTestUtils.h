// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// Helpers shared by the C++ tests of vtkOverlayStitchMesher: a failure
// counter, an observer that keeps every error and warning text, input
// builders and output checks.
#ifndef MesherTestUtils_h
#define MesherTestUtils_h

#include "vtkOverlayStitchMesher.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <array>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace osmtest
{

inline int& Failures()
{
  static int failures = 0;
  return failures;
}

inline bool Check(bool condition, const std::string& what)
{
  std::cout << (condition ? "ok      " : "FAILED  ") << what << "\n";
  if (!condition)
  {
    ++Failures();
  }
  return condition;
}

/// Keeps the text of every error and warning event of the object it observes.
class MessageObserver : public vtkCommand
{
public:
  static MessageObserver* New() { return new MessageObserver; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const std::string text = data ? static_cast<const char*>(data) : "";
    if (event == vtkCommand::ErrorEvent)
    {
      this->Errors.push_back(text);
    }
    else if (event == vtkCommand::WarningEvent)
    {
      this->Warnings.push_back(text);
    }
  }
  void Clear()
  {
    this->Errors.clear();
    this->Warnings.clear();
  }
  /// The number of messages of the list that contain every one of the texts.
  static int Count(const std::vector<std::string>& messages, const std::vector<std::string>& texts)
  {
    int n = 0;
    for (const std::string& m : messages)
    {
      bool all = true;
      for (const std::string& t : texts)
      {
        all = all && m.find(t) != std::string::npos;
      }
      n += all ? 1 : 0;
    }
    return n;
  }
  bool HasError(const std::vector<std::string>& texts) const
  {
    return Count(this->Errors, texts) > 0;
  }
  bool HasWarning(const std::vector<std::string>& texts) const
  {
    return Count(this->Warnings, texts) > 0;
  }
  void Print(const std::string& label) const
  {
    for (const std::string& e : this->Errors)
    {
      std::cout << "  [" << label << "] error: " << e.substr(e.find("): ") + 3);
    }
    for (const std::string& w : this->Warnings)
    {
      std::cout << "  [" << label << "] warning: " << w.substr(w.find("): ") + 3);
    }
  }
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
};

/// Points (x, y, z) and line cells (lists of point ids) as vtkPolyData.
inline vtkSmartPointer<vtkPolyData> MakeLines(
  const std::vector<std::array<double, 3>>& xyz, const std::vector<std::vector<vtkIdType>>& lines)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : xyz)
  {
    points->InsertNextPoint(p[0], p[1], p[2]);
  }
  vtkNew<vtkCellArray> cells;
  for (const auto& line : lines)
  {
    cells->InsertNextCell(static_cast<vtkIdType>(line.size()), line.data());
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(cells);
  return data;
}

/// A field data value of the mesh output (the run statistics), or NaN.
inline double Statistic(vtkPolyData* mesh, const char* name)
{
  vtkDataArray* array = mesh->GetFieldData()->GetArray(name);
  return array && array->GetNumberOfTuples() == 1 ? array->GetTuple1(0) : std::nan("");
}

inline bool AllOutputsEmpty(vtkOverlayStitchMesher* mesher)
{
  for (int port = 0; port < 3; ++port)
  {
    auto* out = vtkPolyData::SafeDownCast(mesher->GetOutputDataObject(port));
    if (!out || out->GetNumberOfPoints() != 0 || out->GetNumberOfCells() != 0)
    {
      return false;
    }
  }
  return true;
}

/// Sum of the (3D) areas of the triangles of a polydata.
inline double TotalArea(vtkPolyData* mesh)
{
  double total = 0.0;
  vtkCellArray* polys = mesh->GetPolys();
  vtkNew<vtkIdList> ids;
  polys->InitTraversal();
  while (polys->GetNextCell(ids))
  {
    double a[3], b[3], c[3];
    mesh->GetPoint(ids->GetId(0), a);
    mesh->GetPoint(ids->GetId(1), b);
    mesh->GetPoint(ids->GetId(2), c);
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
      u[0] * v[1] - u[1] * v[0] };
    total += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }
  return total;
}

/// The largest value of the mesh's MaxAngle cell array (0 without triangles).
inline double LargestAngle(vtkPolyData* mesh)
{
  vtkDataArray* maxAngle = mesh->GetCellData()->GetArray("MaxAngle");
  if (!maxAngle || maxAngle->GetNumberOfTuples() == 0)
  {
    return 0.0;
  }
  double range[2];
  maxAngle->GetRange(range, 0);
  return range[1];
}

/// True if every coordinate of every point of the polydata is finite.
inline bool AllPointsFinite(vtkPolyData* data)
{
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
  {
    double p[3];
    data->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return false;
    }
  }
  return true;
}

} // namespace osmtest

#endif
