// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
#include "OverlayStitchMarkers.h"

#include "vtkDataArray.h"

#include "OverlayStitchArrays.h"

std::vector<int> OverlayStitchSegmentMarkers(
  vtkAbstractArray* segmentMarkers, const std::vector<vtkIdType>& segmentCells)
{
  std::vector<int> markers;
  if (!OverlayStitchIsMarker(segmentMarkers, "SegmentMarker"))
  {
    return markers;
  }
  auto* data = vtkDataArray::SafeDownCast(segmentMarkers);
  markers.reserve(segmentCells.size());
  for (const vtkIdType cell : segmentCells)
  {
    markers.push_back(static_cast<int>(data->GetComponent(cell, 0)));
  }
  return markers;
}
