// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// Internal to OverlayStitch::Filters (not installed): the input's segment
// markers for Triangle's marker rules (osm::TriangleMarkers).
#ifndef OverlayStitchMarkers_h
#define OverlayStitchMarkers_h

#include "vtkType.h" // for vtkIdType

#include <vector>

class vtkAbstractArray;

/// Per Pslg segment, its marker in segmentMarkers (the input's cell array
/// "SegmentMarker", indexed by segmentCells, each segment's input cell), or
/// none (every segment 0) when that is null, not Triangle's (one integer
/// per cell), or shorter than the cells.
std::vector<int> OverlayStitchSegmentMarkers(
  vtkAbstractArray* segmentMarkers, const std::vector<vtkIdType>& segmentCells);

#endif
