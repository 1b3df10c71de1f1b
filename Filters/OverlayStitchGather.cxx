// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
#include "OverlayStitchGather.h"

#include "OverlayStitchArrays.h"
#include "OverlayStitchInternalNames.h"
#include "OverlayStitchUnstructured.h"

#include "vtkAbstractArray.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include "OverlayStitchArrayNames.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <numeric>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace
{

namespace Names = OverlayStitchArrayNames;

/// Exact coordinates of a point; -0.0 and +0.0 are the same point.
using PointKey = std::array<double, 3>;

struct PointKeyHash
{
  std::size_t operator()(const PointKey& key) const
  {
    std::size_t h = 0;
    for (double value : key)
    {
      std::uint64_t bits;
      std::memcpy(&bits, &value, sizeof bits);
      h ^= std::hash<std::uint64_t>()(bits) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    }
    return h;
  }
};

/// A cell as its kind and merged point ids, in the direction whose sequence is smaller.
using CellKey = std::vector<vtkIdType>;

struct CellKeyHash
{
  std::size_t operator()(const CellKey& key) const
  {
    std::size_t h = key.size();
    for (vtkIdType id : key)
    {
      h ^= std::hash<vtkIdType>()(id) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    }
    return h;
  }
};

/// Where a point or cell was first seen: the piece and its id in the combined output.
struct FirstSeen
{
  std::size_t Piece;
  vtkIdType Id;
};

vtkCellArray* CellsOfKind(vtkPolyData* polyData, int kind)
{
  switch (kind)
  {
    case 0:
      return polyData->GetVerts();
    case 1:
      return polyData->GetLines();
    case 2:
      return polyData->GetPolys();
    default:
      return polyData->GetStrips();
  }
}

void SetCellsOfKind(vtkPolyData* polyData, int kind, vtkCellArray* cells)
{
  switch (kind)
  {
    case 0:
      polyData->SetVerts(cells);
      break;
    case 1:
      polyData->SetLines(cells);
      break;
    case 2:
      polyData->SetPolys(cells);
      break;
    default:
      polyData->SetStrips(cells);
      break;
  }
}

/// Whether cell c is one that vtkPolyData::RemoveGhostCells() removes (flagged
/// duplicate, refined or hidden in ghosts, the piece's ghost array, if any).
bool IsGhostCell(vtkDataArray* ghosts, vtkIdType c)
{
  return ghosts && c < ghosts->GetNumberOfTuples() &&
    (static_cast<int>(ghosts->GetComponent(c, 0)) &
      (vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::REFINEDCELL |
        vtkDataSetAttributes::HIDDENCELL)) != 0;
}

/// The piece's ghost array when VTK's RemoveGhostCells() accepts it (one
/// unsigned char per cell), else null: its flags then mean nothing here
/// either, and the cells are meshed as they are.
vtkDataArray* GhostsOf(vtkPolyData* piece)
{
  auto* ghosts = vtkUnsignedCharArray::SafeDownCast(
    piece->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()));
  return ghosts && ghosts->GetNumberOfComponents() == 1 &&
      ghosts->GetNumberOfTuples() >= piece->GetNumberOfCells()
    ? ghosts
    : nullptr;
}

/// Removes from piece (a copy) the point and cell arrays with fewer tuples than
/// its points or cells, which no copy may read past, noting each in notes
/// (if given) as the filter reports such an array ("... : it has 2 tuples for
/// 9 points."; `where` names the piece, e.g. "block 2", or is empty).
void DropShortArrays(
  vtkPolyData* piece, const std::string& where, std::vector<OverlayStitchNote>* notes)
{
  for (vtkDataSetAttributes* data : { static_cast<vtkDataSetAttributes*>(piece->GetPointData()),
         static_cast<vtkDataSetAttributes*>(piece->GetCellData()) })
  {
    const bool points = data == piece->GetPointData();
    const vtkIdType n = points ? piece->GetNumberOfPoints() : piece->GetNumberOfCells();
    for (int a = data->GetNumberOfArrays() - 1; a >= 0; --a)
    {
      vtkAbstractArray* array = data->GetAbstractArray(a);
      if (array->GetNumberOfTuples() >= n)
      {
        continue;
      }
      if (notes)
      {
        const char* kind = points ? "point" : "cell";
        notes->push_back({ { kind, array->GetName() ? array->GetName() : "(unnamed)" },
          OverlayStitchShortArrayNote(
            kind, array->GetName(), array->GetNumberOfTuples(), n, where) });
      }
      data->RemoveArray(a);
    }
  }
}

/// Whether piece has a point or cell array with fewer tuples than its items.
bool HasShortArrays(vtkPolyData* piece)
{
  for (auto [data, n] : { std::make_pair(static_cast<vtkDataSetAttributes*>(piece->GetPointData()),
                            piece->GetNumberOfPoints()),
         std::make_pair(
           static_cast<vtkDataSetAttributes*>(piece->GetCellData()), piece->GetNumberOfCells()) })
  {
    for (int a = 0; a < data->GetNumberOfArrays(); ++a)
    {
      if (data->GetAbstractArray(a)->GetNumberOfTuples() < n)
      {
        return true;
      }
    }
  }
  return false;
}

/// The first of ids[0..n) that names no point of a piece with `points`
/// points, or ids + n.
const vtkIdType* FirstMissing(vtkIdType n, const vtkIdType* ids, vtkIdType points)
{
  return std::find_if(ids, ids + n, [points](vtkIdType id) { return id < 0 || id >= points; });
}

/// Calls visit(cellId, n, ids) on every cell of piece in cell id order
/// (verts, lines, polys, strips) until it returns false.
template <typename Visit>
void VisitCells(vtkPolyData* piece, Visit visit)
{
  vtkIdType cellId = 0;
  for (int kind = 0; kind < 4; ++kind)
  {
    auto it = vtk::TakeSmartPointer(CellsOfKind(piece, kind)->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cellId)
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      if (!visit(cellId, n, ids))
      {
        return;
      }
    }
  }
}

/// Cells naming a point their piece does not have: counted, and the first (in
/// piece, then cell id order, whatever order they are seen in) described, by
/// its block and its id there where the piece comes from a composite input.
struct InvalidCells
{
  const char* PieceName;
  vtkIdType Count = 0;
  std::string First;
  std::pair<std::size_t, vtkIdType> FirstAt;

  /// Notes cell `cellId` (ids `ids[0..n)`) of piece `piece` (`source`), which
  /// has `points` points.
  void Note(vtkIdType n, const vtkIdType* ids, vtkIdType points, vtkIdType cellId,
    std::size_t piece, vtkPolyData* source)
  {
    const vtkIdType* bad = FirstMissing(n, ids, points);
    if (bad == ids + n)
    {
      return;
    }
    if (Count++ == 0 || std::make_pair(piece, cellId) < FirstAt)
    {
      FirstAt = { piece, cellId };
      // A single input (PieceName null) is not named as a piece.
      const std::string inBlock =
        OverlayStitchSource(source->GetCellData(), OverlayStitchSourceCellIdName, cellId, "cell");
      const std::string cell = !inBlock.empty() ? inBlock
        : PieceName
        ? "cell " + std::to_string(cellId) + " of " + PieceName + " " + std::to_string(piece)
        : "cell " + std::to_string(cellId);
      // A -1 in a rank's combination of blocks is what combining left of an
      // invalid id (said on that rank); other ids, and those of a block read
      // on its own rank, are the input's own (a review).
      const bool block = source->GetCellData()->GetArray(OverlayStitchBlockIdName);
      const bool combined = block && source->GetCellData()->GetArray(OverlayStitchRankName);
      First = cell + " refers to " +
        (*bad != -1 || !combined ? "point " + std::to_string(*bad)
                                 : std::string("a point that does not exist")) +
        ", but " +
        (PieceName ? std::string("that ") + PieceName
                   : std::string(block ? "that block" : "the input")) +
        " has " + std::to_string(points) + " point(s)";
    }
  }

  /// Notes every cell of a piece naming a point it does not have, but for its
  /// ghost cells (cell ids count them). (Not from the connectivity's range:
  /// VTK caches it, and cells inserted in place do not renew it.)
  void NoteCells(vtkPolyData* piece, std::size_t index)
  {
    NoteAgainst(piece, piece->GetNumberOfPoints(), index);
  }

  /// Notes every cell of a piece that has no points.
  void NotePiecesCells(vtkPolyData* piece, std::size_t index) { NoteAgainst(piece, 0, index); }

private:
  /// Notes each cell of piece but its ghost cells, in cell id order, as if it
  /// had `points` points.
  void NoteAgainst(vtkPolyData* piece, vtkIdType points, std::size_t index)
  {
    vtkDataArray* ghosts = GhostsOf(piece);
    VisitCells(piece, [&](vtkIdType cellId, vtkIdType n, const vtkIdType* ids) {
      if (!IsGhostCell(ghosts, cellId))
      {
        Note(n, ids, points, cellId, index, piece);
      }
      return true;
    });
  }
};

bool IsFinite(const std::array<double, 3>& at)
{
  return std::isfinite(at[0]) && std::isfinite(at[1]) && std::isfinite(at[2]);
}

/// A hole seed of a piece's field data: (x, y, z), or (x, y) with z 0.
struct HoleSeed
{
  std::array<double, 3> At;
  bool XY; ///< given as (x, y): the mesher lifts it along z onto the input's plane
  bool operator<(const HoleSeed& other) const
  {
    return std::tie(this->At, this->XY) < std::tie(other.At, other.XY);
  }
};

/// Appends the hole seeds of `field` (a 3-component, or 2-component, numeric
/// "HolePoints" array) to `seeds`, skipping exact repeats (every rank may
/// hold the same field data); false if the array has another number of
/// components, which the serial run ignores with a warning too.
bool CollectHolePoints(vtkFieldData* field, std::vector<HoleSeed>& seeds, std::set<HoleSeed>& seen)
{
  vtkDataArray* holes = field ? field->GetArray(Names::HolePoints) : nullptr;
  const int components = holes ? holes->GetNumberOfComponents() : 3;
  if (!holes || !Names::IsHolePointsShape(components))
  {
    return !holes;
  }
  for (vtkIdType t = 0; t < holes->GetNumberOfTuples(); ++t)
  {
    const HoleSeed seed{ { holes->GetComponent(t, 0) + 0.0, holes->GetComponent(t, 1) + 0.0,
                           components == 3 ? holes->GetComponent(t, 2) + 0.0 : 0.0 },
      components == 2 };
    // NaN seeds are passed on (the mesher reports them); they are never "equal".
    if (!IsFinite(seed.At) || seen.insert(seed).second)
    {
      seeds.push_back(seed);
    }
  }
  return true;
}

/// A region seed of a piece's field data: (x, y, attribute, maximum area),
/// the area -1 (none) where the array has 3 components.
using RegionSeed = std::array<double, 4>;

/// Appends the region seeds of `field` (a 4-component, or 3-component,
/// numeric "RegionAttributes" array) to `seeds`, skipping exact repeats (every
/// rank may hold the same field data); false if the array has another number
/// of components, which the serial run ignores with a warning too.
bool CollectRegionSeeds(
  vtkFieldData* field, std::vector<RegionSeed>& seeds, std::set<RegionSeed>& seen)
{
  vtkDataArray* regions = field ? field->GetArray(Names::RegionAttributes) : nullptr;
  const int components = regions ? regions->GetNumberOfComponents() : 4;
  if (!regions || !Names::IsRegionAttributesShape(components))
  {
    return !regions;
  }
  for (vtkIdType t = 0; t < regions->GetNumberOfTuples(); ++t)
  {
    RegionSeed seed{ 0.0, 0.0, 0.0, -1.0 };
    regions->GetTuple(t, seed.data());
    const bool finite =
      std::all_of(seed.begin(), seed.end(), [](double v) { return std::isfinite(v); });
    if (!finite || seen.insert(seed).second)
    {
      seeds.push_back(seed);
    }
  }
  return true;
}

} // namespace

//------------------------------------------------------------------------------
namespace
{
/// The arrays of some pieces that combining left out, since not every piece
/// has them (with the same type and components).
void NoteArraysLeftOut(const std::vector<vtkPolyData*>& used, vtkPolyData* combined,
  std::vector<OverlayStitchArrayName>& out)
{
  std::set<OverlayStitchArrayName> seen;
  for (const bool cells : { false, true })
  {
    vtkDataSetAttributes* kept = cells ? static_cast<vtkDataSetAttributes*>(combined->GetCellData())
                                       : combined->GetPointData();
    for (vtkPolyData* piece : used)
    {
      vtkDataSetAttributes* attributes =
        cells ? static_cast<vtkDataSetAttributes*>(piece->GetCellData()) : piece->GetPointData();
      for (int i = 0; i < attributes->GetNumberOfArrays(); ++i)
      {
        const char* name = attributes->GetArrayName(i);
        const OverlayStitchArrayName item{ cells ? "cell" : "point", name ? name : "(unnamed)" };
        // Not the ghost array, nor the ids combining gives pieces (a review:
        // a rank's polydata beside another's blocks named them).
        if ((!name || !kept->GetAbstractArray(name)) && !OverlayStitchIsNeverCarried(name) &&
          seen.insert(item).second)
        {
          out.push_back(item);
        }
      }
    }
  }
}

/// Whether a cell of piece, not a ghost cell, names a point the piece does
/// not have. (Not from the connectivity's range: VTK caches it, and cells
/// inserted in place do not renew it.)
bool NamesMissingPoints(vtkPolyData* piece)
{
  const vtkIdType points = piece->GetNumberOfPoints();
  vtkDataArray* ghosts = GhostsOf(piece);
  bool missing = false;
  VisitCells(piece, [&](vtkIdType cellId, vtkIdType n, const vtkIdType* ids) {
    missing = !IsGhostCell(ghosts, cellId) && FirstMissing(n, ids, points) != ids + n;
    return !missing;
  });
  return missing;
}

/// An id array: value everywhere, or (value < 0) each tuple's own index.
vtkSmartPointer<vtkIdTypeArray> IdArray(const char* name, vtkIdType n, vtkIdType value)
{
  auto ids = vtkSmartPointer<vtkIdTypeArray>::New();
  ids->SetName(name);
  ids->SetNumberOfTuples(n);
  if (value >= 0)
  {
    ids->FillValue(value);
  }
  else
  {
    std::iota(ids->GetPointer(0), ids->GetPointer(0) + n, vtkIdType(0));
  }
  return ids;
}

/// Which points of piece a copy without its ghost cells keeps, in their order
/// in piece: those the remaining cells use (`kept`, ids in piece) and those
/// no cell uses at all, input vertices of the graph. (A ghost cell may name
/// points piece does not have: it is dropped whatever it names.)
std::vector<vtkIdType> PointsKept(vtkPolyData* piece, vtkIdTypeArray* kept)
{
  const vtkIdType points = piece->GetNumberOfPoints();
  std::vector<char> state(static_cast<std::size_t>(points), 0); // 1 used, 2 kept
  VisitCells(piece, [&](vtkIdType, vtkIdType n, const vtkIdType* ids) {
    for (vtkIdType k = 0; k < n; ++k)
    {
      if (ids[k] >= 0 && ids[k] < points)
      {
        state[static_cast<std::size_t>(ids[k])] = 1;
      }
    }
    return true;
  });
  for (vtkIdType i = 0; i < kept->GetNumberOfTuples(); ++i)
  {
    state[static_cast<std::size_t>(kept->GetValue(i))] = 2;
  }
  std::vector<vtkIdType> order;
  for (std::size_t i = 0; i < state.size(); ++i)
  {
    if (state[i] != 1)
    {
      order.push_back(static_cast<vtkIdType>(i));
    }
  }
  return order;
}

/// A copy of cells (of local, whose point p is point kept[p] of its source)
/// naming each point by its index in `order` (ids in the source).
vtkSmartPointer<vtkCellArray> Renumbered(
  vtkCellArray* cells, vtkIdTypeArray* kept, const std::vector<vtkIdType>& newId)
{
  auto out = vtkSmartPointer<vtkCellArray>::New();
  out->AllocateExact(cells->GetNumberOfCells(), cells->GetNumberOfConnectivityIds());
  std::vector<vtkIdType> renamed;
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    renamed.resize(static_cast<std::size_t>(n));
    for (vtkIdType k = 0; k < n; ++k)
    {
      renamed[static_cast<std::size_t>(k)] =
        newId[static_cast<std::size_t>(kept->GetValue(ids[k]))];
    }
    out->InsertNextCell(n, renamed.data());
  }
  return out;
}

/// A shallow copy of piece without the cells that are ghost copies of another
/// piece's (piece itself when it has none), its arrays and field data kept.
/// VTK's RemoveGhostCells() removes the cells (its semantics: flagged
/// duplicate, refined or hidden), but it renumbers the points in the order
/// the remaining cells use them and drops every point they do not use. The
/// points are taken here instead: those of the remaining cells and those no
/// cell used at all (input vertices of the graph), in their order in piece,
/// so that the mesh is the one of the same data without ghost cells. With
/// sourceIds, the copy's cells and points carry their ids in piece (unless
/// they already carry ids in a block), so that outputs and messages can name
/// them. Arrays too short for their points or cells are left out, each noted
/// in notes (`where` names the piece). A piece with a cell (not a ghost cell)
/// naming a missing point is returned as it is, to be refused by that cell's id.
vtkSmartPointer<vtkPolyData> WithoutGhostCells(vtkPolyData* piece, bool sourceIds,
  const std::string& where, std::vector<OverlayStitchNote>& notes)
{
  vtkAbstractArray* flags =
    piece->GetCellData()->GetAbstractArray(vtkDataSetAttributes::GhostArrayName());
  if (flags && !GhostsOf(piece))
  {
    notes.push_back({ {},
      std::string("The cell data array ") + vtkDataSetAttributes::GhostArrayName() +
        (where.empty() ? "" : " of " + where) +
        " is not used: ghost cells are flagged by one unsigned char per cell, and the cells it "
        "flags are meshed." });
  }
  if (!GhostsOf(piece) || NamesMissingPoints(piece))
  {
    return piece;
  }
  auto local = vtkSmartPointer<vtkPolyData>::New();
  if (piece->GetNumberOfPoints() == 0)
  {
    // VTK removes nothing then; every cell is a ghost cell or names no point.
    local->GetFieldData()->ShallowCopy(piece->GetFieldData());
    return local;
  }
  // The cells without ghosts, each point carrying its id in piece; VTK copies
  // only that point array.
  auto source = vtkSmartPointer<vtkPolyData>::New();
  source->ShallowCopy(piece);
  DropShortArrays(source, where, &notes);
  local->ShallowCopy(source);
  const bool hadIds = piece->GetPointData()->GetArray(OverlayStitchSourcePointIdName);
  if (!hadIds)
  {
    local->GetCellData()->AddArray(
      IdArray(OverlayStitchSourceCellIdName, piece->GetNumberOfCells(), -1));
  }
  local->GetPointData()->Initialize();
  local->GetPointData()->AddArray(IdArray("kept", piece->GetNumberOfPoints(), -1));
  local->RemoveGhostCells();
  vtkSmartPointer<vtkIdTypeArray> kept =
    vtkIdTypeArray::SafeDownCast(local->GetPointData()->GetArray("kept"));
  if (!kept || local->GetNumberOfCells() == piece->GetNumberOfCells())
  {
    return source; // no ghost cell
  }

  const std::vector<vtkIdType> order = PointsKept(piece, kept);
  std::vector<vtkIdType> newId(static_cast<std::size_t>(piece->GetNumberOfPoints()), -1);
  for (std::size_t k = 0; k < order.size(); ++k)
  {
    newId[static_cast<std::size_t>(order[k])] = static_cast<vtkIdType>(k);
  }
  for (int kind = 0; kind < 4; ++kind)
  {
    SetCellsOfKind(local, kind, Renumbered(CellsOfKind(local, kind), kept, newId));
  }
  const auto n = static_cast<vtkIdType>(order.size());
  vtkNew<vtkPoints> points;
  points->SetDataType(piece->GetPoints()->GetDataType());
  points->SetNumberOfPoints(n);
  for (vtkIdType k = 0; k < n; ++k)
  {
    points->SetPoint(k, piece->GetPoint(order[static_cast<std::size_t>(k)]));
  }
  local->SetPoints(points);
  vtkNew<vtkPointData> from;
  from->ShallowCopy(source->GetPointData());
  from->RemoveArray(vtkDataSetAttributes::GhostArrayName()); // as VTK's removal does
  vtkNew<vtkIdList> fromIds;
  fromIds->SetNumberOfIds(n);
  std::copy(order.begin(), order.end(), fromIds->begin());
  vtkPointData* to = local->GetPointData();
  to->Initialize();
  to->CopyGlobalIdsOn();
  to->CopyAllocate(from, n);
  to->CopyData(from.Get(), fromIds.Get(), vtkIdType(0));
  if (sourceIds && !hadIds)
  {
    auto ids = vtkSmartPointer<vtkIdTypeArray>::New();
    ids->SetName(OverlayStitchSourcePointIdName);
    ids->SetNumberOfTuples(n);
    std::copy(order.begin(), order.end(), ids->GetPointer(0));
    to->AddArray(ids);
  }
  else if (!hadIds)
  {
    local->GetCellData()->RemoveArray(OverlayStitchSourceCellIdName);
  }
  // RemoveGhostCells() may drop the field data (ParaView 5.11's VTK does): keep
  // the hole seeds.
  local->GetFieldData()->ShallowCopy(piece->GetFieldData());
  return local;
}

/// How messages name a piece without block ids: "rank 1" (pieceName and index).
std::string PieceLabel(const char* pieceName, std::size_t index)
{
  return std::string(pieceName) + " " + std::to_string(index);
}

/// The first value of the id array `name` in the cell, point or field data
/// of piece, or -1.
vtkIdType FirstIdOf(vtkPolyData* piece, const char* name)
{
  for (vtkFieldData* data : { static_cast<vtkFieldData*>(piece->GetCellData()),
         static_cast<vtkFieldData*>(piece->GetPointData()), piece->GetFieldData() })
  {
    auto* ids = vtkIdTypeArray::SafeDownCast(data->GetAbstractArray(name));
    if (ids && ids->GetNumberOfTuples() > 0)
    {
      return ids->GetValue(0);
    }
  }
  return -1;
}

/// How messages name a piece: by its block (and rank) when it carries block
/// ids, else as "rank 1" (pieceName and index).
std::string PieceLabel(vtkPolyData* piece, const char* pieceName, std::size_t index)
{
  const vtkIdType block = FirstIdOf(piece, OverlayStitchBlockIdName);
  if (block < 0)
  {
    return PieceLabel(pieceName, index);
  }
  const vtkIdType rank = FirstIdOf(piece, OverlayStitchRankName);
  return "block " + std::to_string(block) +
    (rank >= 0 ? " on rank " + std::to_string(rank) : std::string());
}

/// A shallow copy of block whose cells and points carry its flat index and
/// their ids in it, without its ghost cells: combined with the other blocks,
/// a ghost copy of a later block's cell would take the place of that cell.
vtkSmartPointer<vtkPolyData> WithBlockIds(
  vtkPolyData* block, unsigned int flatIndex, std::vector<OverlayStitchNote>& notes)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(block);
  const auto index = static_cast<vtkIdType>(flatIndex);
  const vtkIdType cells = block->GetNumberOfCells(), points = block->GetNumberOfPoints();
  copy->GetCellData()->AddArray(IdArray(OverlayStitchBlockIdName, cells, index));
  copy->GetPointData()->AddArray(IdArray(OverlayStitchBlockIdName, points, index));
  // In the field data too, so that a block without points or cells is named
  // by its flat index, not its place among the blocks (a review). A new field
  // data: the shallow copy shares the caller's.
  vtkNew<vtkFieldData> field;
  field->ShallowCopy(block->GetFieldData());
  field->AddArray(IdArray(OverlayStitchBlockIdName, 1, index));
  copy->SetFieldData(field);
  // A block read from an unstructured grid carries its grid's ids already.
  if (!block->GetCellData()->GetArray(OverlayStitchSourceCellIdName))
  {
    copy->GetCellData()->AddArray(IdArray(OverlayStitchSourceCellIdName, cells, -1));
    copy->GetPointData()->AddArray(IdArray(OverlayStitchSourcePointIdName, points, -1));
  }
  return WithoutGhostCells(copy, true, "block " + std::to_string(flatIndex), notes);
}

/// In a parallel run, a shallow copy of a composite input's piece (one that
/// carries block ids) whose cells and points also carry the rank it came
/// from: a rank may hold only part of a block, and the ids in the block are
/// then those of its part. Other pieces are returned as they are.
vtkSmartPointer<vtkDataObject> WithRank(vtkDataObject* piece, int rank)
{
  vtkPolyData* polyData = vtkPolyData::SafeDownCast(piece);
  // A piece without cells may carry its block id in its field data only (the
  // transfer drops cell arrays of no tuples).
  if (!polyData ||
    (!polyData->GetCellData()->GetArray(OverlayStitchBlockIdName) &&
      FirstIdOf(polyData, OverlayStitchBlockIdName) < 0))
  {
    return piece;
  }
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(polyData);
  copy->GetCellData()->AddArray(
    IdArray(OverlayStitchRankName, polyData->GetNumberOfCells(), static_cast<vtkIdType>(rank)));
  copy->GetPointData()->AddArray(
    IdArray(OverlayStitchRankName, polyData->GetNumberOfPoints(), static_cast<vtkIdType>(rank)));
  vtkNew<vtkFieldData> field; // as the block id (WithBlockIds)
  field->ShallowCopy(polyData->GetFieldData());
  field->AddArray(IdArray(OverlayStitchRankName, 1, static_cast<vtkIdType>(rank)));
  copy->SetFieldData(field);
  return copy;
}
} // namespace

const char* const OverlayStitchBlockIdName = "vtkOverlayStitchBlockId";
const char* const OverlayStitchSourceCellIdName = "vtkOverlayStitchSourceCellId";
const char* const OverlayStitchSourcePointIdName = "vtkOverlayStitchSourcePointId";
const char* const OverlayStitchRankName = "vtkOverlayStitchRank";
const char* const OverlayStitchIgnoredCellsName = "vtkOverlayStitchIgnoredCells";
const char* const OverlayStitchMalformedName = "vtkOverlayStitchMalformed";
const char* const OverlayStitchFloatPointsName = "vtkOverlayStitchFloatPoints";

//------------------------------------------------------------------------------
vtkSmartPointer<vtkIdTypeArray> OverlayStitchIdArray(const char* name, vtkIdType n, vtkIdType value)
{
  return IdArray(name, n, value);
}

//------------------------------------------------------------------------------
bool OverlayStitchIsGhostCell(vtkDataArray* ghosts, vtkIdType c)
{
  return IsGhostCell(ghosts, c);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> OverlayStitchWithIgnoredCells(vtkPolyData* piece, vtkIdType cells)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(piece);
  vtkNew<vtkFieldData> field; // not the piece's own, which the copy shares
  field->ShallowCopy(piece->GetFieldData());
  field->AddArray(
    IdArray(OverlayStitchIgnoredCellsName, 1, OverlayStitchIgnoredCells(piece) + cells));
  copy->SetFieldData(field);
  return copy;
}

//------------------------------------------------------------------------------
vtkIdType OverlayStitchIgnoredCells(vtkDataObject* data)
{
  auto* count = data ? vtkIdTypeArray::SafeDownCast(
                         data->GetFieldData()->GetAbstractArray(OverlayStitchIgnoredCellsName))
                     : nullptr;
  return count && count->GetNumberOfTuples() == 1 ? count->GetValue(0) : 0;
}

//------------------------------------------------------------------------------
vtkIdType OverlayStitchSourceId(vtkDataSetAttributes* data, const char* idName, vtkIdType i)
{
  auto* ids = vtkIdTypeArray::SafeDownCast(data->GetAbstractArray(idName));
  return ids && i >= 0 && i < ids->GetNumberOfTuples() ? ids->GetValue(i) : vtkIdType(-1);
}

//------------------------------------------------------------------------------
std::string OverlayStitchSource(
  vtkDataSetAttributes* data, const char* idName, vtkIdType i, const char* kind)
{
  const vtkIdType block = OverlayStitchSourceId(data, OverlayStitchBlockIdName, i);
  const vtkIdType id = OverlayStitchSourceId(data, idName, i);
  if (id < 0)
  {
    return std::string();
  }
  const vtkIdType rank = OverlayStitchSourceId(data, OverlayStitchRankName, i);
  return std::string(kind) + " " + std::to_string(id) +
    (block >= 0 ? " of block " + std::to_string(block) : std::string(" of the input")) +
    (rank >= 0 ? " on rank " + std::to_string(rank) : std::string());
}

//------------------------------------------------------------------------------
void OverlayStitchToSourceIds(vtkDataSetAttributes* in, const char* sourceIdName,
  vtkIdTypeArray* ids, vtkDataSetAttributes* out)
{
  auto* block = vtkIdTypeArray::SafeDownCast(in->GetAbstractArray(OverlayStitchBlockIdName));
  auto* source = vtkIdTypeArray::SafeDownCast(in->GetAbstractArray(sourceIdName));
  if (!source)
  {
    return;
  }
  const vtkIdType n = ids->GetNumberOfTuples();
  vtkIdType* of = ids->GetPointer(0);
  if (block)
  {
    vtkNew<vtkIdTypeArray> blockIds;
    blockIds->SetName(Names::InputBlockId);
    blockIds->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      blockIds->SetValue(i, of[i] >= 0 ? block->GetValue(of[i]) : -1);
    }
    out->AddArray(blockIds);
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    of[i] = of[i] >= 0 ? source->GetValue(of[i]) : -1;
  }
}

//------------------------------------------------------------------------------
namespace
{
/// The point (or cell) arrays common to every piece of used, with the same
/// type and components, into fields; returns the pieces' points (or cells).
vtkIdType CommonFields(
  const std::vector<vtkPolyData*>& used, bool cells, vtkDataSetAttributes::FieldList& fields)
{
  vtkIdType total = 0;
  for (std::size_t u = 0; u < used.size(); ++u)
  {
    vtkDataSetAttributes* data = cells
      ? static_cast<vtkDataSetAttributes*>(used[u]->GetCellData())
      : static_cast<vtkDataSetAttributes*>(used[u]->GetPointData());
    if (u == 0)
    {
      fields.InitializeFieldList(data);
    }
    else
    {
      fields.IntersectFieldList(data);
    }
    total += cells ? used[u]->GetNumberOfCells() : used[u]->GetNumberOfPoints();
  }
  return total;
}

/// One combination of pieces (OverlayStitchCombinePieces), step by step;
/// single use: Combine() once.
class PieceCombination
{
public:
  PieceCombination(const std::vector<vtkSmartPointer<vtkDataObject>>& pieces, const char* pieceName)
    : Pieces(pieces)
    , PieceName(pieceName)
    , Invalid{ pieceName }
  {
    this->Holes->SetName(Names::HolePoints);
    this->Regions->SetName(Names::RegionAttributes);
    this->Regions->SetNumberOfComponents(4);
  }

  vtkSmartPointer<vtkPolyData> Combine(OverlayStitchGatherSummary* summary)
  {
    this->SelectPieces();
    if (!this->Used.empty())
    {
      this->MergePoints();
      this->MergeCells();
    }
    this->MergeFieldData();
    if (summary)
    {
      NoteArraysLeftOut(this->Used, this->Combined, summary->ArraysLeftOut);
      summary->NotCarried = this->Notes;
      summary->SharedPointsMerged = this->SharedPoints;
      summary->SharedCellsDropped = this->SharedCells;
      summary->HolePoints = static_cast<vtkIdType>(this->Seeds.size());
      summary->FloatPoints = this->AnyFloat;
      summary->CountsFromOne = this->CountsFromOne;
      summary->MalformedPieces = static_cast<vtkIdType>(this->Refused.size());
      summary->FirstMalformedPiece = this->FirstRefused;
      summary->InvalidCells = this->Invalid.Count;
      summary->FirstInvalidCell = this->Invalid.First;
    }
    return this->Combined;
  }

private:
  void SelectPieces();
  void MergePoints();
  void MergeCells();
  void MergeFieldData();
  void NoteRefused(vtkFieldData* field, std::size_t p);
  void CollectRegions(vtkFieldData* field, std::size_t p);
  /// How notes name piece p: by its block id where its cells carry one.
  std::string Label(std::size_t p) const
  {
    auto* polyData = vtkPolyData::SafeDownCast(this->Pieces[p]);
    return polyData ? PieceLabel(polyData, this->PieceName, p) : PieceLabel(this->PieceName, p);
  }
  void SetHoleSeeds();

  const std::vector<vtkSmartPointer<vtkDataObject>>& Pieces;
  const char* PieceName;
  vtkSmartPointer<vtkPolyData> Combined = vtkSmartPointer<vtkPolyData>::New();
  InvalidCells Invalid;
  std::vector<OverlayStitchNote> Notes;
  // The pieces with points (their arrays too short for them left out), and
  // their places among the pieces.
  std::vector<vtkPolyData*> Used;
  std::vector<std::size_t> UsedIndex;
  std::vector<vtkSmartPointer<vtkPolyData>> Trimmed;
  std::vector<std::vector<vtkIdType>> NewId; // per used piece, its points' ids in Combined
  vtkIdType SharedPoints = 0;
  vtkIdType SharedCells = 0;
  bool AnyFloat = false;
  bool AllFloat = false;
  bool CountsFromOne = false;
  std::vector<HoleSeed> Seeds;
  std::set<HoleSeed> SeenSeeds;
  bool AnyHoles = false;
  vtkNew<vtkDoubleArray> Holes;
  std::set<RegionSeed> SeenRegions;
  vtkNew<vtkDoubleArray> Regions;
  vtkIdType IgnoredCells = 0;
  // The refused pieces' block ids (-1 where not a block's), and how messages
  // name the first.
  std::vector<vtkIdType> Refused;
  std::string FirstRefused;
};

/// The pieces with points; a piece without points has no valid cell (its
/// cells are reported, not lost). Arrays too short for their piece are left
/// out (the copies would read past them), each noted.
void PieceCombination::SelectPieces()
{
  this->Trimmed.resize(this->Pieces.size());
  for (std::size_t p = 0; p < this->Pieces.size(); ++p)
  {
    vtkPolyData* polyData = vtkPolyData::SafeDownCast(this->Pieces[p]);
    if (polyData && HasShortArrays(polyData))
    {
      this->Trimmed[p] = vtkSmartPointer<vtkPolyData>::New();
      this->Trimmed[p]->ShallowCopy(polyData);
      DropShortArrays(this->Trimmed[p], PieceLabel(polyData, this->PieceName, p), &this->Notes);
      polyData = this->Trimmed[p];
    }
    if (polyData && polyData->GetNumberOfPoints() > 0)
    {
      this->Used.push_back(polyData);
      this->UsedIndex.push_back(p);
    }
    else if (polyData)
    {
      this->Invalid.NotePiecesCells(polyData, p);
    }
  }
}

/// Points: a point equal to one of an earlier piece is that point; point
/// arrays are those common to every piece.
void PieceCombination::MergePoints()
{
  const std::vector<vtkPolyData*>& used = this->Used;
  vtkDataSetAttributes::FieldList pointFields(static_cast<int>(used.size()));
  const vtkIdType totalPoints = CommonFields(used, false, pointFields);
  vtkPolyData* combined = this->Combined;
  std::vector<std::vector<vtkIdType>>& newId = this->NewId;
  vtkIdType& sharedPoints = this->SharedPoints;
  bool& anyFloat = this->AnyFloat;
  bool& allFloat = this->AllFloat;
  // Ids are first given in first-seen order, then, when every piece numbers
  // its points with global ids, in global id order: the input's order, which
  // the mesh may depend on (see the header).
  struct Source
  {
    std::size_t Piece;
    vtkIdType Id;
    double GlobalId;
  };
  std::vector<Source> sources;
  sources.reserve(static_cast<std::size_t>(totalPoints));
  bool globalIds = true;
  for (vtkPolyData* piece : used)
  {
    globalIds = globalIds && piece->GetPointData()->GetGlobalIds() &&
      piece->GetPointData()->GetGlobalIds()->GetNumberOfComponents() == 1;
  }
  std::unordered_map<PointKey, FirstSeen, PointKeyHash> firstPoint;
  firstPoint.reserve(static_cast<std::size_t>(totalPoints));
  newId.assign(used.size(), {});
  for (std::size_t u = 0; u < used.size(); ++u)
  {
    vtkPolyData* piece = used[u];
    vtkDataArray* ids = globalIds ? piece->GetPointData()->GetGlobalIds() : nullptr;
    newId[u].resize(static_cast<std::size_t>(piece->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < piece->GetNumberOfPoints(); ++i)
    {
      double x[3];
      piece->GetPoint(i, x);
      const PointKey key = { x[0] + 0.0, x[1] + 0.0, x[2] + 0.0 };
      const bool finite = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
      auto found = finite ? firstPoint.find(key) : firstPoint.end();
      if (found != firstPoint.end() && found->second.Piece != u)
      {
        newId[u][static_cast<std::size_t>(i)] = found->second.Id;
        ++sharedPoints;
        continue;
      }
      const auto id = static_cast<vtkIdType>(sources.size());
      sources.push_back({ u, i, ids ? ids->GetComponent(i, 0) : 0.0 });
      newId[u][static_cast<std::size_t>(i)] = id;
      if (finite && found == firstPoint.end())
      {
        firstPoint.emplace(key, FirstSeen{ u, id });
      }
    }
  }
  std::vector<vtkIdType> order(sources.size());
  std::iota(order.begin(), order.end(), vtkIdType(0));
  if (globalIds)
  {
    std::stable_sort(order.begin(), order.end(), [&sources](vtkIdType a, vtkIdType b) {
      return sources[static_cast<std::size_t>(a)].GlobalId <
        sources[static_cast<std::size_t>(b)].GlobalId;
    });
  }
  std::vector<vtkIdType> finalId(sources.size());
  vtkNew<vtkPoints> points;
  // Float points stay float where every piece's are (exactly): the mesher
  // allows their rounding off a tilted plane (a review: a Slice's output
  // meshed serially, not in parallel); any float piece is noted.
  allFloat = true;
  for (vtkPolyData* piece : used)
  {
    const bool floats = piece->GetPoints() && piece->GetPoints()->GetDataType() == VTK_FLOAT;
    anyFloat = anyFloat || floats;
    allFloat = allFloat && floats;
  }
  points->SetDataType(allFloat ? VTK_FLOAT : VTK_DOUBLE);
  points->SetNumberOfPoints(static_cast<vtkIdType>(sources.size()));
  // Each point and cell is copied once, so global ids keep their meaning
  // (vtkDataSetAttributes leaves them out by default).
  vtkPointData* outPointData = combined->GetPointData();
  outPointData->CopyGlobalIdsOn();
  outPointData->CopyAllocate(pointFields, static_cast<vtkIdType>(sources.size()));
  for (std::size_t k = 0; k < order.size(); ++k)
  {
    const Source& source = sources[static_cast<std::size_t>(order[k])];
    finalId[static_cast<std::size_t>(order[k])] = static_cast<vtkIdType>(k);
    double x[3];
    used[source.Piece]->GetPoint(source.Id, x);
    points->SetPoint(static_cast<vtkIdType>(k), x);
    outPointData->CopyData(pointFields, used[source.Piece]->GetPointData(),
      static_cast<int>(source.Piece), source.Id, static_cast<vtkIdType>(k));
  }
  for (auto& pieceIds : newId)
  {
    for (vtkIdType& id : pieceIds)
    {
      id = finalId[static_cast<std::size_t>(id)];
    }
  }
  combined->SetPoints(points);
}

/// Cells, kind by kind (verts, lines, polys, strips: vtkPolyData's cell id
/// order), each piece in turn; a cell equal to one of an earlier piece is
/// that cell. Cell arrays are those common to every piece.
void PieceCombination::MergeCells()
{
  const std::vector<vtkPolyData*>& used = this->Used;
  const std::vector<std::size_t>& usedIndex = this->UsedIndex;
  vtkDataSetAttributes::FieldList cellFields(static_cast<int>(used.size()));
  const vtkIdType totalCells = CommonFields(used, true, cellFields);
  vtkPolyData* combined = this->Combined;
  const std::vector<std::vector<vtkIdType>>& newId = this->NewId;
  vtkIdType& sharedCells = this->SharedCells;
  InvalidCells& invalid = this->Invalid;
  vtkCellData* outCellData = combined->GetCellData();
  outCellData->CopyGlobalIdsOn();
  outCellData->CopyAllocate(cellFields, totalCells);
  vtkIdType nextCellId = 0;
  for (int kind = 0; kind < 4; ++kind)
  {
    vtkNew<vtkCellArray> cells;
    std::unordered_map<CellKey, FirstSeen, CellKeyHash> firstCell;
    std::vector<vtkIdType> ids;
    CellKey key;
    CellKey reversed;
    for (std::size_t u = 0; u < used.size(); ++u)
    {
      vtkPolyData* piece = used[u];
      // Cell ids of this kind in the piece start after those of the earlier kinds.
      vtkIdType pieceCellId = 0;
      for (int earlier = 0; earlier < kind; ++earlier)
      {
        pieceCellId += CellsOfKind(piece, earlier)->GetNumberOfCells();
      }
      vtkCellArray* pieceCells = CellsOfKind(piece, kind);
      auto it = vtk::TakeSmartPointer(pieceCells->NewIterator());
      for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++pieceCellId)
      {
        vtkIdType n;
        const vtkIdType* pieceIds;
        it->GetCurrentCell(n, pieceIds);
        ids.resize(static_cast<std::size_t>(n));
        const vtkIdType pointsInPiece = static_cast<vtkIdType>(newId[u].size());
        for (vtkIdType k = 0; k < n; ++k)
        {
          const vtkIdType id = pieceIds[k];
          ids[static_cast<std::size_t>(k)] =
            (id >= 0 && id < pointsInPiece) ? newId[u][static_cast<std::size_t>(id)] : -1;
        }
        // An invalid id stays invalid (-1); which one it was is said here.
        invalid.Note(n, pieceIds, pointsInPiece, pieceCellId, usedIndex[u], piece);
        key.assign(ids.begin(), ids.end());
        reversed.assign(ids.rbegin(), ids.rend());
        if (reversed < key)
        {
          key.swap(reversed);
        }
        auto found = firstCell.find(key);
        if (found != firstCell.end() && found->second.Piece != u)
        {
          ++sharedCells;
          continue;
        }
        cells->InsertNextCell(n, ids.data());
        outCellData->CopyData(
          cellFields, piece->GetCellData(), static_cast<int>(u), pieceCellId, nextCellId);
        if (found == firstCell.end())
        {
          firstCell.emplace(key, FirstSeen{ u, nextCellId });
        }
        ++nextCellId;
      }
    }
    if (cells->GetNumberOfCells() > 0)
    {
      SetCellsOfKind(combined, kind, cells);
    }
  }
}

/// Field data: the first array of each name, except the hole and region
/// seeds, which are gathered from every piece (empty pieces included) and
/// deduplicated (a review: a second block's region seeds were dropped). The
/// seeds' arrays take their places among the others when first seen, and
/// their values at the end: the order of a serial run's input. The marks
/// (ignored cells, float points, refused pieces) are summed up.
void PieceCombination::MergeFieldData()
{
  vtkFieldData* outField = this->Combined->GetFieldData();
  for (std::size_t p = 0; p < this->Pieces.size(); ++p)
  {
    vtkDataObject* piece = this->Pieces[p];
    vtkFieldData* field = piece ? piece->GetFieldData() : nullptr;
    if (!field)
    {
      continue;
    }
    this->IgnoredCells += OverlayStitchIgnoredCells(piece);
    this->AnyFloat = this->AnyFloat || field->GetArray(OverlayStitchFloatPointsName);
    this->CountsFromOne = this->CountsFromOne || OverlayStitchCountsFromOne(field);
    this->NoteRefused(field, p);
    if (vtkAbstractArray* array = field->GetAbstractArray(Names::HolePoints))
    {
      this->AnyHoles = true;
      if (!CollectHolePoints(field, this->Seeds, this->SeenSeeds))
      {
        this->Notes.push_back({ { "field", Names::HolePoints },
          "The field data array HolePoints of " + this->Label(p) + " has " +
            std::to_string(array->GetNumberOfComponents()) +
            " components (2 or 3 expected: x, y and perhaps z): ignored." });
      }
    }
    this->CollectRegions(field, p);
    for (int a = 0; a < field->GetNumberOfArrays(); ++a)
    {
      vtkAbstractArray* array = field->GetAbstractArray(a);
      const char* name = array ? array->GetName() : nullptr;
      if (name && !outField->GetAbstractArray(name) && !OverlayStitchIsInternalName(name))
      {
        outField->AddArray(std::strcmp(name, Names::HolePoints) == 0 ? this->Holes.Get()
            : std::strcmp(name, Names::RegionAttributes) == 0        ? this->Regions.Get()
                                                                     : array);
      }
    }
  }
  if (this->IgnoredCells > 0)
  {
    outField->AddArray(IdArray(OverlayStitchIgnoredCellsName, 1, this->IgnoredCells)); // the sum
  }
  if (this->AnyFloat && !this->AllFloat)
  {
    // Float points among double ones: said to the rank that combines this
    // combination with others (the point type cannot say it).
    outField->AddArray(IdArray(OverlayStitchFloatPointsName, 1, 1));
  }
  if (!this->Refused.empty())
  {
    auto marks =
      IdArray(OverlayStitchMalformedName, static_cast<vtkIdType>(this->Refused.size()), -1);
    std::copy(this->Refused.begin(), this->Refused.end(), marks->GetPointer(0));
    outField->AddArray(marks);
  }
  if (this->AnyHoles)
  {
    this->SetHoleSeeds();
  }
}

/// The region seeds of piece p's field data appended to Regions; an array of
/// another shape is noted and left out, as a serial run warns and ignores it.
void PieceCombination::CollectRegions(vtkFieldData* field, std::size_t p)
{
  vtkAbstractArray* array = field->GetAbstractArray(Names::RegionAttributes);
  if (!array)
  {
    return;
  }
  std::vector<RegionSeed> seeds;
  if (!CollectRegionSeeds(field, seeds, this->SeenRegions))
  {
    this->Notes.push_back({ { "field", Names::RegionAttributes },
      "The field data array RegionAttributes of " + this->Label(p) + " has " +
        std::to_string(array->GetNumberOfComponents()) +
        " components (4 expected: x, y, attribute, maximum area): ignored." });
    return;
  }
  for (const RegionSeed& seed : seeds)
  {
    this->Regions->InsertNextTypedTuple(seed.data());
  }
}

/// The refused pieces among the marks of a piece's field data.
void PieceCombination::NoteRefused(vtkFieldData* field, std::size_t p)
{
  vtkDataArray* marks = field->GetArray(OverlayStitchMalformedName);
  if (!marks)
  {
    return;
  }
  // A block's own id is in its field data alone (a rank's combination of
  // blocks carries each refused one's in its marks: its cells' ids are those
  // of the blocks that were not refused, a review).
  auto* ownIds = vtkIdTypeArray::SafeDownCast(field->GetAbstractArray(OverlayStitchBlockIdName));
  const vtkIdType own = ownIds && ownIds->GetNumberOfTuples() > 0 ? ownIds->GetValue(0) : -1;
  const bool ranks = std::strcmp(this->PieceName, "rank") == 0;
  for (vtkIdType m = 0; m < marks->GetNumberOfTuples(); ++m)
  {
    const auto mark = static_cast<vtkIdType>(marks->GetComponent(m, 0));
    const vtkIdType block = mark >= 0 ? mark : own;
    this->Refused.push_back(block);
    if (this->FirstRefused.empty())
    {
      this->FirstRefused = block < 0 ? "the piece of " + PieceLabel(this->PieceName, p)
        : ranks ? "block " + std::to_string(block) + " on rank " + std::to_string(p)
                : "block " + std::to_string(block);
    }
  }
}

/// The hole seeds gathered, into the combination's HolePoints. (x, y) seeds
/// stay so, to be lifted onto the input's plane along z, as in a serial run
/// (a review: taken as (x, y, 0), they were projected across a tilted plane);
/// beside (x, y, z) seeds they can only be taken at z 0.
void PieceCombination::SetHoleSeeds()
{
  std::vector<HoleSeed>& seeds = this->Seeds;
  const auto xy = std::count_if(seeds.begin(), seeds.end(), [](const HoleSeed& h) { return h.XY; });
  const int components = xy > 0 && xy == static_cast<std::ptrdiff_t>(seeds.size()) ? 2 : 3;
  if (xy > 0 && components == 3)
  {
    this->Notes.push_back({ { "field", Names::HolePoints },
      "The field data arrays HolePoints give " + std::to_string(xy) +
        " seed(s) as (x, y) and others as (x, y, z): the (x, y) ones are taken at z = 0." });
    // Taken so, an (x, y) seed may repeat another piece's (x, y, 0).
    std::set<std::array<double, 3>> at;
    seeds.erase(std::remove_if(seeds.begin(), seeds.end(),
                  [&at](const HoleSeed& h) { return IsFinite(h.At) && !at.insert(h.At).second; }),
      seeds.end());
  }
  this->Holes->SetNumberOfComponents(components);
  this->Holes->SetNumberOfTuples(static_cast<vtkIdType>(seeds.size()));
  for (std::size_t s = 0; s < seeds.size(); ++s)
  {
    this->Holes->SetTypedTuple(static_cast<vtkIdType>(s), seeds[s].At.data());
  }
}
} // namespace

//------------------------------------------------------------------------------
bool OverlayStitchCountsFromOne(vtkFieldData* field)
{
  vtkDataArray* first = field ? field->GetArray(Names::FileFirstIndex) : nullptr;
  return first && first->GetNumberOfTuples() == 1 && first->GetComponent(0, 0) == 1.0;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> OverlayStitchCombinePieces(
  const std::vector<vtkSmartPointer<vtkDataObject>>& pieces, OverlayStitchGatherSummary* summary,
  const char* pieceName)
{
  return PieceCombination(pieces, pieceName).Combine(summary);
}

//------------------------------------------------------------------------------
bool OverlayStitchGatherInput(vtkMultiProcessController* controller, vtkPolyData* input,
  vtkSmartPointer<vtkPolyData>& gathered, OverlayStitchGatherSummary* summary)
{
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  // This rank's piece, without the cells that are ghost copies of another
  // piece's: in a serial run too, so that it meshes what a parallel one does.
  std::vector<OverlayStitchNote> notes;
  vtkSmartPointer<vtkPolyData> local = input
    ? WithoutGhostCells(input, ranks <= 1,
        ranks > 1 ? "the piece of rank " + std::to_string(controller->GetLocalProcessId()) : "",
        notes)
    : vtkSmartPointer<vtkPolyData>::New();
  if (ranks <= 1)
  {
    gathered = input ? local : nullptr;
    if (summary)
    {
      *summary = OverlayStitchGatherSummary();
      summary->CellsPerRank.assign(1, local->GetNumberOfCells());
      // Combining pieces finds cells naming missing points; a single input is
      // checked here, so that such a cell is refused in every case alike.
      // The input's own cell ids, ghost cells skipped.
      InvalidCells invalid{ nullptr };
      invalid.NoteCells(input ? input : local.Get(), 0);
      summary->InvalidCells = invalid.Count;
      summary->FirstInvalidCell = invalid.First;
      summary->NotCarried = notes;
    }
    return true;
  }

  // The one collective call: every rank reaches it, whatever its input.
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  const int status = controller->Gather(OverlayStitchPieceToSend(local), pieces, 0);
  if (controller->GetLocalProcessId() != 0)
  {
    return false;
  }

  if (summary)
  {
    *summary = OverlayStitchGatherSummary();
    summary->Ranks = ranks;
    for (const auto& piece : pieces)
    {
      vtkPolyData* polyData = vtkPolyData::SafeDownCast(piece);
      summary->CellsPerRank.push_back(polyData ? polyData->GetNumberOfCells() : 0);
    }
  }
  if (!status || static_cast<int>(pieces.size()) != ranks)
  {
    gathered = nullptr;
    return true;
  }
  for (std::size_t rank = 0; rank < pieces.size(); ++rank)
  {
    pieces[rank] = WithRank(pieces[rank], static_cast<int>(rank));
  }
  gathered = OverlayStitchCombinePieces(pieces, summary, "rank");
  if (summary)
  {
    summary->NotCarried.insert(summary->NotCarried.begin(), notes.begin(), notes.end());
  }
  return true;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> OverlayStitchPieceToSend(vtkPolyData* piece)
{
  vtkFieldData* fields = piece->GetFieldData();
  bool empty = false;
  for (int a = 0; fields && a < fields->GetNumberOfArrays(); ++a)
  {
    empty = empty || fields->GetAbstractArray(a)->GetNumberOfTuples() == 0;
  }
  if (!empty)
  {
    return piece;
  }
  auto sent = vtkSmartPointer<vtkPolyData>::New();
  sent->ShallowCopy(piece);
  vtkNew<vtkFieldData> kept;
  for (int a = 0; a < fields->GetNumberOfArrays(); ++a)
  {
    if (fields->GetAbstractArray(a)->GetNumberOfTuples() > 0)
    {
      kept->AddArray(fields->GetAbstractArray(a));
    }
  }
  sent->SetFieldData(kept);
  return sent;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> OverlayStitchCombineBlocks(vtkCompositeDataSet* input,
  std::vector<std::string>& ignored, OverlayStitchGatherSummary* summary)
{
  if (summary)
  {
    *summary = OverlayStitchGatherSummary();
  }
  ignored.clear();
  std::vector<OverlayStitchNote> notes;
  std::vector<vtkSmartPointer<vtkDataObject>> blocks;
  auto it = vtkSmartPointer<vtkCompositeDataIterator>::Take(input->NewIterator());
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    vtkDataObject* leaf = it->GetCurrentDataObject();
    if (auto* polyData = vtkPolyData::SafeDownCast(leaf))
    {
      blocks.emplace_back(WithBlockIds(polyData, it->GetCurrentFlatIndex(), notes));
    }
    else if (auto* grid = vtkUnstructuredGrid::SafeDownCast(leaf))
    {
      const std::string where = "block " + std::to_string(it->GetCurrentFlatIndex());
      vtkIdType ignoredCells = 0;
      vtkSmartPointer<vtkPolyData> read =
        OverlayStitchPolyDataOf(grid, true, where, notes, ignoredCells);
      if (ignoredCells > 0)
      {
        read = OverlayStitchWithIgnoredCells(read, ignoredCells); // summed when combined
      }
      blocks.emplace_back(WithBlockIds(read, it->GetCurrentFlatIndex(), notes));
    }
    else if (vtkDataSet* other = vtkDataSet::SafeDownCast(leaf))
    {
      if (other->GetNumberOfPoints() > 0)
      {
        ignored.emplace_back(other->GetClassName());
      }
    }
  }
  if (blocks.size() == 1)
  {
    vtkPolyData* only = vtkPolyData::SafeDownCast(blocks.front()); // already a copy
    if (summary)
    {
      summary->NotCarried = notes;
      summary->CountsFromOne = only && OverlayStitchCountsFromOne(only->GetFieldData());
    }
    return only;
  }
  auto combined = OverlayStitchCombinePieces(blocks, summary, "block");
  if (summary)
  {
    summary->NotCarried.insert(summary->NotCarried.begin(), notes.begin(), notes.end());
  }
  return combined;
}
