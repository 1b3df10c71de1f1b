// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// Internal to OverlayStitch::Filters and osm-mesh (not installed): the names
// of the arrays the filter and the reader write and read, in one place. They
// are the output contract README documents; the tests spell them out on
// purpose, as a user would.
#ifndef OverlayStitchArrayNames_h
#define OverlayStitchArrayNames_h

#include <array>

namespace OverlayStitchArrayNames
{

// The input's field data: hole and region seeds (vtkTrianglePolyReader writes
// them from a .poly), and the first index of the file the points came from.
constexpr const char* HolePoints = "HolePoints";
constexpr const char* RegionAttributes = "RegionAttributes";
constexpr const char* FileFirstIndex = "FileFirstIndex";
// The seed arrays' shapes, by components: HolePoints (x, y) or (x, y, z);
// RegionAttributes (x, y, attribute) or (x, y, attribute, maximum area).
// Others are ignored with a warning.
constexpr bool IsHolePointsShape(int components)
{
  return components == 2 || components == 3;
}
constexpr bool IsRegionAttributesShape(int components)
{
  return components == 3 || components == 4;
}
// The input's point and cell data: Triangle's vertex and segment markers.
constexpr const char* PointMarker = "PointMarker";
constexpr const char* SegmentMarker = "SegmentMarker";

// The Mesh output's point data.
constexpr const char* VertexOrigin = "VertexOrigin";
constexpr const char* InputPointId = "InputPointId";
constexpr const char* InputZ = "InputZ";
// Point and cell data of the outputs of a composite input only.
constexpr const char* InputBlockId = "InputBlockId";
// The Mesh output's cell data.
constexpr const char* MinAngle = "MinAngle";
constexpr const char* MaxAngle = "MaxAngle";
constexpr const char* RegionId = "RegionId";
constexpr const char* RegionAttribute = "RegionAttribute";
constexpr const char* InputCellId = "InputCellId";
// The Mesh output's field data: counts about the input.
constexpr const char* IgnoredCells = "IgnoredCells";
constexpr const char* InputHolePoints = "InputHolePoints";
constexpr const char* InputPlaneFitted = "InputPlaneFitted";
constexpr const char* InputProjectedToXY = "InputProjectedToXY";

// The Edges output's cell data: one 0/1 array per edge flag, the edge's class
// (osm::EdgeClass), and in its field data the classes' names.
constexpr const char* Overlay = "Overlay";
constexpr const char* Kept = "Kept";
constexpr const char* Discarded = "Discarded";
constexpr const char* Input = "Input";
constexpr const char* EdgeClass = "EdgeClass";
constexpr const char* EdgeClassNames = "EdgeClassNames";

// Each output's own arrays (InputBlockId aside), which no carried input array
// may take the name of.
constexpr std::array<const char*, 2> MeshPointArrays{ VertexOrigin, InputPointId };
constexpr std::array<const char*, 5> MeshCellArrays{ MinAngle, MaxAngle, RegionId, RegionAttribute,
  InputCellId };
constexpr std::array<const char*, 6> EdgesCellArrays{ Overlay, Kept, Discarded, Input, EdgeClass,
  InputCellId };

} // namespace OverlayStitchArrayNames

#endif
