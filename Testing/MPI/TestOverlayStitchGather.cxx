// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// Unit test of the combination done on rank 0 after the gather (no MPI needed):
// points and cells shared between pieces are merged, duplicates inside one piece
// are kept, arrays follow their points and cells, hole seeds come from every piece.
#include "OverlayStitchGather.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCharArray.h"
#include "vtkCommunicator.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <array>
#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace
{

int Failures = 0;

void Check(bool condition, const std::string& what)
{
  std::cout << (condition ? "  ok    " : "  FAIL  ") << what << "\n";
  if (!condition)
  {
    ++Failures;
  }
}

/// A piece: points (x, y), 2-point lines, vertex cells, a point marker per point,
/// a segment marker per cell, hole seeds.
vtkSmartPointer<vtkPolyData> MakePiece(const std::vector<std::array<double, 2>>& points,
  const std::vector<std::pair<vtkIdType, vtkIdType>>& lines, const std::vector<vtkIdType>& verts,
  const std::vector<int>& pointMarkers, const std::vector<int>& cellMarkers,
  const std::vector<std::array<double, 2>>& holes)
{
  auto piece = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  for (const auto& p : points)
  {
    pts->InsertNextPoint(p[0], p[1], 0.0);
  }
  piece->SetPoints(pts);
  vtkNew<vtkCellArray> vertCells;
  for (vtkIdType v : verts)
  {
    vertCells->InsertNextCell(1, &v);
  }
  vtkNew<vtkCellArray> lineCells;
  for (const auto& l : lines)
  {
    const vtkIdType ids[2] = { l.first, l.second };
    lineCells->InsertNextCell(2, ids);
  }
  piece->SetVerts(vertCells);
  piece->SetLines(lineCells);
  vtkNew<vtkIntArray> pointMarker;
  pointMarker->SetName("PointMarker");
  for (int m : pointMarkers)
  {
    pointMarker->InsertNextValue(m);
  }
  piece->GetPointData()->AddArray(pointMarker);
  vtkNew<vtkIntArray> cellMarker;
  cellMarker->SetName("SegmentMarker");
  for (int m : cellMarkers)
  {
    cellMarker->InsertNextValue(m);
  }
  piece->GetCellData()->AddArray(cellMarker);
  vtkNew<vtkDoubleArray> seeds;
  seeds->SetName("HolePoints");
  seeds->SetNumberOfComponents(3);
  for (const auto& h : holes)
  {
    seeds->InsertNextTuple3(h[0], h[1], 0.0);
  }
  piece->GetFieldData()->AddArray(seeds);
  return piece;
}

/// The mark of a refused piece, as a rank makes it (its block id unknown).
vtkSmartPointer<vtkIdTypeArray> RefusedMark()
{
  auto mark = vtkSmartPointer<vtkIdTypeArray>::New();
  mark->SetName(OverlayStitchMalformedName);
  mark->InsertNextValue(-1);
  return mark;
}

std::array<double, 2> PointOf(vtkPolyData* data, vtkIdType id)
{
  double x[3];
  data->GetPoint(id, x);
  return { x[0], x[1] };
}

/// Found by a review: a piece's field data crossed the gather (VTK's legacy
/// encoding) without any array after an empty one, and the .poly reader's
/// HolePoints, empty without holes, comes first.
void TestPieceToSend()
{
  std::cout << "field data through the gather's encoding\n";
  vtkNew<vtkPolyData> piece;
  vtkNew<vtkDoubleArray> holes;
  holes->SetName("HolePoints");
  holes->SetNumberOfComponents(3);
  vtkNew<vtkIntArray> first;
  first->SetName("FileFirstIndex");
  first->InsertNextValue(1);
  vtkNew<vtkDoubleArray> regions;
  regions->SetName("RegionAttributes");
  regions->SetNumberOfComponents(4);
  regions->InsertNextTuple4(1, 1, 7, 0.5);
  for (vtkAbstractArray* a :
    std::initializer_list<vtkAbstractArray*>{ holes.Get(), first.Get(), regions.Get() })
  {
    piece->GetFieldData()->AddArray(a);
  }
  auto across = [](vtkPolyData* sent) {
    vtkNew<vtkCharArray> buffer;
    vtkCommunicator::MarshalDataObject(sent, buffer);
    auto received = vtkSmartPointer<vtkPolyData>::New();
    vtkCommunicator::UnMarshalDataObject(buffer, received);
    return received;
  };
  const bool lost = across(piece)->GetFieldData()->GetArray("RegionAttributes") == nullptr;
  std::cout << "  (VTK's encoding itself " << (lost ? "loses" : "keeps")
            << " the arrays after an empty one)\n";
  vtkSmartPointer<vtkPolyData> sent = OverlayStitchPieceToSend(piece);
  Check(sent.Get() != piece.Get() && piece->GetFieldData()->GetNumberOfArrays() == 3,
    "a copy is sent, the piece itself is left as it was");
  vtkSmartPointer<vtkPolyData> received = across(sent);
  vtkDataArray* r = received->GetFieldData()->GetArray("RegionAttributes");
  vtkDataArray* f = received->GetFieldData()->GetArray("FileFirstIndex");
  Check(r && r->GetNumberOfTuples() == 1 && r->GetComponent(0, 3) == 0.5 && f &&
      f->GetComponent(0, 0) == 1,
    "RegionAttributes and FileFirstIndex arrive");
  Check(!received->GetFieldData()->GetArray("HolePoints"), "the empty HolePoints is not sent");
  vtkNew<vtkPolyData> plain;
  plain->GetFieldData()->AddArray(first);
  Check(OverlayStitchPieceToSend(plain).Get() == plain.Get(), "without empty arrays: the piece");
}

} // namespace

int main()
{
  // Piece 0: a corner (0,0) - (1,0) - (1,1), one hole seed, an extra field array.
  auto piece0 = MakePiece({ { 0, 0 }, { 1, 0 }, { 1, 1 } }, { { 0, 1 }, { 1, 2 } }, {},
    { 10, 11, 12 }, { 100, 101 }, { { 0.5, 0.25 } });
  vtkNew<vtkIntArray> other;
  other->SetName("Other");
  other->InsertNextValue(7);
  piece0->GetFieldData()->AddArray(other);
  // Piece 1 shares (1,1), (0,0), (1,0) with piece 0 (ids 0, 2, 4), holds the point
  // (0,1) twice (ids 1 and 3: the user's duplicate, kept), repeats piece 0's
  // segment (1,0)-(1,1) reversed (dropped), and marks (0,1) copy 3 with a vertex cell.
  // Its hole seeds repeat piece 0's and add one; -0.0 is the same as 0.0.
  auto piece1 = MakePiece({ { 1, 1 }, { 0, 1 }, { -0.0, 0 }, { 0, 1 }, { 1, 0 } },
    { { 0, 1 }, { 1, 2 }, { 0, 4 } }, { 3 }, { 20, 21, 22, 23, 24 }, { 200, 201, 202, 203 },
    { { 0.5, 0.25 }, { 0.25, 0.5 } });
  // Piece 2 is empty (no points) but carries a hole seed; piece 3 is missing.
  auto piece2 = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkDoubleArray> seeds2;
  seeds2->SetName("HolePoints");
  seeds2->SetNumberOfComponents(3);
  seeds2->InsertNextTuple3(0.75, 0.5, 0.0);
  piece2->GetFieldData()->AddArray(seeds2);

  std::vector<vtkSmartPointer<vtkDataObject>> pieces = { piece0, piece1, piece2, nullptr };
  OverlayStitchGatherSummary summary;
  vtkSmartPointer<vtkPolyData> combined = OverlayStitchCombinePieces(pieces, &summary);

  std::cout << "combine four pieces\n";
  Check(combined->GetNumberOfPoints() == 5, "5 points (3 shared merged, the in-piece copy kept)");
  Check(summary.SharedPointsMerged == 3, "3 shared points counted");
  Check(combined->GetNumberOfLines() == 4, "4 lines (the repeated segment dropped)");
  Check(summary.SharedCellsDropped == 1, "1 shared cell counted");
  Check(combined->GetNumberOfVerts() == 1, "1 vertex cell");
  Check(combined->GetLines()->IsStorage64Bit() && combined->GetVerts()->IsStorage64Bit(),
    "cells in 64-bit storage, as the serial filter makes them");
  const std::vector<std::array<double, 2>> expectedPoints = { { 0, 0 }, { 1, 0 }, { 1, 1 },
    { 0, 1 }, { 0, 1 } };
  bool pointsOk = combined->GetNumberOfPoints() == 5;
  for (vtkIdType i = 0; pointsOk && i < 5; ++i)
  {
    pointsOk = PointOf(combined, i) == expectedPoints[static_cast<std::size_t>(i)];
  }
  Check(pointsOk, "points in first-seen order");

  auto* pointMarker = vtkIntArray::SafeDownCast(combined->GetPointData()->GetArray("PointMarker"));
  Check(pointMarker && pointMarker->GetNumberOfTuples() == 5 && pointMarker->GetValue(0) == 10 &&
      pointMarker->GetValue(2) == 12 && pointMarker->GetValue(3) == 21 &&
      pointMarker->GetValue(4) == 23,
    "point data follows the first copy of each point");

  // Cell ids: the vertex cell first, then the lines in piece order.
  auto* cellMarker = vtkIntArray::SafeDownCast(combined->GetCellData()->GetArray("SegmentMarker"));
  Check(cellMarker && cellMarker->GetNumberOfTuples() == 5 && cellMarker->GetValue(0) == 200 &&
      cellMarker->GetValue(1) == 100 && cellMarker->GetValue(2) == 101 &&
      cellMarker->GetValue(3) == 201 && cellMarker->GetValue(4) == 202,
    "cell data follows its cells (verts, then lines)");
  vtkNew<vtkIdList> ids;
  combined->GetCellPoints(0, ids);
  Check(ids->GetNumberOfIds() == 1 && ids->GetId(0) == 4, "the vertex cell is on the kept copy");
  combined->GetCellPoints(4, ids);
  Check(ids->GetNumberOfIds() == 2 && ids->GetId(0) == 3 && ids->GetId(1) == 0,
    "piece 1's second line uses the merged (0,0)");

  auto* holes = vtkDoubleArray::SafeDownCast(combined->GetFieldData()->GetArray("HolePoints"));
  Check(holes && holes->GetNumberOfComponents() == 3 && holes->GetNumberOfTuples() == 3 &&
      holes->GetComponent(0, 0) == 0.5 && holes->GetComponent(1, 0) == 0.25 &&
      holes->GetComponent(2, 0) == 0.75,
    "3 distinct hole seeds from every piece, the empty one included");
  Check(summary.HolePoints == 3, "3 hole seeds counted");
  Check(combined->GetFieldData()->GetArray("Other") != nullptr, "other field data kept");

  std::cout << "a piece with the ids combining gives blocks, beside one without\n";
  {
    // A rank's blocks, combined, carry block ids; another rank's polydata does
    // not: not every piece has them, but they are no arrays of the user's (a
    // review found them named in the "not carried" warning).
    auto blockPiece = MakePiece({ { 0, 0 }, { 1, 0 } }, { { 0, 1 } }, {}, { 1, 2 }, { 3 }, {});
    for (const char* name : { OverlayStitchBlockIdName, OverlayStitchRankName })
    {
      blockPiece->GetCellData()->AddArray(OverlayStitchIdArray(name, 1, 0));
      blockPiece->GetPointData()->AddArray(OverlayStitchIdArray(name, 2, 0));
    }
    auto plainPiece = MakePiece({ { 2, 0 }, { 3, 0 } }, { { 0, 1 } }, {}, { 1, 2 }, { 3 }, {});
    std::vector<vtkSmartPointer<vtkDataObject>> mixed = { blockPiece, plainPiece };
    OverlayStitchGatherSummary left;
    OverlayStitchCombinePieces(mixed, &left);
    std::string names;
    for (const OverlayStitchArrayName& item : left.ArraysLeftOut)
    {
      names += " " + item.Name;
    }
    Check(names.find("vtkOverlayStitch") == std::string::npos,
      "the filter's own ids are not among the arrays left out (" + names + " )");
  }

  std::cout << "marks that travel with a rank's combination\n";
  {
    // A rank's stand-in for a piece with a malformed cell array (no cells, a
    // mark): counted, and named by its rank, where rank 0 combines the pieces.
    auto good = MakePiece({ { 0, 0 }, { 1, 0 } }, { { 0, 1 } }, {}, { 1, 2 }, { 3 }, {});
    auto standIn = MakePiece({ { 5, 0 } }, {}, {}, { 1 }, {}, {});
    standIn->GetFieldData()->AddArray(RefusedMark());
    std::vector<vtkSmartPointer<vtkDataObject>> ranks = { good, standIn };
    OverlayStitchGatherSummary bad;
    OverlayStitchCombinePieces(ranks, &bad, "rank");
    Check(bad.MalformedPieces == 1 && bad.FirstMalformedPiece == "the piece of rank 1",
      "a piece marked malformed is counted and named (" + bad.FirstMalformedPiece + ")");
    // A rank's single block, emptied as malformed: named by its block and
    // rank, which only its field data can carry (it has no cells left).
    auto emptied = MakePiece({}, {}, {}, {}, {}, {});
    emptied->GetFieldData()->AddArray(RefusedMark());
    emptied->GetFieldData()->AddArray(OverlayStitchIdArray(OverlayStitchBlockIdName, 1, 2));
    emptied->GetFieldData()->AddArray(OverlayStitchIdArray(OverlayStitchRankName, 1, 1));
    ranks = { good, emptied };
    vtkSmartPointer<vtkPolyData> named = OverlayStitchCombinePieces(ranks, &bad, "rank");
    Check(bad.MalformedPieces == 1 && bad.FirstMalformedPiece == "block 2 on rank 1",
      "a block without cells is named by the ids in its field data (" + bad.FirstMalformedPiece +
        ")");
    Check(!named->GetFieldData()->GetArray(OverlayStitchBlockIdName) &&
        !named->GetFieldData()->GetArray(OverlayStitchRankName),
      "the field data's ids are not passed on as the user's field data");
    // A rank's blocks, one of them refused: the rank's combination carries the
    // refused block's id in its mark, which rank 0 names (a review found the
    // id of the other block's cells named).
    auto goodBlock = MakePiece({ { 3, 0 }, { 4, 0 } }, { { 0, 1 } }, {}, { 1, 2 }, { 3 }, {});
    goodBlock->GetCellData()->AddArray(OverlayStitchIdArray(OverlayStitchBlockIdName, 1, 1));
    goodBlock->GetPointData()->AddArray(OverlayStitchIdArray(OverlayStitchBlockIdName, 2, 1));
    goodBlock->GetFieldData()->AddArray(OverlayStitchIdArray(OverlayStitchBlockIdName, 1, 1));
    auto badBlock = MakePiece({}, {}, {}, {}, {}, {});
    badBlock->GetFieldData()->AddArray(RefusedMark());
    badBlock->GetFieldData()->AddArray(OverlayStitchIdArray(OverlayStitchBlockIdName, 1, 2));
    std::vector<vtkSmartPointer<vtkDataObject>> blocks = { goodBlock, badBlock };
    OverlayStitchGatherSummary onRank1;
    vtkSmartPointer<vtkPolyData> rank1Piece = OverlayStitchCombinePieces(blocks, &onRank1, "block");
    Check(onRank1.MalformedPieces == 1 && onRank1.FirstMalformedPiece == "block 2",
      "a rank's refused block is named by its own id (" + onRank1.FirstMalformedPiece + ")");
    ranks = { good, rank1Piece };
    OverlayStitchCombinePieces(ranks, &bad, "rank");
    Check(bad.MalformedPieces == 1 && bad.FirstMalformedPiece == "block 2 on rank 1",
      "rank 0 names the refused block of a rank's several (" + bad.FirstMalformedPiece + ")");
    // Float points beside double ones combine to double points, marked: a
    // second combination (rank 0's of the ranks' own) still knows.
    auto withPointType = [](vtkPolyData* piece, int type) {
      vtkNew<vtkPoints> points;
      points->SetDataType(type);
      for (vtkIdType i = 0; i < piece->GetNumberOfPoints(); ++i)
      {
        points->InsertNextPoint(piece->GetPoint(i));
      }
      piece->SetPoints(points);
    };
    auto floats = MakePiece({ { 0, 0 }, { 1, 0 } }, { { 0, 1 } }, {}, { 1, 2 }, { 3 }, {});
    withPointType(floats, VTK_FLOAT);
    auto doubles = MakePiece({ { 2, 0 }, { 3, 0 } }, { { 0, 1 } }, {}, { 1, 2 }, { 3 }, {});
    withPointType(doubles, VTK_DOUBLE);
    std::vector<vtkSmartPointer<vtkDataObject>> mixed = { floats, doubles };
    OverlayStitchGatherSummary first;
    vtkSmartPointer<vtkPolyData> rank1 = OverlayStitchCombinePieces(mixed, &first, "block");
    Check(first.FloatPoints && rank1->GetPoints()->GetDataType() == VTK_DOUBLE,
      "float and double pieces: double points, and float noted");
    std::vector<vtkSmartPointer<vtkDataObject>> again = { doubles, rank1 };
    OverlayStitchGatherSummary second;
    OverlayStitchCombinePieces(again, &second, "rank");
    Check(second.FloatPoints, "combined again with double points: float still noted");
    std::vector<vtkSmartPointer<vtkDataObject>> onlyFloats = { floats, floats };
    OverlayStitchGatherSummary third;
    vtkSmartPointer<vtkPolyData> allFloat = OverlayStitchCombinePieces(onlyFloats, &third, "rank");
    Check(third.FloatPoints && allFloat->GetPoints()->GetDataType() == VTK_FLOAT,
      "float pieces only: float points");
  }

  std::cout << "(x, y) seeds beside (x, y, z) ones\n";
  {
    // Taken at z = 0 there, an (x, y) seed repeating another piece's (x, y, 0)
    // is one seed, not two.
    auto flat = MakePiece({ { 0, 0 } }, {}, {}, { 1 }, {}, {});
    vtkNew<vtkDoubleArray> xy;
    xy->SetName("HolePoints");
    xy->SetNumberOfComponents(2);
    xy->InsertNextTuple2(0.5, 0.25);
    flat->GetFieldData()->AddArray(xy);
    auto spatial = MakePiece({ { 1, 0 } }, {}, {}, { 1 }, {}, { { 0.5, 0.25 }, { 0.75, 0.5 } });
    std::vector<vtkSmartPointer<vtkDataObject>> seeded = { flat, spatial };
    OverlayStitchGatherSummary seeds;
    vtkSmartPointer<vtkPolyData> both = OverlayStitchCombinePieces(seeded, &seeds, "rank");
    auto* holes = vtkDoubleArray::SafeDownCast(both->GetFieldData()->GetArray("HolePoints"));
    Check(seeds.HolePoints == 2 && holes && holes->GetNumberOfTuples() == 2 &&
        holes->GetNumberOfComponents() == 3,
      "(0.5, 0.25) and (0.5, 0.25, 0) are one seed (" + std::to_string(seeds.HolePoints) +
        " counted)");
  }

  std::cout << "no piece at all\n";
  std::vector<vtkSmartPointer<vtkDataObject>> none = { nullptr,
    vtkSmartPointer<vtkPolyData>::New() };
  vtkSmartPointer<vtkPolyData> empty = OverlayStitchCombinePieces(none, &summary);
  Check(empty && empty->GetNumberOfPoints() == 0 && empty->GetNumberOfCells() == 0,
    "empty pieces give an empty polydata");
  Check(empty->GetFieldData()->GetArray("HolePoints") == nullptr, "no HolePoints invented");

  std::cout << "global point ids give the order\n";
  // The input was (0,0) (1,0) (2,0) (3,0), ids 0..3; piece 0 holds (2,0) (1,0), piece 1
  // holds (3,0) (2,0) (0,0): the combination must list them in id order.
  auto idsPiece0 = MakePiece({ { 2, 0 }, { 1, 0 } }, { { 0, 1 } }, {}, { 2, 1 }, { 0 }, {});
  auto idsPiece1 =
    MakePiece({ { 3, 0 }, { 2, 0 }, { 0, 0 } }, { { 0, 1 } }, { 2 }, { 3, 2, 0 }, { 1, 2 }, {});
  for (auto& piece : { idsPiece0, idsPiece1 })
  {
    vtkNew<vtkIdTypeArray> globalIds;
    globalIds->SetName("GlobalPointIds");
    auto* markers = vtkIntArray::SafeDownCast(piece->GetPointData()->GetArray("PointMarker"));
    for (vtkIdType i = 0; i < piece->GetNumberOfPoints(); ++i)
    {
      globalIds->InsertNextValue(markers->GetValue(i)); // the marker doubles as the id here
    }
    piece->GetPointData()->SetGlobalIds(globalIds);
  }
  std::vector<vtkSmartPointer<vtkDataObject>> withIds = { idsPiece0, idsPiece1 };
  vtkSmartPointer<vtkPolyData> ordered = OverlayStitchCombinePieces(withIds, &summary);
  bool inOrder = ordered->GetNumberOfPoints() == 4;
  for (vtkIdType i = 0; inOrder && i < 4; ++i)
  {
    inOrder = PointOf(ordered, i)[0] == static_cast<double>(i);
  }
  Check(inOrder, "points (0,0) (1,0) (2,0) (3,0) in global id order");
  auto* orderedMarker = vtkIntArray::SafeDownCast(ordered->GetPointData()->GetArray("PointMarker"));
  Check(orderedMarker && orderedMarker->GetValue(0) == 0 && orderedMarker->GetValue(3) == 3,
    "point data reordered with the points");
  ordered->GetCellPoints(1, ids); // piece 0's line, after piece 1's vertex cell
  const bool line0 = ids->GetNumberOfIds() == 2 && ids->GetId(0) == 2 && ids->GetId(1) == 1;
  ordered->GetCellPoints(2, ids);
  const bool line1 = ids->GetNumberOfIds() == 2 && ids->GetId(0) == 3 && ids->GetId(1) == 2;
  ordered->GetCellPoints(0, ids);
  Check(line0 && line1 && ids->GetId(0) == 0, "cells follow the reordered points");

  std::cout << "cells naming points their piece does not have\n";
  Check(summary.InvalidCells == 0 && summary.FirstInvalidCell.empty(), "none in valid pieces");
  // Piece 1's line 1 names point 7 of its 2; piece 2 has lines but no points.
  auto badPiece1 =
    MakePiece({ { 2, 0 }, { 3, 0 } }, { { 0, 1 }, { 1, 7 } }, {}, { 0, 1 }, { 0, 1 }, {});
  auto pointless = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkCellArray> pointlessLines;
  const vtkIdType pointlessIds[2] = { 0, 1 };
  pointlessLines->InsertNextCell(2, pointlessIds);
  pointless->SetLines(pointlessLines);
  std::vector<vtkSmartPointer<vtkDataObject>> withBad = { piece0, badPiece1, pointless };
  OverlayStitchCombinePieces(withBad, &summary, "rank");
  Check(summary.InvalidCells == 2,
    "both invalid cells counted (" + std::to_string(summary.InvalidCells) + ")");
  Check(
    summary.FirstInvalidCell == "cell 1 of rank 1 refers to point 7, but that rank has 2 point(s)",
    "the first described with the piece's own ids: '" + summary.FirstInvalidCell + "'");
  std::vector<vtkSmartPointer<vtkDataObject>> onlyPointless = { pointless };
  OverlayStitchCombinePieces(onlyPointless, &summary, "block");
  Check(summary.FirstInvalidCell ==
      "cell 0 of block 0 refers to point 0, but that block has 0 point(s)",
    "a piece without points: '" + summary.FirstInvalidCell + "'");

  std::cout << "one process\n";
  vtkSmartPointer<vtkPolyData> same;
  const bool meshes = OverlayStitchGatherInput(nullptr, piece0, same, &summary);
  Check(meshes && same == piece0, "without a controller the input passes through, uncopied");
  Check(summary.CellsPerRank.size() == 1 && summary.CellsPerRank[0] == 2, "its cells counted");

  TestPieceToSend();
  std::cout << (Failures ? "FAILED\n" : "passed\n");
  return Failures ? 1 : 0;
}
