// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// Internal to OverlayStitch::Filters (not installed): cell arrays checked
// before any cell is read. A legacy .vtk file or a program can give offsets
// that decrease or pass the end of the connectivity; iterating such an array
// reads out of bounds (a review: osm-mesh and ParaView crashed on one).
#ifndef OverlayStitchCellArrays_h
#define OverlayStitchCellArrays_h

#include "vtkSmartPointer.h"

#include <string>

class vtkDataObject;

/// input as it is when every cell array of it (a polydata's verts, lines,
/// polys and strips, an unstructured grid's cells and their types; every
/// block of a composite) is well formed. Otherwise a shallow copy in which
/// each malformed array is replaced by one cell naming point -1, which the
/// filter then refuses as a cell naming a point that does not exist, on every
/// rank alike; malformed names the first one ("the lines of block 2: their
/// offsets decrease at cell 1").
vtkSmartPointer<vtkDataObject> OverlayStitchWithWellFormedCells(
  vtkDataObject* input, std::string& malformed);

#endif
