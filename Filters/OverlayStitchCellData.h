// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// Internal to OverlayStitch::Filters (not installed): carries the input's
// cell data to the outputs (vtkOverlayStitchMesher's PassCellData), so that
// each input subsegment of the Edges output keeps what its line, polyline or
// polygon said (a river's name, a boundary condition, Triangle's segment
// marker), and each triangle of the Mesh what the polygon around it said (a
// land use, a material).
//
// An output cell that comes from no input cell takes NaN (floating point),
// 0 (other numbers) or an empty string, and "InputCellId" -1. Arrays named
// as the output's own (reserved) are left out with a warning; the ghost
// array is left out (the outputs are one piece, with no ghost cells). poll
// reports the fraction done and returns true to stop; the functions return
// false when stopped.
#ifndef OverlayStitchCellData_h
#define OverlayStitchCellData_h

#include "vtkType.h" // for vtkIdType

#include <functional>
#include <string>
#include <vector>

class vtkCellData;
class vtkPolyData;

namespace osm
{
class PlaneMap;
struct Pslg;
struct Result;
}

/// Fills out, the cell data of the Edges output (result.edges as lines, in
/// order), from in, the cell data of the input's inputCells cells (an array
/// with fewer tuples is left out, with a warning); segmentCells gives each
/// Pslg segment's input cell.
///
/// - "InputCellId": an input subsegment's input cell, -1 on every other edge
///   (the hull's edges included).
/// - Triangle's "SegmentMarker" (one integer per cell), by Triangle's rules
///   for .edge files: an input subsegment's nonzero marker, else 1 on the
///   mesh's boundary (the holes' included), else 0.
/// - Every other array: an input subsegment its cell's tuple.
bool OverlayStitchPassCellData(vtkCellData* in, vtkIdType inputCells, const osm::Pslg& pslg,
  const osm::Result& result, const std::vector<vtkIdType>& segmentCells,
  const std::vector<std::string>& reserved, vtkCellData* out,
  const std::function<bool(double)>& poll, std::vector<std::string>& warnings);

/// Fills out, the cell data of the Mesh (result.mesh's triangles, in order),
/// from the polygon cells of input (whose point i is the Pslg's point i):
/// each triangle takes the tuple of the smallest polygon (by area) that
/// contains it, the innermost where polygons nest (even-odd rule for a
/// polygon that crosses itself), and "InputCellId" names it. Nothing when
/// the input has no polygon cells. When it has no line cells either and the
/// domain is the enclosed one, a warning says where regions lie in no polygon (as a hole point: map
/// takes it back to the input's space).
bool OverlayStitchPassPolygonData(vtkPolyData* input, const osm::Pslg& pslg,
  const osm::Result& result, const osm::PlaneMap& map, const std::vector<std::string>& reserved,
  vtkCellData* out, const std::function<bool(double)>& poll, std::vector<std::string>& warnings);

#endif
