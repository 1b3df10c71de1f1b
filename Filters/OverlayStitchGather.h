// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// Internal to OverlayStitch::Filters (not installed): gathers a distributed
// input on rank 0 so that vtkOverlayStitchMesher meshes the whole PSLG at once.
//
// Under pvbatch or pvserver with several MPI ranks, each rank's pipeline holds
// one piece of the line data. Meshing each piece separately would give seams
// and missing segments, so the mesher gathers every piece on rank 0, meshes
// there, and leaves the outputs of the other ranks empty.
//
// The pieces are combined without inventing repairs the serial run would not
// report: a point of one piece that has exactly the coordinates of a point of
// an EARLIER piece is the same point (pieces share the points on their common
// boundary), and a cell of one piece equal to a cell of an earlier piece (same
// kind, same merged point ids, either direction) is the same cell (a ghost
// copy, or a piece read by every rank). Duplicates inside one piece are kept:
// they are the user's, and the core merges and reports them as in a serial
// run. Cells flagged as ghosts are removed before gathering (with VTK's
// RemoveGhostCells choosing the cells; the points that no cell used are kept,
// and every point kept keeps its order). Point
// and cell arrays common to all non-empty pieces are kept; field data arrays
// are taken from the first piece that has each name, except "HolePoints" (2
// or 3 components) and "RegionAttributes" (3 or 4), whose tuples are
// collected from every piece and deduplicated.
//
// Point order: the mesh the core makes can depend on the order of the input
// points (not only on the point set), and a distribution loses the input's
// order. When every piece carries global point ids (the point data's GlobalIds
// attribute, e.g. the input's point index), the combined points are put back in
// global id order, and a parallel run meshes exactly the serial run's input;
// otherwise they come in rank order, each piece's in its own order.
#ifndef OverlayStitchGather_h
#define OverlayStitchGather_h

#include "vtkSmartPointer.h" // for vtkSmartPointer
#include "vtkType.h"         // for vtkIdType

#include <string>
#include <vector>

class vtkCompositeDataSet;
class vtkDataArray;
class vtkDataObject;
class vtkDataSetAttributes;
class vtkFieldData;
class vtkIdTypeArray;
class vtkMultiProcessController;
class vtkPolyData;

/// An input array, point or cell data, by its kind ("point" or "cell") and
/// name ("(unnamed)" for an array without one).
struct OverlayStitchArrayName
{
  std::string Kind;
  std::string Name;
  bool operator==(const OverlayStitchArrayName& other) const
  {
    return this->Kind == other.Kind && this->Name == other.Name;
  }
  bool operator<(const OverlayStitchArrayName& other) const
  {
    return this->Kind != other.Kind ? this->Kind < other.Kind : this->Name < other.Name;
  }
};

/// A sentence for the user about input left out of a piece or block, and the
/// array it is about (Kind empty: about no array the filter may carry, so
/// always worth reporting).
struct OverlayStitchNote
{
  OverlayStitchArrayName Array;
  std::string Text;
};

/// What the gather did, for tests and diagnostics (meaningful on rank 0).
struct OverlayStitchGatherSummary
{
  int Ranks = 1;                       ///< processes taking part
  std::vector<vtkIdType> CellsPerRank; ///< input cells (ghosts removed) per rank
  vtkIdType SharedPointsMerged = 0;    ///< points found again in a later piece
  vtkIdType SharedCellsDropped = 0;    ///< cells found again in a later piece
  vtkIdType HolePoints = 0;            ///< distinct hole seeds after the gather
  /// Some piece has float points (rounded to 2^-24 of themselves): the
  /// combination's are float only where every piece's are.
  bool FloatPoints = false;
  /// Some piece was read from a .poly or .node file that counts from 1 (its
  /// field data FileFirstIndex): messages that number a block's cells from 0
  /// say so.
  bool CountsFromOne = false;
  /// Cells naming a point their own piece does not have: after combining, such
  /// an id is -1 and says nothing, so the first is described here ("cell 3 of
  /// rank 1 refers to point 57, ..."), for the caller to report.
  vtkIdType InvalidCells = 0;
  std::string FirstInvalidCell;
  /// Pieces with malformed cell arrays (OverlayStitchMalformedName), and the
  /// first of them, as messages name it ("the piece of rank 1", "block 2 on rank 1").
  vtkIdType MalformedPieces = 0;
  std::string FirstMalformedPiece;
  /// Point and cell arrays of some pieces but not all: the combined input has
  /// only those common to every piece.
  std::vector<OverlayStitchArrayName> ArraysLeftOut;
  /// Arrays left out of a piece or block for other reasons (fewer tuples than
  /// its points or cells; a ghost array VTK cannot use), one sentence each.
  std::vector<OverlayStitchNote> NotCarried;
};

/// Whether field data says its points and cells were read from a .poly or
/// .node file that counts from 1 (the reader's FileFirstIndex).
bool OverlayStitchCountsFromOne(vtkFieldData* field);

/// Collective over `controller`: every rank must call it once, in the same
/// order relative to the controller's other collective calls, whatever its
/// input (a null input counts as an empty piece). Returns true on the rank
/// that must mesh, with `gathered` set to the whole input (or to null if the
/// communication failed), and false on every other rank. With no controller or
/// a single process, `gathered` is `input` itself (no copy; a shallow copy
/// without its ghost cells if it has any, as a parallel run drops them), the
/// summary notes its cells that name missing points, and it returns true.
bool OverlayStitchGatherInput(vtkMultiProcessController* controller, vtkPolyData* input,
  vtkSmartPointer<vtkPolyData>& gathered, OverlayStitchGatherSummary* summary = nullptr);

/// The piece a rank sends to rank 0: piece itself, or a shallow copy without
/// its field arrays of no tuples. VTK's legacy encoding, which the gather
/// uses, loses every field array after one with no tuples (the .poly reader's
/// HolePoints comes first, empty without holes: RegionAttributes and
/// FileFirstIndex were lost); an empty array holds nothing the combination
/// needs. Exposed for tests.
vtkSmartPointer<vtkPolyData> OverlayStitchPieceToSend(vtkPolyData* piece);

/// The combination done on rank 0, exposed for tests: `pieces` in rank order
/// (null or non-polydata entries count as empty pieces). `pieceName` names a
/// piece in the summary's FirstInvalidCell ("rank", "block") with its index in
/// pieces, unless the piece's cells carry block ids (below): then a cell is
/// named by its block and its id there.
vtkSmartPointer<vtkPolyData> OverlayStitchCombinePieces(
  const std::vector<vtkSmartPointer<vtkDataObject>>& pieces,
  OverlayStitchGatherSummary* summary = nullptr, const char* pieceName = "piece");

/// The arrays OverlayStitchCombineBlocks gives every block's cells and points:
/// the block's flat index in the composite (cell and point data), and the
/// cell's or point's id in its block. They pass through the combination and
/// the gather as any array (a point shared by blocks keeps the first block's),
/// so that the outputs and the messages can name the user's cells and points
/// (InputBlockId, InputCellId); the filter does not carry them as input arrays.
/// A single dataset meshed in a serial run gets the id arrays (not the block
/// index) when its ghost cells are removed, which renumbers its cells and points.
extern const char* const OverlayStitchBlockIdName;
extern const char* const OverlayStitchSourceCellIdName;
extern const char* const OverlayStitchSourcePointIdName;
/// An id array of n tuples: value everywhere, or (value < 0) each tuple's own index.
vtkSmartPointer<vtkIdTypeArray> OverlayStitchIdArray(
  const char* name, vtkIdType n, vtkIdType value);

/// Whether cell c is one that vtkPolyData::RemoveGhostCells() removes, by its
/// flags in ghosts (the ghost array; null: none is).
bool OverlayStitchIsGhostCell(vtkDataArray* ghosts, vtkIdType c);

/// A field data count of the input cells left out before the gather (an
/// unstructured grid's cells of other types): combining pieces sums it.
extern const char* const OverlayStitchIgnoredCellsName;

/// A field data count of the malformed cell arrays a piece had (said on the
/// rank that holds it, OverlayStitchCellArrays.h): combining pieces sums it,
/// and the rank that meshes refuses the input.
extern const char* const OverlayStitchMalformedName;

/// A field data mark of a combination whose points are double but came in
/// part from float ones: combining it again keeps FloatPoints.
extern const char* const OverlayStitchFloatPointsName;

/// A shallow copy of piece whose field data counts `cells` more left out.
vtkSmartPointer<vtkPolyData> OverlayStitchWithIgnoredCells(vtkPolyData* piece, vtkIdType cells);

/// The count OverlayStitchWithIgnoredCells put in data's field data, or 0.
vtkIdType OverlayStitchIgnoredCells(vtkDataObject* data);

/// In a parallel run, the rank each such cell and point came from (on the
/// pieces that carry block ids): the ids in a block are those of the rank's
/// part of it.
extern const char* const OverlayStitchRankName;

/// Item i's value in data's id array idName (one of those above), or -1
/// without one.
vtkIdType OverlayStitchSourceId(vtkDataSetAttributes* data, const char* idName, vtkIdType i);

/// Where item i (a cell or point of data, the combined input's cell or point
/// data) comes from, as "point 3 of block 2" (kind "point", idName the id
/// array of that kind), with " on rank 1" in a parallel run, or "point 3 of
/// the input" for a single dataset that carries ids; empty for an item
/// without ids (a single dataset without ghost cells, or a rank's piece of one).
std::string OverlayStitchSource(
  vtkDataSetAttributes* data, const char* idName, vtkIdType i, const char* kind);

/// For an input whose cells or points carry their ids in the dataset the user
/// gave (the arrays above, `sourceIdName` of in): ids, per output cell or
/// point the meshed input's item (or -1), become those ids, and for a
/// composite out gets "InputBlockId" (the flat index, -1 where ids has -1).
/// Without such ids, nothing changes.
void OverlayStitchToSourceIds(vtkDataSetAttributes* in, const char* sourceIdName,
  vtkIdTypeArray* ids, vtkDataSetAttributes* out);

/// A composite input (multiblock, partitioned) is one graph: its polydata
/// leaves are combined as the ranks' pieces are (in the iteration order of the
/// blocks; points equal to a point of an earlier block are that point, cells
/// equal to one of an earlier block are dropped; each block's ghost cells are
/// removed first, so that a ghost copy never stands in for the cell it
/// copies). A single polydata leaf is
/// returned as a shallow copy, so that it meshes as it would on its own. Each
/// block's cells and points get the arrays above.
/// Unstructured grid leaves are read as polydata (OverlayStitchUnstructured.h),
/// their cells keeping their ids in the grid, and the cells of other types
/// they leave out noted in the summary and counted in the field data
/// (OverlayStitchIgnoredCells). `ignored` receives the class names of
/// non-empty leaves of other types, one entry per leaf; `summary`, if given,
/// what the combination did.
vtkSmartPointer<vtkPolyData> OverlayStitchCombineBlocks(vtkCompositeDataSet* input,
  std::vector<std::string>& ignored, OverlayStitchGatherSummary* summary = nullptr);

#endif
