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

#include <functional>
#include <string>

class vtkDataObject;
class vtkPolyData;

/// input with each dataset of it (input itself, or every block of a
/// composite) replaced by what replace gives for it, where that is not
/// null: input itself if none is replaced, else a shallow copy. replace is
/// given the block's flat index, or -1 for a dataset that is no block.
vtkSmartPointer<vtkDataObject> OverlayStitchWithBlocksReplaced(vtkDataObject* input,
  const std::function<vtkSmartPointer<vtkDataObject>(vtkDataObject*, int)>& replace);

/// input as it is when every cell array of it (a polydata's verts, lines,
/// polys and strips, an unstructured grid's cells and their types; every
/// block of a composite) is well formed. Otherwise a shallow copy in which a
/// dataset with a malformed array has no cells, and its field data the mark
/// OverlayStitchMalformedName, which the gather carries to the rank that
/// meshes: that rank refuses the input (a stand-in cell, as before, was
/// refused again as a cell naming a missing point: a review). malformed names
/// the first one ("the lines of block 2: their offsets decrease at cell 1").
vtkSmartPointer<vtkDataObject> OverlayStitchWithWellFormedCells(
  vtkDataObject* input, std::string& malformed);

/// An empty piece with the mark OverlayStitchMalformedName: what a rank that
/// cannot read its piece (out of memory) gathers instead, so that the other
/// ranks do not wait for it and the rank that meshes refuses the input.
vtkSmartPointer<vtkPolyData> OverlayStitchRefusedPiece();

#endif
