// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
#include "OverlayStitchInternalNames.h"

#include "vtkCellData.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"

#include "OverlayStitchCellArrays.h"
#include "OverlayStitchGather.h"

#include <algorithm>
#include <cstring>

namespace
{
/// The internal names among data's arrays.
std::vector<std::string> InternalNamesIn(vtkFieldData* data)
{
  std::vector<std::string> names;
  for (int i = 0; data && i < data->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* array = data->GetAbstractArray(i);
    if (array && OverlayStitchIsInternalName(array->GetName()))
    {
      names.emplace_back(array->GetName());
    }
  }
  return names;
}

/// data without its arrays of internal names (a shallow copy), or null if it
/// has none; each is said in removed, with what names data.
vtkSmartPointer<vtkDataObject> Cleared(
  vtkDataObject* data, const std::string& what, std::vector<std::string>& removed)
{
  auto* dataSet = vtkDataSet::SafeDownCast(data);
  if (!dataSet)
  {
    return nullptr;
  }
  const char* const kinds[3] = { "point", "cell", "field" };
  vtkFieldData* const attributes[3] = { dataSet->GetPointData(), dataSet->GetCellData(),
    dataSet->GetFieldData() };
  std::vector<std::string> found[3];
  bool any = false;
  for (int k = 0; k < 3; ++k)
  {
    found[k] = InternalNamesIn(attributes[k]);
    any = any || !found[k].empty();
  }
  if (!any)
  {
    return nullptr;
  }
  auto copy = vtk::TakeSmartPointer(dataSet->NewInstance());
  copy->ShallowCopy(dataSet);
  vtkFieldData* const copied[3] = { copy->GetPointData(), copy->GetCellData(),
    copy->GetFieldData() };
  for (int k = 0; k < 3; ++k)
  {
    for (const std::string& name : found[k])
    {
      copied[k]->RemoveArray(name.c_str());
      removed.push_back(std::string(kinds[k]) + " data array " + name + what);
    }
  }
  return copy;
}
} // namespace

//------------------------------------------------------------------------------
bool OverlayStitchIsInternalName(const char* name)
{
  const char* const internal[] = { OverlayStitchBlockIdName, OverlayStitchSourceCellIdName,
    OverlayStitchSourcePointIdName, OverlayStitchRankName, OverlayStitchIgnoredCellsName,
    OverlayStitchMalformedName, OverlayStitchFloatPointsName };
  return name && std::any_of(std::begin(internal), std::end(internal), [name](const char* own) {
    return std::strcmp(name, own) == 0;
  });
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkDataObject> OverlayStitchWithoutInternalArrays(
  vtkDataObject* input, std::vector<std::string>& removed)
{
  removed.clear();
  // Blocks are named by their flat index, as the filter's other messages do.
  return OverlayStitchWithBlocksReplaced(input, [&removed](vtkDataObject* data, int block) {
    return Cleared(data, block < 0 ? "" : " of block " + std::to_string(block), removed);
  });
}
