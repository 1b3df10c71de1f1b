// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
#include "OverlayStitchCellData.h"

#include "vtkAbstractArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include "Mesher.h"

#include <algorithm>
#include <cstring>
#include <limits>

namespace
{

bool IsFloating(vtkAbstractArray* array)
{
  const int type = array->GetDataType();
  return vtkDataArray::SafeDownCast(array) && (type == VTK_FLOAT || type == VTK_DOUBLE);
}

/// Triangle's segment markers: one integer per cell.
bool IsSegmentMarker(vtkAbstractArray* array)
{
  return array->GetName() && std::strcmp(array->GetName(), "SegmentMarker") == 0 &&
    vtkDataArray::SafeDownCast(array) && array->GetNumberOfComponents() == 1 && !IsFloating(array);
}

/// A new array like source, with n tuples of the value an edge from no input
/// cell takes.
vtkSmartPointer<vtkAbstractArray> NewTarget(vtkAbstractArray* source, vtkIdType n)
{
  auto target = vtkSmartPointer<vtkAbstractArray>::Take(source->NewInstance());
  target->SetName(source->GetName());
  target->SetNumberOfComponents(source->GetNumberOfComponents());
  target->CopyComponentNames(source);
  target->SetNumberOfTuples(n);
  if (auto* data = vtkDataArray::SafeDownCast(target))
  {
    data->Fill(IsFloating(source) ? std::numeric_limits<double>::quiet_NaN() : 0.0);
  }
  return target;
}

} // namespace

bool OverlayStitchPassCellData(vtkCellData* in, const osm::Result& result,
  const std::vector<vtkIdType>& segmentCells, const std::vector<std::string>& reserved,
  vtkCellData* out, const std::function<bool(double)>& poll, std::vector<std::string>& warnings)
{
  const auto n = static_cast<vtkIdType>(result.edges.size());
  vtkNew<vtkIdTypeArray> cellIds;
  cellIds->SetName("InputCellId");
  cellIds->SetNumberOfTuples(n);
  vtkIdType* cellOf = cellIds->GetPointer(0);
  std::vector<vtkIdType> fromCells; // the input subsegments: the only edges that take a tuple
  for (vtkIdType e = 0; e < n; ++e)
  {
    const int s = result.edges[static_cast<std::size_t>(e)].segment;
    cellOf[e] = s >= 0 ? segmentCells[static_cast<std::size_t>(s)] : -1;
    if (s >= 0)
    {
      fromCells.push_back(e);
    }
  }

  std::vector<std::pair<vtkAbstractArray*, vtkSmartPointer<vtkAbstractArray>>> carried;
  for (int i = 0; i < in->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* source = in->GetAbstractArray(i);
    const char* name = source->GetName();
    if (name && std::strcmp(name, vtkDataSetAttributes::GhostArrayName()) == 0)
    {
      continue;
    }
    if (name && std::find(reserved.begin(), reserved.end(), name) != reserved.end())
    {
      warnings.push_back(std::string("The input's cell data array ") + name +
        " is not carried to the Edges output: it has an array of that name of its own.");
      continue;
    }
    carried.emplace_back(source, NewTarget(source, n));
  }

  // Each carried array is filled along the input subsegments; the hull's
  // edges are boundary edges to Triangle's markers.
  const double total = static_cast<double>(fromCells.size() * (carried.size() + 1));
  std::size_t done = 0;
  for (auto& [source, target] : carried)
  {
    for (const vtkIdType e : fromCells)
    {
      if ((++done & 0xffff) == 0 && poll(static_cast<double>(done) / total))
      {
        return false;
      }
      target->SetTuple(e, cellOf[e], source);
    }
    if (IsSegmentMarker(source))
    {
      auto* markers = vtkDataArray::SafeDownCast(target);
      for (vtkIdType e = 0; e < n; ++e)
      {
        const osm::Edge& edge = result.edges[static_cast<std::size_t>(e)];
        if ((edge.flags & osm::EdgeInput) && edge.segment < 0)
        {
          markers->SetComponent(e, 0, 1.0);
        }
      }
    }
  }
  out->AddArray(cellIds);
  for (auto& carriedArray : carried)
  {
    out->AddArray(carriedArray.second);
  }
  // The input's active scalars, ... stay active; not its global or pedigree
  // ids, which the subsegments of one cell repeat.
  for (int a = 0; a < vtkDataSetAttributes::NUM_ATTRIBUTES; ++a)
  {
    vtkAbstractArray* active = in->GetAbstractAttribute(a);
    const bool isCarried = std::any_of(
      carried.begin(), carried.end(), [active](const auto& c) { return c.first == active; });
    if (active && isCarried && a != vtkDataSetAttributes::GLOBALIDS &&
      a != vtkDataSetAttributes::PEDIGREEIDS)
    {
      out->SetActiveAttribute(active->GetName(), a);
    }
  }
  return true;
}
