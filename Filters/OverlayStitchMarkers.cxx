// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
#include "OverlayStitchMarkers.h"

#include "vtkDataArray.h"

#include "OverlayStitchArrayNames.h"
#include "OverlayStitchArrays.h"

#include <algorithm>

std::vector<int> OverlayStitchSegmentMarkers(
  vtkAbstractArray* segmentMarkers, const std::vector<vtkIdType>& segmentCells)
{
  std::vector<int> markers;
  if (!OverlayStitchIsMarker(segmentMarkers, OverlayStitchArrayNames::SegmentMarker))
  {
    return markers;
  }
  auto* data = vtkDataArray::SafeDownCast(segmentMarkers);
  const vtkIdType tuples = data->GetNumberOfTuples();
  if (std::any_of(segmentCells.begin(), segmentCells.end(),
        [tuples](vtkIdType cell) { return cell < 0 || cell >= tuples; }))
  {
    return markers; // too short for the cells (the cell data carrier warns)
  }
  markers.reserve(segmentCells.size());
  for (const vtkIdType cell : segmentCells)
  {
    markers.push_back(OverlayStitchMarkerValue(data->GetComponent(cell, 0)));
  }
  return markers;
}
