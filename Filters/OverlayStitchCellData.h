// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// Internal to OverlayStitch::Filters (not installed): carries the input's
// cell data to the Edges output (vtkOverlayStitchMesher's PassCellData), so
// that each input subsegment keeps what its line, polyline or polygon said
// (a river's name, a boundary condition, Triangle's segment marker).
#ifndef OverlayStitchCellData_h
#define OverlayStitchCellData_h

#include "vtkType.h" // for vtkIdType

#include <functional>
#include <string>
#include <vector>

class vtkCellData;

namespace osm
{
struct Result;
}

/// Fills out, the cell data of the Edges output (result.edges as lines, in
/// order), from in, the input's cell data; segmentCells gives each Pslg
/// segment's input cell.
///
/// - "InputCellId": an input subsegment's input cell, -1 on every other edge
///   (the hull's edges included).
/// - Triangle's "SegmentMarker" (one integer per cell): an input subsegment
///   its cell's marker, a hull edge 1 (Triangle marks boundary edges so), any
///   other edge 0, as in Triangle's .edge files.
/// - Every other array: an input subsegment its cell's tuple; every other
///   edge NaN (floating point), 0 (other numbers) or an empty string.
///
/// Arrays named as the Edges output's own (reserved) are left out with a
/// warning; the ghost array is left out (the output has no ghost cells).
/// poll reports the fraction done and returns true to stop; returns false
/// when stopped.
bool OverlayStitchPassCellData(vtkCellData* in, const osm::Result& result,
  const std::vector<vtkIdType>& segmentCells, const std::vector<std::string>& reserved,
  vtkCellData* out, const std::function<bool(double)>& poll, std::vector<std::string>& warnings);

#endif
