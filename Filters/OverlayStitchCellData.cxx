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

#include "Mesher.h"
#include "OverlayStitchArrays.h"
#include "OverlayStitchGather.h"
#include "OverlayStitchMarkers.h"
#include "Predicates.h"
#include "Pslg.h"
#include "TriangleMarkers.h"

#include <algorithm>
#include <cmath>
#include <cstring>
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
  ids->SetName("InputCellId");
  ids->SetNumberOfTuples(n);
  return ids;
}

/// An input polygon: its loop of Pslg points, its area and bounds.
struct Polygon
{
  vtkIdType Cell;
  std::size_t First; ///< in the loops' point list
  std::size_t Count;
  double Shoelace;     ///< the absolute signed area: lobes of a self-crossing loop cancel
  double Box[4];       ///< x min, x max, y min, y max
  double Inside = 0.0; ///< the area of the mesh's regions inside it (even-odd)
};

/// The input's polygons, in cell order.
void ReadPolygons(vtkPolyData* input, const osm::Pslg& pslg, std::vector<Polygon>& polygons,
  std::vector<int>& loops)
{
  // vtkPolyData numbers its cells verts first, then lines, polygons, strips.
  vtkIdType cell = input->GetNumberOfVerts() + input->GetNumberOfLines();
  auto it = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell)
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    if (n >= 2 && ids[n - 1] == ids[0])
    {
      --n; // a loop closed by repeating its first point, as the segments read it
    }
    if (n < 3)
    {
      continue;
    }
    Polygon p{ cell, loops.size(), static_cast<std::size_t>(n), 0.0,
      { std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
        std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity() } };
    for (vtkIdType k = 0; k < n; ++k)
    {
      const osm::Point& a = pslg.points[static_cast<std::size_t>(ids[k])];
      const osm::Point& b = pslg.points[static_cast<std::size_t>(ids[(k + 1) % n])];
      p.Shoelace += a.x * b.y - a.y * b.x;
      p.Box[0] = std::min(p.Box[0], a.x);
      p.Box[1] = std::max(p.Box[1], a.x);
      p.Box[2] = std::min(p.Box[2], a.y);
      p.Box[3] = std::max(p.Box[3], a.y);
      loops.push_back(static_cast<int>(ids[k]));
    }
    p.Shoelace = std::fabs(0.5 * p.Shoelace);
    polygons.push_back(p);
  }
}

/// The mesh's regions: per region a point inside it (the centroid of its
/// largest triangle, well away from the segments that bound the region), and
/// its area.
struct Regions
{
  std::vector<osm::Point> At;
  std::vector<double> Area;
};

Regions RegionPoints(const osm::Result& result)
{
  const auto& v = result.mesh.vertices;
  Regions regions;
  std::vector<osm::Point>& at = regions.At;
  std::vector<double> largest;
  for (std::size_t t = 0; t < result.mesh.triangles.size(); ++t)
  {
    const int r = t < result.regionId.size() ? result.regionId[t] : -1;
    if (r < 0)
    {
      continue;
    }
    if (static_cast<std::size_t>(r) >= at.size())
    {
      at.resize(static_cast<std::size_t>(r) + 1, { std::numeric_limits<double>::quiet_NaN(), 0 });
      largest.resize(at.size(), -1.0);
      regions.Area.resize(at.size(), 0.0);
    }
    const osm::Triangle& tri = result.mesh.triangles[t];
    const osm::Point &a = v[tri[0]], &b = v[tri[1]], &c = v[tri[2]];
    const double area = std::fabs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    regions.Area[static_cast<std::size_t>(r)] += 0.5 * area;
    if (area > largest[static_cast<std::size_t>(r)])
    {
      largest[static_cast<std::size_t>(r)] = area;
      at[static_cast<std::size_t>(r)] = { (a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3 };
    }
  }
  return regions;
}

/// The points in buckets of a square grid over their bounds, about one per
/// bucket, so that those inside a polygon's bounds are found without a scan.
struct PointGrid
{
  explicit PointGrid(const std::vector<osm::Point>& points)
  {
    for (const osm::Point& p : points)
    {
      Lo.x = std::min(Lo.x, p.x); // NaN (a region without a point) compares false: skipped
      Lo.y = std::min(Lo.y, p.y);
      Hi.x = std::max(Hi.x, p.x);
      Hi.y = std::max(Hi.y, p.y);
    }
    Side = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(points.size())))));
    Start.assign(static_cast<std::size_t>(Side) * Side + 1, 0);
    for (const osm::Point& p : points)
    {
      Start[Bucket(p) + 1] += std::isnan(p.x) ? 0 : 1;
    }
    for (std::size_t b = 1; b < Start.size(); ++b)
    {
      Start[b] += Start[b - 1];
    }
    Items.resize(Start.back());
    std::vector<std::size_t> next(Start.begin(), Start.end() - 1);
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      if (!std::isnan(points[i].x))
      {
        Items[next[Bucket(points[i])]++] = static_cast<int>(i);
      }
    }
  }
  int Column(double x) const { return Index(x, Lo.x, Hi.x); }
  int Row(double y) const { return Index(y, Lo.y, Hi.y); }
  /// Clamped before the conversion: a polygon's bounds may lie far beyond
  /// the points', where the quotient would not fit an int.
  int Index(double v, double lo, double hi) const
  {
    const double f = hi > lo ? (v - lo) / (hi - lo) * Side : 0.0;
    return static_cast<int>(std::clamp(f, 0.0, Side - 1.0));
  }
  std::size_t Bucket(const osm::Point& p) const
  {
    return std::isnan(p.x) ? 0
                           : static_cast<std::size_t>(Row(p.y)) * static_cast<std::size_t>(Side) +
        static_cast<std::size_t>(Column(p.x));
  }
  osm::Point Lo{ std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity() };
  osm::Point Hi{ -std::numeric_limits<double>::infinity(),
    -std::numeric_limits<double>::infinity() };
  int Side = 1;
  std::vector<std::size_t> Start;
  std::vector<int> Items;
};

/// Which of the candidates (y, region point index), sorted by y, lie inside
/// the polygon: the parity of the polygon's edges to their right (exact
/// orientation tests), each edge tested against the candidates in its span of y.
/// Costs the candidates in each edge's span of y: the number of candidates
/// times the edges a line across the polygon meets (a comb of 16,000 teeth
/// around 32,000 regions: 3.1 s). tests counts the orientation tests, and poll is
/// asked every 2^20 of them; returns false when it says stop.
bool MarkInside(const Polygon& p, const std::vector<int>& loops,
  const std::vector<osm::Point>& points, const std::vector<std::pair<double, int>>& candidates,
  const osm::Pslg& pslg, std::vector<unsigned char>& inside, std::size_t& tests,
  const std::function<bool()>& poll)
{
  inside.assign(candidates.size(), 0);
  for (std::size_t k = 0; k < p.Count; ++k)
  {
    osm::Point lo = pslg.points[static_cast<std::size_t>(loops[p.First + k])];
    osm::Point hi = pslg.points[static_cast<std::size_t>(loops[p.First + (k + 1) % p.Count])];
    if (lo.y == hi.y)
    {
      continue;
    }
    if (lo.y > hi.y)
    {
      std::swap(lo, hi);
    }
    // Half-open spans [lo.y, hi.y), so that a vertex at a point's y counts once.
    auto byY = [](const std::pair<double, int>& c, double y) { return c.first < y; };
    const auto first = std::lower_bound(candidates.begin(), candidates.end(), lo.y, byY);
    const auto last = std::lower_bound(first, candidates.end(), hi.y, byY);
    for (auto c = first; c != last; ++c)
    {
      if ((++tests & 0xfffff) == 0 && poll())
      {
        return false;
      }
      if (osm::orient2d(lo, hi, points[static_cast<std::size_t>(c->second)]) > 0)
      {
        inside[static_cast<std::size_t>(c - candidates.begin())] ^= 1;
      }
    }
  }
  return true;
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
    if (OverlayStitchIsMarker(source, "SegmentMarker"))
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

bool OverlayStitchPassPolygonData(vtkPolyData* input, const osm::Pslg& pslg,
  const osm::Result& result, const std::vector<std::string>& reserved, vtkCellData* out,
  const Poll& poll, std::vector<std::string>& warnings)
{
  if (!input->GetPolys() || input->GetPolys()->GetNumberOfCells() == 0)
  {
    return true;
  }
  std::vector<Polygon> polygons;
  std::vector<int> loops;
  ReadPolygons(input, pslg, polygons, loops);

  // Every region of the mesh lies inside or outside each polygon as a whole,
  // since the polygons' edges are segments: one point of it decides.
  const Regions regions = RegionPoints(result);
  const std::vector<osm::Point>& points = regions.At;
  const PointGrid grid(points);
  std::vector<int> polygonOf(points.size(), -1);
  std::vector<std::pair<double, int>> candidates;
  std::vector<unsigned char> inside;
  const double total = static_cast<double>(loops.size());
  std::size_t edgesDone = 0;
  std::size_t nextPoll = 0x10000;
  std::size_t tests = 0;
  const std::function<bool()> pollHere = [&]() {
    return poll(static_cast<double>(edgesDone) / total);
  };
  for (std::size_t i = 0; i < polygons.size(); ++i)
  {
    Polygon& p = polygons[i];
    if (edgesDone >= nextPoll)
    {
      nextPoll = edgesDone + 0x10000;
      if (pollHere())
      {
        return false;
      }
    }
    edgesDone += p.Count;
    candidates.clear();
    for (int row = grid.Row(p.Box[2]); row <= grid.Row(p.Box[3]); ++row)
    {
      for (int column = grid.Column(p.Box[0]); column <= grid.Column(p.Box[1]); ++column)
      {
        const std::size_t b = static_cast<std::size_t>(row) * static_cast<std::size_t>(grid.Side) +
          static_cast<std::size_t>(column);
        for (std::size_t k = grid.Start[b]; k < grid.Start[b + 1]; ++k)
        {
          const osm::Point& q = points[static_cast<std::size_t>(grid.Items[k])];
          if (q.x >= p.Box[0] && q.x <= p.Box[1] && q.y >= p.Box[2] && q.y <= p.Box[3])
          {
            candidates.emplace_back(q.y, grid.Items[k]);
          }
        }
      }
    }
    std::sort(candidates.begin(), candidates.end());
    if (!MarkInside(p, loops, points, candidates, pslg, inside, tests, pollHere))
    {
      return false;
    }
    for (std::size_t k = 0; k < candidates.size(); ++k)
    {
      p.Inside += inside[k] ? regions.Area[static_cast<std::size_t>(candidates[k].second)] : 0.0;
    }
    // The smallest polygon around a region is its innermost: by the area of
    // the mesh inside them (nested polygons keep their order, whatever holes
    // remove, and a self-crossing loop counts all its lobes), then by the
    // loop's own area; a tie keeps the first.
    for (std::size_t k = 0; k < candidates.size(); ++k)
    {
      int& of = polygonOf[static_cast<std::size_t>(candidates[k].second)];
      const Polygon* owner = of >= 0 ? &polygons[static_cast<std::size_t>(of)] : nullptr;
      if (inside[k] &&
        (!owner || p.Inside < owner->Inside ||
          (p.Inside == owner->Inside && p.Shoelace < owner->Shoelace)))
      {
        of = static_cast<int>(i);
      }
    }
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
    cellOf[t] = of >= 0 ? polygons[static_cast<std::size_t>(of)].Cell : -1;
    if (of >= 0)
    {
      fromCells.push_back(t);
    }
  }
  CarriedArrays carried;
  return Carry(input->GetCellData(), input->GetNumberOfCells(), cellIds, fromCells, reserved,
    "Mesh", out, poll, warnings, carried);
}
