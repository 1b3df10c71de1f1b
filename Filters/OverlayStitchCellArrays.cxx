// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
#include "OverlayStitchCellArrays.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include "OverlayStitchGather.h"

namespace
{

/// What is wrong with cells, or "" if nothing: offsets that do not start at
/// 0, that decrease, or that end anywhere but at the connectivity's end.
std::string Problem(vtkCellArray* cells)
{
  if (!cells || cells->IsValid())
  {
    return "";
  }
  vtkDataArray* offsets = cells->GetOffsetsArray();
  vtkDataArray* connectivity = cells->GetConnectivityArray();
  if (!offsets || !connectivity || offsets->GetNumberOfComponents() != 1 ||
    connectivity->GetNumberOfComponents() != 1)
  {
    return "their offsets or connectivity are missing or have several components";
  }
  const vtkIdType n = offsets->GetNumberOfTuples();
  if (n == 0)
  {
    return "their offsets are empty (they start with a 0)";
  }
  if (offsets->GetComponent(0, 0) != 0)
  {
    return "their offsets do not start at 0";
  }
  for (vtkIdType c = 1; c < n; ++c)
  {
    if (offsets->GetComponent(c, 0) < offsets->GetComponent(c - 1, 0))
    {
      return "their offsets decrease at cell " + std::to_string(c - 1);
    }
  }
  const vtkIdType size = connectivity->GetNumberOfTuples();
  if (static_cast<vtkIdType>(offsets->GetComponent(n - 1, 0)) != size)
  {
    return "their offsets end at " +
      std::to_string(static_cast<vtkIdType>(offsets->GetComponent(n - 1, 0))) +
      ", but their connectivity has " + std::to_string(size) + " value(s)";
  }
  return "";
}

/// Marks data as the stand-in of a piece with a malformed cell array (its
/// block id, -1, is filled in when blocks are combined).
void MarkMalformed(vtkDataObject* data)
{
  vtkNew<vtkIdTypeArray> mark;
  mark->SetName(OverlayStitchMalformedName);
  mark->InsertNextValue(-1);
  data->GetFieldData()->AddArray(mark);
}

/// data with its malformed cell arrays replaced (a shallow copy), or null if
/// none is; what names data in malformed.
vtkSmartPointer<vtkDataObject> Repaired(
  vtkDataObject* data, const std::string& what, std::string& malformed)
{
  auto note = [&](const std::string& array, const std::string& problem) {
    if (malformed.empty())
    {
      malformed = "the " + array + " of " + what + ": " + problem;
    }
  };
  if (auto* poly = vtkPolyData::SafeDownCast(data))
  {
    vtkCellArray* kinds[4] = { poly->GetVerts(), poly->GetLines(), poly->GetPolys(),
      poly->GetStrips() };
    const char* names[4] = { "vertex cells", "line cells", "polygon cells", "strip cells" };
    bool any = false;
    for (int k = 0; k < 4; ++k)
    {
      const std::string problem = Problem(kinds[k]);
      if (!problem.empty())
      {
        note(names[k], problem);
        any = true;
      }
    }
    if (!any)
    {
      return nullptr;
    }
    auto copy = vtkSmartPointer<vtkPolyData>::New();
    copy->ShallowCopy(poly);
    // Every cell array goes: a malformed one shifts the ids of the cells after it.
    copy->SetVerts(nullptr);
    copy->SetLines(nullptr);
    copy->SetPolys(nullptr);
    copy->SetStrips(nullptr);
    copy->GetCellData()->Initialize();
    MarkMalformed(copy);
    return copy;
  }
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(data))
  {
    vtkCellArray* cells = grid->GetCells();
    std::string problem = Problem(cells);
    vtkUnsignedCharArray* types = grid->GetCellTypesArray();
    if (problem.empty() && cells &&
      (types ? types->GetNumberOfTuples() : 0) != cells->GetNumberOfCells())
    {
      problem = "it has " + std::to_string(cells->GetNumberOfCells()) + " cell(s) but " +
        std::to_string(types ? types->GetNumberOfTuples() : 0) + " cell type(s)";
    }
    if (problem.empty())
    {
      return nullptr;
    }
    note("cells", problem);
    auto copy = vtkSmartPointer<vtkUnstructuredGrid>::New();
    copy->SetPoints(grid->GetPoints());
    copy->GetPointData()->ShallowCopy(grid->GetPointData());
    copy->GetFieldData()->ShallowCopy(grid->GetFieldData());
    vtkNew<vtkUnsignedCharArray> noTypes;
    vtkNew<vtkCellArray> noCells;
    copy->SetCells(noTypes, noCells);
    MarkMalformed(copy);
    return copy;
  }
  return nullptr;
}

} // namespace

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> OverlayStitchRefusedPiece()
{
  auto piece = vtkSmartPointer<vtkPolyData>::New();
  piece->SetPoints(vtkNew<vtkPoints>());
  MarkMalformed(piece);
  return piece;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkDataObject> OverlayStitchWithBlocksReplaced(vtkDataObject* input,
  const std::function<vtkSmartPointer<vtkDataObject>(vtkDataObject*, int)>& replace)
{
  auto* composite = vtkCompositeDataSet::SafeDownCast(input);
  if (!composite)
  {
    vtkSmartPointer<vtkDataObject> replaced = replace(input, -1);
    return replaced ? replaced : vtkSmartPointer<vtkDataObject>(input);
  }
  vtkSmartPointer<vtkCompositeDataSet> copy;
  auto it = vtk::TakeSmartPointer(composite->NewIterator());
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    vtkSmartPointer<vtkDataObject> replaced =
      replace(it->GetCurrentDataObject(), static_cast<int>(it->GetCurrentFlatIndex()));
    if (!replaced)
    {
      continue;
    }
    if (!copy)
    {
      copy = vtk::TakeSmartPointer(composite->NewInstance());
      copy->ShallowCopy(composite);
    }
    copy->SetDataSet(it, replaced);
  }
  return copy ? vtkSmartPointer<vtkDataObject>(copy) : vtkSmartPointer<vtkDataObject>(input);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkDataObject> OverlayStitchWithWellFormedCells(
  vtkDataObject* input, std::string& malformed)
{
  malformed.clear();
  // Blocks are named by their flat index, as the filter's other messages do.
  return OverlayStitchWithBlocksReplaced(input, [&malformed](vtkDataObject* data, int block) {
    return Repaired(data,
      block < 0 ? "the input" : "block " + std::to_string(block) + " of the input", malformed);
  });
}
