// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
#include "OverlayStitchArrays.h"

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"

#include "OverlayStitchInternalNames.h"

#include <algorithm>
#include <climits>
#include <cstring>
#include <limits>

bool OverlayStitchIsFloating(vtkAbstractArray* array)
{
  const int type = array->GetDataType();
  return vtkDataArray::SafeDownCast(array) && (type == VTK_FLOAT || type == VTK_DOUBLE);
}

bool OverlayStitchIsMarker(vtkAbstractArray* array, const char* name)
{
  return array && array->GetName() && std::strcmp(array->GetName(), name) == 0 &&
    vtkDataArray::SafeDownCast(array) && array->GetNumberOfComponents() == 1 &&
    !OverlayStitchIsFloating(array);
}

int OverlayStitchMarkerValue(double value)
{
  constexpr double lo = std::numeric_limits<int>::min(), hi = std::numeric_limits<int>::max();
  return value >= lo && value <= hi ? static_cast<int>(value) : value > hi ? INT_MAX : INT_MIN;
}

bool OverlayStitchIsNeverCarried(const char* name)
{
  return name &&
    (std::strcmp(name, vtkDataSetAttributes::GhostArrayName()) == 0 ||
      OverlayStitchIsInternalName(name));
}

bool OverlayStitchHasUserArrays(vtkDataSetAttributes* in)
{
  for (int i = 0; in && i < in->GetNumberOfArrays(); ++i)
  {
    if (!OverlayStitchIsNeverCarried(in->GetArrayName(i)))
    {
      return true;
    }
  }
  return false;
}

std::vector<vtkAbstractArray*> OverlayStitchCarriedArrays(vtkDataSetAttributes* in, vtkIdType items,
  const char* kind, const char* output, const std::vector<std::string>& reserved,
  std::vector<std::string>& warnings)
{
  std::vector<vtkAbstractArray*> carried;
  for (int i = 0; in && i < in->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* source = in->GetAbstractArray(i);
    const char* name = source->GetName();
    const std::string array = std::string("The input's ") + kind + " data array " +
      (name ? name : "(unnamed)") + " is not carried";
    if (OverlayStitchIsNeverCarried(name))
    {
      continue;
    }
    if (name && std::find(reserved.begin(), reserved.end(), name) != reserved.end())
    {
      warnings.push_back(
        array + " to the " + output + " output: it has an array of that name of its own.");
      continue;
    }
    if (source->GetNumberOfTuples() < items)
    {
      warnings.push_back(
        OverlayStitchShortArrayNote(kind, name, source->GetNumberOfTuples(), items));
      continue;
    }
    carried.push_back(source);
  }
  return carried;
}

std::string OverlayStitchShortArrayNote(
  const char* kind, const char* name, vtkIdType tuples, vtkIdType items, const std::string& where)
{
  return std::string("The input's ") + kind + " data array " + (name ? name : "(unnamed)") +
    " is not carried: " + (where.empty() ? "it" : where) + " has " + std::to_string(tuples) +
    " tuples for " + std::to_string(items) + " " + kind + "s.";
}

void OverlayStitchKeepActive(vtkDataSetAttributes* in, vtkDataSetAttributes* out,
  const std::vector<vtkAbstractArray*>& carried)
{
  for (int a = 0; a < vtkDataSetAttributes::NUM_ATTRIBUTES; ++a)
  {
    vtkAbstractArray* active = in->GetAbstractAttribute(a);
    if (active && active->GetName() &&
      std::find(carried.begin(), carried.end(), active) != carried.end() &&
      a != vtkDataSetAttributes::GLOBALIDS && a != vtkDataSetAttributes::PEDIGREEIDS &&
      a != vtkDataSetAttributes::NORMALS)
    {
      out->SetActiveAttribute(active->GetName(), a);
    }
  }
}
