// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// Internal to OverlayStitch::Filters (not installed): an unstructured grid
// read as the polydata the filter meshes (a .vtu, or the blocks an Exodus or
// Gmsh reader gives, hold their lines and polygons in one).
#ifndef OverlayStitchUnstructured_h
#define OverlayStitchUnstructured_h

#include "vtkSmartPointer.h"
#include "vtkType.h" // for vtkIdType

#include "OverlayStitchGather.h" // for OverlayStitchNote

#include <string>
#include <vector>

class vtkPolyData;
class vtkUnstructuredGrid;

/// grid as polydata: its points with their point data and its field data (the
/// hole seeds), and each cell of a type polydata holds as the cell of its
/// kind, with its cell data. Vertex and polyvertex cells become verts; line
/// and polyline cells lines; triangle, quad, pixel (its corners put in loop
/// order) and polygon cells polys; triangle strips strips. vtkPolyData
/// numbers its cells by kind, so with sourceIds each cell carries its id in
/// grid and each point its own (the arrays of OverlayStitchGather.h), which
/// the outputs' InputCellId and the messages then give. Quadratic, cubic and
/// Lagrange cells are read through their nodes: a curve as the polyline of
/// its nodes in order along it, a face as the polygon of its boundary's
/// nodes (the mesh has no curved edges). Cells of other types (volumes,
/// Bezier cells, empty cells) are left out and
/// counted in ignoredCells; notes then receives a warning that names the
/// first by its id (in `where`, e.g. "block 3", or the input when empty) and
/// its type. Cell arrays shorter than the cells are left out too, each with a
/// note (reordered, they would be misread).
vtkSmartPointer<vtkPolyData> OverlayStitchPolyDataOf(vtkUnstructuredGrid* grid, bool sourceIds,
  const std::string& where, std::vector<OverlayStitchNote>& notes, vtkIdType& ignoredCells);

#endif
