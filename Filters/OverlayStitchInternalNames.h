// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// Internal to OverlayStitch::Filters (not installed): the input's arrays
// named like those the filter adds to it on the way (OverlayStitchGather.h)
// are set aside before it adds its own, which they would otherwise stand for
// (a review: a user array vtkOverlayStitchSourceCellId renumbered the cells
// in the filter's messages).
#ifndef OverlayStitchInternalNames_h
#define OverlayStitchInternalNames_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkDataObject;

/// Whether an array's name is one the filter gives arrays of its input on
/// the way (block, rank and source ids; the count of ignored cells; the marks
/// of malformed cell arrays and of float points).
bool OverlayStitchIsInternalName(const char* name);

/// input as it is when no point, cell or field data array of it (of any
/// block of a composite) bears one of the filter's internal names;
/// otherwise a shallow copy without them, each named in removed ("point
/// data array vtkOverlayStitchSourcePointId of block 1"), once per name
/// and kind.
vtkSmartPointer<vtkDataObject> OverlayStitchWithoutInternalArrays(
  vtkDataObject* input, std::vector<std::string>& removed);

#endif
