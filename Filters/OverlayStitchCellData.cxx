// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
#include "OverlayStitchCellData.h"

#include "vtkAbstractArray.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include "Clean.h"
#include "Mesher.h"
#include "NumberText.h"
#include "OverlayStitchArrayNames.h"
#include "OverlayStitchArrays.h"
#include "OverlayStitchGather.h"
#include "OverlayStitchMarkers.h"
#include "Plane.h"
#include "Pslg.h"
#include "RegionPolygons.h"
#include "TriangleMarkers.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <limits>
#include <utility>

namespace
{

using Poll = std::function<bool(double)>;
using CarriedArrays = std::vector<std::pair<vtkAbstractArray*, vtkSmartPointer<vtkAbstractArray>>>;

/// A new array like source, with n tuples of the value an output cell from no
/// input cell takes.
vtkSmartPointer<vtkAbstractArray> NewTarget(vtkAbstractArray* source, vtkIdType n)
{
  auto target = vtkSmartPointer<vtkAbstractArray>::Take(source->NewInstance());
  target->SetName(source->GetName());
  target->SetNumberOfComponents(source->GetNumberOfComponents());
  target->CopyComponentNames(source);
  target->SetNumberOfTuples(n);
  if (auto* data = vtkDataArray::SafeDownCast(target))
  {
    data->Fill(OverlayStitchIsFloating(source) ? std::numeric_limits<double>::quiet_NaN() : 0.0);
  }
  return target;
}

/// Adds cellIds ("InputCellId": per output cell its input cell, or -1) to out,
/// and a copy of each input array along it: the output cells listed in taking
/// (those with an input cell) take their cell's tuple. carried lists the
/// arrays made, with their sources.
bool Carry(vtkCellData* in, vtkIdType inputCells, vtkIdTypeArray* cellIds,
  const std::vector<vtkIdType>& taking, const std::vector<std::string>& reserved,
  const char* output, vtkCellData* out, const Poll& poll, std::vector<std::string>& warnings,
  CarriedArrays& carried)
{
  const vtkIdType n = cellIds->GetNumberOfTuples();
  const vtkIdType* cellOf = cellIds->GetPointer(0);
  for (vtkAbstractArray* source :
    OverlayStitchCarriedArrays(in, inputCells, "cell", output, reserved, warnings))
  {
    carried.emplace_back(source, NewTarget(source, n));
  }
  const double total = static_cast<double>(taking.size() * (carried.size() + 1));
  std::size_t done = 0;
  for (auto& [source, target] : carried)
  {
    for (const vtkIdType c : taking)
    {
      if ((++done & 0xffff) == 0 && poll(static_cast<double>(done) / total))
      {
        return false;
      }
      target->SetTuple(c, cellOf[c], source);
    }
  }
  OverlayStitchToSourceIds(in, OverlayStitchSourceCellIdName, cellIds, out);
  out->AddArray(cellIds);
  for (auto& carriedArray : carried)
  {
    out->AddArray(carriedArray.second);
  }
  std::vector<vtkAbstractArray*> sources;
  for (auto& carriedArray : carried)
  {
    sources.push_back(carriedArray.first);
  }
  OverlayStitchKeepActive(in, out, sources);
  return true;
}

vtkSmartPointer<vtkIdTypeArray> NewCellIds(vtkIdType n)
{
  auto ids = vtkSmartPointer<vtkIdTypeArray>::New();
  ids->SetName(OverlayStitchArrayNames::InputCellId);
  ids->SetNumberOfTuples(n);
  return ids;
}

/// The input's polygons as loops of Pslg points, and the cell of each, in
/// cell order.
void ReadPolygons(vtkPolyData* input, osm::PolygonLoops& loops, std::vector<vtkIdType>& cells)
{
  // vtkPolyData numbers its cells verts first, then lines, polygons, strips.
  vtkIdType cell = input->GetNumberOfVerts() + input->GetNumberOfLines();
  std::vector<int> ids;
  auto it = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell)
  {
    vtkIdType n;
    const vtkIdType* cellIds;
    it->GetCurrentCell(n, cellIds);
    if (n >= 2 && cellIds[n - 1] == cellIds[0])
    {
      --n; // a loop closed by repeating its first point, as the segments read it
    }
    if (n < 3)
    {
      continue;
    }
    ids.assign(cellIds, cellIds + n);
    loops.add(ids.data(), ids.size());
    cells.push_back(cell);
  }
}

} // namespace

bool OverlayStitchPassCellData(vtkCellData* in, vtkIdType inputCells, const osm::Pslg& pslg,
  const osm::Result& result, const std::vector<vtkIdType>& segmentCells,
  const std::vector<std::string>& reserved, vtkCellData* out, const Poll& poll,
  std::vector<std::string>& warnings)
{
  const auto n = static_cast<vtkIdType>(result.edges.size());
  auto cellIds = NewCellIds(n);
  vtkIdType* cellOf = cellIds->GetPointer(0);
  std::vector<vtkIdType> fromCells; // the input subsegments: the only edges that take a tuple
  for (vtkIdType e = 0; e < n; ++e)
  {
    if ((e & 0xffff) == 0 && poll(0.0)) // (an abort check only: 0.2 s at 1.4e7 edges)
    {
      return false;
    }
    const int s = result.edges[static_cast<std::size_t>(e)].segment;
    cellOf[e] = s >= 0 ? segmentCells[static_cast<std::size_t>(s)] : -1;
    if (s >= 0)
    {
      fromCells.push_back(e);
    }
  }
  CarriedArrays carried;
  if (!Carry(in, inputCells, cellIds, fromCells, reserved, "Edges", out, poll, warnings, carried))
  {
    return false;
  }
  // Triangle's markers, by its rules.
  for (auto& [source, target] : carried)
  {
    if (OverlayStitchIsMarker(source, OverlayStitchArrayNames::SegmentMarker))
    {
      const osm::TriangleMarkers markers(
        pslg, result, OverlayStitchSegmentMarkers(source, segmentCells));
      auto* marked = vtkDataArray::SafeDownCast(target);
      for (vtkIdType e = 0; e < n; ++e)
      {
        if ((e & 0xffff) == 0 && poll(1.0)) // (after Carry's share: an abort check only)
        {
          return false;
        }
        marked->SetComponent(e, 0, markers.edge(static_cast<std::size_t>(e)));
      }
    }
  }
  return true;
}

namespace
{

/// Input made of polygons alone is a surface: a region that no polygon holds
/// (a hole in it, or the space between its parts) is meshed all the same, as
/// the domain's rules say, but hardly what the user meant; says where.
void NoteRegionsOutsidePolygons(const osm::Result& result, const std::vector<int>& polygonOf,
  const osm::PlaneMap& map, std::vector<std::string>& warnings)
{
  const auto& points = result.mesh.vertices;
  auto area = [&points](const osm::Triangle& t) {
    const osm::Point &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
    return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  };
  std::vector<double> largest(polygonOf.size(), -1.0); // per region outside every polygon
  std::vector<std::size_t> largestAt(polygonOf.size(), 0);
  double outside = 0.0, all = 0.0;
  for (std::size_t t = 0; t < result.mesh.triangles.size(); ++t)
  {
    const double a = area(result.mesh.triangles[t]);
    all += a;
    const int r = t < result.regionId.size() ? result.regionId[t] : -1;
    if (r < 0 || polygonOf[static_cast<std::size_t>(r)] >= 0)
    {
      continue;
    }
    outside += a;
    if (a > largest[static_cast<std::size_t>(r)])
    {
      largest[static_cast<std::size_t>(r)] = a;
      largestAt[static_cast<std::size_t>(r)] = t;
    }
  }
  const auto regions =
    std::count_if(largest.begin(), largest.end(), [](double a) { return a >= 0; });
  if (regions == 0)
  {
    return;
  }
  // The centroid of the example region's largest triangle lies well inside it.
  const std::size_t r =
    std::find_if(largest.begin(), largest.end(), [](double a) { return a >= 0; }) - largest.begin();
  const osm::Triangle& t = result.mesh.triangles[largestAt[r]];
  const osm::Point c{ (points[t[0]].x + points[t[1]].x + points[t[2]].x) / 3,
    (points[t[0]].y + points[t[1]].y + points[t[2]].y) / 3 };
  const osm::Vec3 seed = map.toSpace(c);
  // Round-trip digits: a seed rounded for print may fall across a thin
  // region's edge.
  std::string where;
  if (map.seedXYDefined())
  {
    where = "a hole point (HolePoints) in each, e.g. (" + osm::formatNumber(seed.x) + ", " +
      osm::formatNumber(seed.y) + ")";
  }
  else
  {
    // In a vertical plane an (x, y) seed leaves the height undefined.
    where = "an (x, y, z) seed in each in the input's field data HolePoints, e.g. (" +
      osm::formatNumber(seed.x) + ", " + osm::formatNumber(seed.y) + ", " +
      osm::formatNumber(seed.z) + ")";
  }
  const std::string counts = std::to_string(regions) +
    " region(s) of the mesh lie in no input polygon (holes in the polygons, or space their "
    "edges enclose between them), area " +
    osm::generalText(outside, 6) + " of the mesh's " + osm::generalText(all, 6);
  warnings.push_back(counts + ": they are meshed, with InputCellId -1. To leave them out, give " +
    where + " for region " + std::to_string(r) + " (RegionId)");
}

} // namespace

bool OverlayStitchPassPolygonData(vtkPolyData* input, const osm::Pslg& pslg,
  const osm::Result& result, const osm::PlaneMap& map, const std::vector<std::string>& reserved,
  vtkCellData* out, const Poll& poll, std::vector<std::string>& warnings)
{
  if (!input->GetPolys() || input->GetPolys()->GetNumberOfCells() == 0)
  {
    return true;
  }
  osm::PolygonLoops loops;
  std::vector<vtkIdType> polygons; // the cell of each loop
  ReadPolygons(input, loops, polygons);
  std::vector<int> polygonOf; // per region of the mesh
  if (!osm::innermostPolygons(pslg, result, loops, polygonOf, poll))
  {
    return false;
  }

  const auto n = static_cast<vtkIdType>(result.mesh.triangles.size());
  auto cellIds = NewCellIds(n);
  vtkIdType* cellOf = cellIds->GetPointer(0);
  std::vector<vtkIdType> fromCells;
  for (vtkIdType t = 0; t < n; ++t)
  {
    const auto tt = static_cast<std::size_t>(t);
    const int r = tt < result.regionId.size() ? result.regionId[tt] : -1;
    const int of = r >= 0 ? polygonOf[static_cast<std::size_t>(r)] : -1;
    cellOf[t] = of >= 0 ? polygons[static_cast<std::size_t>(of)] : -1;
    if (of >= 0)
    {
      fromCells.push_back(t);
    }
  }
  // Only the enclosed domain is the polygons' (the hull's and the box's
  // padding is asked for).
  if ((!input->GetLines() || input->GetLines()->GetNumberOfCells() == 0) &&
    result.domain == osm::Domain::Enclosed)
  {
    NoteRegionsOutsidePolygons(result, polygonOf, map, warnings);
  }
  CarriedArrays carried;
  return Carry(input->GetCellData(), input->GetNumberOfCells(), cellIds, fromCells, reserved,
    "Mesh", out, poll, warnings, carried);
}
