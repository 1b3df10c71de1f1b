// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// Internal to OverlayStitch::Filters (not installed): carries the input's
// point data to the mesh's vertices (vtkOverlayStitchMesher's
// InterpolatePointData), with the weights of the core's Interpolation.h.
//
// Arrays of floating-point values are interpolated: an input vertex keeps its
// tuple, a point on a segment takes the tuple linear along it, any other point
// the tuple linear in the triangle of those points that holds it. Other arrays
// (integers, strings: labels and ids, which an average would turn into
// another label) take the tuple of the input point with the largest weight,
// except Triangle's vertex markers: a "PointMarker" array (as
// vtkTrianglePolyReader writes them) follows Triangle's rules: a point's own
// nonzero marker, else a nonzero marker of a segment it lies on (the cells'
// "SegmentMarker"), else 1 on the mesh's boundary, else 0
// (OverlayStitchCellData.h gives the segment markers to the Edges output).
#ifndef OverlayStitchPointData_h
#define OverlayStitchPointData_h

#include "vtkType.h" // for vtkIdType

#include <functional>
#include <string>
#include <vector>

class vtkCellData;
class vtkPointData;

namespace osm
{
struct Pslg;
struct Result;
}

/// Fills out with the mesh's point data from in (the input's, point i being
/// the Pslg's point i). segmentCells gives each Pslg segment's input cell,
/// whose cell data (inCells) holds the segment markers; result must come from
/// Options::keepVertexSegments. An input array with one of the reserved names (the mesh's own
/// arrays) is left out, with a warning. poll reports the fraction done and
/// returns true to stop; returns false when stopped.
bool OverlayStitchInterpolatePointData(vtkPointData* in, vtkCellData* inCells,
  const osm::Pslg& pslg, const osm::Result& result, const std::vector<vtkIdType>& segmentCells,
  const std::vector<std::string>& reserved, vtkPointData* out,
  const std::function<bool(double)>& poll, std::vector<std::string>& warnings);

/// Adds the arrays of from to to, with their active attributes.
void OverlayStitchMovePointData(vtkPointData* from, vtkPointData* to);

#endif
