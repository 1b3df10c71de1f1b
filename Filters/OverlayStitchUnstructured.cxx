// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
#include "OverlayStitchUnstructured.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include "OverlayStitchArrays.h"
#include "OverlayStitchGather.h"

#include <array>
#include <utility>
#include <vector>

namespace
{
/// The polydata kind a cell type is read as: 0 verts, 1 lines, 2 polys,
/// 3 strips (vtkPolyData's cell order), or -1 for none.
int KindOf(int type)
{
  switch (type)
  {
    case VTK_VERTEX:
    case VTK_POLY_VERTEX:
      return 0;
    case VTK_LINE:
    case VTK_POLY_LINE:
      return 1;
    case VTK_TRIANGLE:
    case VTK_QUAD:
    case VTK_PIXEL:
    case VTK_POLYGON:
      return 2;
    case VTK_TRIANGLE_STRIP:
      return 3;
    default:
      return -1;
  }
}

} // namespace

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> OverlayStitchPolyDataOf(vtkUnstructuredGrid* grid, bool sourceIds,
  const std::string& where, std::vector<OverlayStitchNote>& notes, vtkIdType& ignoredCells)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(grid->GetPoints());
  out->GetPointData()->ShallowCopy(grid->GetPointData());
  out->GetFieldData()->ShallowCopy(grid->GetFieldData());

  std::array<vtkNew<vtkCellArray>, 4> cells;
  std::array<std::vector<vtkIdType>, 4> order; // grid's cell ids, per kind
  vtkIdType left = 0, first = -1;
  int firstType = VTK_EMPTY_CELL;
  vtkNew<vtkIdList> ids;
  // Ghost cells are copies of cells another piece holds, which says so.
  vtkDataArray* ghosts = vtkUnsignedCharArray::SafeDownCast(
    grid->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    const int type = grid->GetCellType(c);
    const int kind = KindOf(type);
    if (kind < 0 && OverlayStitchIsGhostCell(ghosts, c))
    {
      continue;
    }
    if (kind < 0)
    {
      first = left++ == 0 ? c : first;
      firstType = first == c ? type : firstType;
      continue;
    }
    grid->GetCellPoints(c, ids);
    if (type == VTK_PIXEL && ids->GetNumberOfIds() == 4)
    {
      std::swap(*ids->GetPointer(2), *ids->GetPointer(3)); // pixels order their corners by axis
    }
    cells[kind]->InsertNextCell(ids);
    order[kind].push_back(c);
  }
  out->SetVerts(cells[0]);
  out->SetLines(cells[1]);
  out->SetPolys(cells[2]);
  out->SetStrips(cells[3]);

  vtkNew<vtkIdList> from;
  for (const std::vector<vtkIdType>& kind : order)
  {
    for (const vtkIdType c : kind)
    {
      from->InsertNextId(c);
    }
  }
  // Arrays shorter than the cells cannot be reordered: left out, as the
  // filter leaves out polydata's.
  vtkNew<vtkCellData> whole;
  whole->ShallowCopy(grid->GetCellData());
  for (int a = whole->GetNumberOfArrays() - 1; a >= 0; --a)
  {
    vtkAbstractArray* array = whole->GetAbstractArray(a);
    if (array->GetNumberOfTuples() < grid->GetNumberOfCells())
    {
      const char* name = array->GetName() ? array->GetName() : "(unnamed)";
      notes.push_back({ { "cell", name },
        OverlayStitchShortArrayNote(
          "cell", name, array->GetNumberOfTuples(), grid->GetNumberOfCells(), where) });
      whole->RemoveArray(a);
    }
  }
  vtkCellData* to = out->GetCellData();
  to->CopyGlobalIdsOn();
  to->CopyAllocate(whole, from->GetNumberOfIds());
  to->CopyData(whole, from, vtkIdType(0));
  if (sourceIds)
  {
    vtkSmartPointer<vtkIdTypeArray> cellIds =
      OverlayStitchIdArray(OverlayStitchSourceCellIdName, from->GetNumberOfIds(), 0);
    std::copy(from->begin(), from->end(), cellIds->GetPointer(0));
    to->AddArray(cellIds);
    out->GetPointData()->AddArray(
      OverlayStitchIdArray(OverlayStitchSourcePointIdName, grid->GetNumberOfPoints(), -1));
  }
  ignoredCells = left;
  if (left > 0)
  {
    notes.push_back({ {},
      "Ignored " + std::to_string(left) + " cell(s) of " +
        (where.empty() ? "the unstructured grid" : where + " (an unstructured grid)") +
        ", the first cell " + std::to_string(first) + " (" +
        vtkCellTypes::GetClassNameFromTypeId(firstType) +
        "): segments come from line, polyline and polygon cells (triangles, quads, pixels), "
        "points from every cell and point." });
  }
  return out;
}
