// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
#include "OverlayStitchPointData.h"

#include "vtkAbstractArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include "Interpolation.h"
#include "Mesher.h"
#include "OverlayStitchArrayNames.h"
#include "OverlayStitchArrays.h"
#include "OverlayStitchMarkers.h"
#include "Pslg.h"
#include "TriangleMarkers.h"

#include <algorithm>
#include <cstring>
#include <optional>

namespace
{

/// How an input array reaches the mesh's vertices.
struct Carried
{
  enum Kind
  {
    Linear,  ///< floating point: the weighted sum
    Largest, ///< labels: the tuple of the largest weight
    Marker   ///< Triangle's vertex markers: the segment's marker (1 without), else 0
  };
  vtkAbstractArray* Source;
  vtkSmartPointer<vtkAbstractArray> Target;
  Kind How;
};

} // namespace

bool OverlayStitchInterpolatePointData(vtkPointData* in, vtkCellData* inCells,
  const osm::Pslg& pslg, const osm::Result& result, const std::vector<vtkIdType>& segmentCells,
  const std::vector<std::string>& reserved, vtkPointData* out,
  const std::function<bool(double)>& poll, std::vector<std::string>& warnings)
{
  const auto vertices = static_cast<vtkIdType>(result.mesh.vertices.size());
  std::vector<Carried> carried;
  for (vtkAbstractArray* source : OverlayStitchCarriedArrays(
         in, static_cast<vtkIdType>(pslg.points.size()), "point", "Mesh", reserved, warnings))
  {
    auto target = vtkSmartPointer<vtkAbstractArray>::Take(source->NewInstance());
    target->SetName(source->GetName());
    target->SetNumberOfComponents(source->GetNumberOfComponents());
    target->CopyComponentNames(source);
    target->SetNumberOfTuples(vertices);
    if (auto* data = vtkDataArray::SafeDownCast(target))
    {
      data->Fill(0.0); // a vertex with no terms (none on the input) reads 0
    }
    carried.push_back({ source, target,
      OverlayStitchIsFloating(source)                                         ? Carried::Linear
        : OverlayStitchIsMarker(source, OverlayStitchArrayNames::PointMarker) ? Carried::Marker
                                                                              : Carried::Largest });
  }
  if (carried.empty())
  {
    return true;
  }
  const bool markers = std::any_of(
    carried.begin(), carried.end(), [](const Carried& c) { return c.How == Carried::Marker; });
  std::optional<osm::TriangleMarkers> triangle;
  if (markers)
  {
    triangle.emplace(pslg, result,
      OverlayStitchSegmentMarkers(
        inCells ? inCells->GetArray(OverlayStitchArrayNames::SegmentMarker) : nullptr,
        segmentCells));
  }

  vtkNew<vtkIdList> ids;
  double weights[6];
  vtkIdType visited = 0;
  const bool done = osm::visitInputWeights(pslg, result, [&](const osm::VertexTerms& t) {
    if ((++visited & 0xffff) == 0 && poll(static_cast<double>(visited) / vertices))
    {
      return false;
    }
    const auto v = static_cast<vtkIdType>(t.vertex);
    for (const Carried& c : carried)
    {
      if (c.How == Carried::Marker)
      {
        auto* source = vtkDataArray::SafeDownCast(c.Source);
        const int own =
          t.inputPoint >= 0 ? OverlayStitchMarkerValue(source->GetComponent(t.inputPoint, 0)) : 0;
        vtkDataArray::SafeDownCast(c.Target)->SetComponent(
          v, 0, triangle->vertex(static_cast<int>(t.vertex), own));
      }
    }
    if (t.count == 0)
    {
      return true;
    }
    ids->SetNumberOfIds(t.count);
    int largest = 0;
    for (int k = 0; k < t.count; ++k)
    {
      ids->SetId(k, t.point[k]);
      weights[k] = t.weight[k];
      largest = t.weight[k] > t.weight[largest] ? k : largest;
    }
    for (const Carried& c : carried)
    {
      if (c.How == Carried::Marker)
      {
        continue; // above
      }
      if (t.inputPoint >= 0)
      {
        c.Target->SetTuple(v, t.inputPoint, c.Source);
      }
      else if (c.How == Carried::Linear)
      {
        c.Target->InterpolateTuple(v, ids, c.Source, weights);
      }
      else
      {
        c.Target->SetTuple(v, t.point[largest], c.Source);
      }
    }
    return true;
  });
  if (!done)
  {
    return false;
  }
  for (const Carried& c : carried)
  {
    out->AddArray(c.Target);
  }
  std::vector<vtkAbstractArray*> sources;
  for (const Carried& c : carried)
  {
    sources.push_back(c.Source);
  }
  OverlayStitchKeepActive(in, out, sources);
  return true;
}

void OverlayStitchMovePointData(vtkPointData* from, vtkPointData* to)
{
  for (int i = 0; i < from->GetNumberOfArrays(); ++i)
  {
    to->AddArray(from->GetAbstractArray(i));
  }
  for (int a = 0; a < vtkDataSetAttributes::NUM_ATTRIBUTES; ++a)
  {
    vtkAbstractArray* active = from->GetAbstractAttribute(a);
    if (active && active->GetName())
    {
      to->SetActiveAttribute(active->GetName(), a);
    }
  }
}
