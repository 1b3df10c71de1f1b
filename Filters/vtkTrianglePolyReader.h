// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
/**
 * @class   vtkTrianglePolyReader
 * @brief   read Triangle's .poly and .node files (Planar Straight Line Graphs)
 *
 * vtkTrianglePolyReader reads the .poly (points, segments, holes, regional
 * attributes) and .node (points only) files of Shewchuk's Triangle into
 * vtkPolyData ready for vtkOverlayStitchMesher. The format is chosen by the
 * file's extension (.poly or .node, any case). A .poly file that lists zero
 * vertices takes them from the .node file beside it, as Triangle does.
 *
 * The output:
 * - points in file order (renumbered from 0 whatever the file's first index),
 *   with z = 0;
 * - one 2-point line cell per segment, in file order, and one vertex cell per
 *   point that is on no segment (vertex cells come first in the cell data, as
 *   always in vtkPolyData);
 * - point data `PointMarker` (int, when the file has boundary markers on its
 *   vertices or its segments: 0 where the vertices have none, as Triangle
 *   reads them) and
 *   `Attribute0`, `Attribute1`, ... (double, one array per vertex attribute);
 * - cell data `SegmentMarker` (int, when the file has segment markers; 0 on
 *   the vertex cells);
 * - field data `HolePoints`: a 3-component double array (x, y, 0) with the
 *   file's hole seeds, always present, possibly with 0 tuples (the mesher
 *   uses it as hole seeds); `FileFirstIndex` (int, 1 value: 0 or 1, the
 *   numbering the file used); when the file has regional attributes,
 *   `RegionAttributes`: 4 components (x, y, attribute, maximum area); and,
 *   when it has hole or region seeds, `SeedReferencePoints` (4 components:
 *   the id and coordinates of four of its points, then the number of points), by
 *   which vtkOverlayStitchMesher moves the seeds with the points through a
 *   Transform; the mesher does not pass it to its outputs.
 *
 * A malformed file gives an error "file:line: reason" and an empty output;
 * the request does not fail (Update() returns 1), so that the filters
 * downstream run on the empty output instead of keeping their last outputs,
 * and a gather downstream in parallel does not wait for a failed piece.
 *
 * In parallel the whole file is read by piece 0; the other pieces are empty
 * (with an empty `HolePoints`), so that the data is delivered once.
 *
 * @sa
 * vtkOverlayStitchMesher
 */

#ifndef vtkTrianglePolyReader_h
#define vtkTrianglePolyReader_h

#include "OverlayStitchFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class OVERLAYSTITCHFILTERS_EXPORT vtkTrianglePolyReader : public vtkPolyDataAlgorithm
{
public:
  static vtkTrianglePolyReader* New();
  vtkTypeMacro(vtkTrianglePolyReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The .poly or .node file to read.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /**
   * 1 if the name ends in .poly or .node (any case) and the file can be
   * opened, else 0. Does not parse the file.
   */
  int CanReadFile(const char* fileName);

protected:
  vtkTrianglePolyReader();
  ~vtkTrianglePolyReader() override;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  char* FileName;

private:
  vtkTrianglePolyReader(const vtkTrianglePolyReader&) = delete;
  void operator=(const vtkTrianglePolyReader&) = delete;
};

#endif
