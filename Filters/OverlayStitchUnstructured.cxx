// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
#include "OverlayStitchUnstructured.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCellTypes.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkGenericCell.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include "OverlayStitchArrays.h"
#include "OverlayStitchGather.h"

#include <algorithm>
#include <array>
#include <cmath>
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

/// The kind a higher-order cell is linearised as: 1 (a polyline through its
/// nodes along the curve) or 2 (a polygon through its boundary's nodes), or
/// -1. Bezier cells are not among them: their inner nodes are control points
/// off the curve.
int HigherOrderKindOf(int type)
{
  switch (type)
  {
    case VTK_QUADRATIC_EDGE:
    case VTK_CUBIC_LINE:
    case VTK_LAGRANGE_CURVE:
      return 1;
    case VTK_QUADRATIC_TRIANGLE:
    case VTK_BIQUADRATIC_TRIANGLE:
    case VTK_QUADRATIC_QUAD:
    case VTK_QUADRATIC_LINEAR_QUAD:
    case VTK_BIQUADRATIC_QUAD:
    case VTK_QUADRATIC_POLYGON:
    case VTK_LAGRANGE_TRIANGLE:
    case VTK_LAGRANGE_QUADRILATERAL:
      return 2;
    default:
      return -1;
  }
}

/// Whether n nodes make a cell of the higher-order type (VTK would read the
/// nodes of a cell of another count out of bounds). degrees are the cell's
/// orders (its HigherOrderDegrees tuple) if the grid gives them, else null.
bool HasNodesOfItsType(int type, vtkIdType n, const double* degrees)
{
  const auto isSquare = [](vtkIdType k) {
    const auto side = static_cast<vtkIdType>(std::lround(std::sqrt(static_cast<double>(k))));
    return side >= 2 && side * side == k;
  };
  const auto isTriangular = [](vtkIdType k) {
    const auto side = static_cast<vtkIdType>(std::lround((std::sqrt(8.0 * k + 1) - 1) / 2));
    return side >= 2 && side * (side + 1) / 2 == k;
  };
  switch (type)
  {
    case VTK_QUADRATIC_EDGE:
      return n == 3;
    case VTK_CUBIC_LINE:
      return n == 4;
    case VTK_QUADRATIC_TRIANGLE:
    case VTK_QUADRATIC_LINEAR_QUAD:
      return n == 6;
    case VTK_BIQUADRATIC_TRIANGLE:
      return n == 7;
    case VTK_QUADRATIC_QUAD:
      return n == 8;
    case VTK_BIQUADRATIC_QUAD:
      return n == 9;
    case VTK_QUADRATIC_POLYGON:
      return n >= 6 && n % 2 == 0;
    case VTK_LAGRANGE_CURVE:
      return n >= 2;
    case VTK_LAGRANGE_TRIANGLE:
      return isTriangular(n) || n == 7; // 7: order 2 and a middle node (Exodus's TRI7)
    case VTK_LAGRANGE_QUADRILATERAL:
      return degrees ? degrees[0] >= 1 && degrees[1] >= 1 &&
          (degrees[0] + 1) * (degrees[1] + 1) == static_cast<double>(n)
                     : isSquare(n);
    default:
      return false;
  }
}

/// VTK's class name of a cell type (vtkCellTypes of VTK 9.2 swaps the
/// Lagrange triangle's and quadrilateral's, found by a review).
std::string TypeName(int type)
{
  switch (type)
  {
    case VTK_LAGRANGE_TRIANGLE:
      return "vtkLagrangeTriangle";
    case VTK_LAGRANGE_QUADRILATERAL:
      return "vtkLagrangeQuadrilateral";
    default:
    {
      // An unknown type (a file's garbage) is named by its number (a review).
      const std::string name = vtkCellTypes::GetClassNameFromTypeId(type);
      return name == "UnknownClass" ? "unknown cell type " + std::to_string(type) : name;
    }
  }
}

/// The nodes of a curve cell (a line, quadratic edge, cubic line or Lagrange
/// curve) in order along it: VTK lists its two ends first, then the inner
/// nodes from the first end to the second.
void AppendCurveNodes(vtkIdList* curve, std::vector<vtkIdType>& nodes)
{
  const vtkIdType n = curve->GetNumberOfIds();
  if (n < 2)
  {
    return;
  }
  nodes.push_back(curve->GetId(0));
  for (vtkIdType i = 2; i < n; ++i)
  {
    nodes.push_back(curve->GetId(i));
  }
  nodes.push_back(curve->GetId(1));
}

/// The boundary loop of a higher-order face through the nodes of its edges,
/// each edge turned to start where the one before ended (VTK runs some edges
/// of Lagrange quadrilaterals against the loop); empty if they do not join.
std::vector<vtkIdType> BoundaryLoopOf(vtkGenericCell* face)
{
  std::vector<vtkIdType> loop, edge;
  for (int e = 0; e < face->GetNumberOfEdges(); ++e)
  {
    edge.clear();
    AppendCurveNodes(face->GetEdge(e)->GetPointIds(), edge);
    if (edge.empty())
    {
      return {};
    }
    if (!loop.empty() && edge.front() != loop.back())
    {
      std::reverse(edge.begin(), edge.end());
    }
    if (!loop.empty() && edge.front() != loop.back())
    {
      return {};
    }
    loop.insert(loop.end(), edge.begin() + (loop.empty() ? 0 : 1), edge.end());
  }
  if (loop.size() < 4 || loop.front() != loop.back())
  {
    return {};
  }
  loop.pop_back();
  return loop;
}

/// The cell's nodes as the cell of its kind reads them (a higher-order
/// cell's linearised); false if it is not read.
bool ReadCell(vtkUnstructuredGrid* grid, vtkIdType c, int type, int& kind, vtkIdList* ids,
  vtkGenericCell* cell, std::vector<vtkIdType>& nodes)
{
  kind = KindOf(type);
  if (kind >= 0)
  {
    grid->GetCellPoints(c, ids);
    if (type == VTK_PIXEL && ids->GetNumberOfIds() == 4)
    {
      std::swap(*ids->GetPointer(2), *ids->GetPointer(3)); // pixels order their corners by axis
    }
    return true;
  }
  kind = HigherOrderKindOf(type);
  vtkDataArray* degrees = grid->GetCellData()->GetHigherOrderDegrees();
  double order[3] = { 0, 0, 0 };
  if (degrees && degrees->GetNumberOfComponents() == 3 && c < degrees->GetNumberOfTuples())
  {
    degrees->GetTuple(c, order);
  }
  if (kind < 0 || !HasNodesOfItsType(type, grid->GetCellSize(c), degrees ? order : nullptr))
  {
    return false;
  }
  // GetCell copies every node's coordinates: a node naming a missing point
  // would be read out of bounds (a review: osm-mesh and ParaView crashed).
  // Such a cell is passed on as its ids, which the filter then refuses.
  grid->GetCellPoints(c, ids);
  const vtkIdType points = grid->GetNumberOfPoints();
  if (std::any_of(
        ids->begin(), ids->end(), [points](vtkIdType id) { return id < 0 || id >= points; }))
  {
    return true;
  }
  nodes.clear();
  if (type == VTK_LAGRANGE_TRIANGLE && ids->GetNumberOfIds() == 7)
  {
    // VTK 9.2 gives this cell's edges wrong nodes: its boundary is its
    // corners and the nodes between them, as a biquadratic triangle's.
    for (const int node : { 0, 3, 1, 4, 2, 5 })
    {
      nodes.push_back(ids->GetId(node));
    }
    ids->SetNumberOfIds(6);
    std::copy(nodes.begin(), nodes.end(), ids->begin());
    return true;
  }
  grid->GetCell(c, cell);
  if (kind == 1)
  {
    AppendCurveNodes(cell->GetPointIds(), nodes);
  }
  else
  {
    nodes = BoundaryLoopOf(cell);
  }
  ids->SetNumberOfIds(static_cast<vtkIdType>(nodes.size()));
  std::copy(nodes.begin(), nodes.end(), ids->begin());
  return !nodes.empty();
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
  vtkIdType left = 0, first = -1, firstNodes = 0;
  int firstType = VTK_EMPTY_CELL;
  vtkNew<vtkIdList> ids;
  vtkNew<vtkGenericCell> cell;
  std::vector<vtkIdType> nodes;
  // Ghost cells are copies of cells another piece holds, which says so.
  vtkDataArray* ghosts = vtkUnsignedCharArray::SafeDownCast(
    grid->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    const int type = grid->GetCellType(c);
    int kind = -1;
    if (!ReadCell(grid, c, type, kind, ids, cell, nodes))
    {
      if (!OverlayStitchIsGhostCell(ghosts, c))
      {
        first = left++ == 0 ? c : first;
        firstType = first == c ? type : firstType;
        firstNodes = first == c ? grid->GetCellSize(c) : firstNodes;
      }
      continue;
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
        ", the first cell " + std::to_string(first) + " (" + TypeName(firstType) +
        (HigherOrderKindOf(firstType) >= 0
            ? ", whose " + std::to_string(firstNodes) + " nodes do not make one"
            : std::string()) +
        "): segments come from line, polyline and polygon cells (triangles, quads, pixels; "
        "quadratic, cubic and Lagrange ones through their nodes), points from every cell and "
        "point." });
  }
  return out;
}
