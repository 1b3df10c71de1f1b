// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// Internal to OverlayStitch::Filters (not installed): which input arrays the
// filter carries to its outputs, shared by its point and cell data carriers.
#ifndef OverlayStitchArrays_h
#define OverlayStitchArrays_h

#include "vtkType.h" // for vtkIdType

#include <string>
#include <vector>

class vtkAbstractArray;
class vtkDataArray;
class vtkDataSetAttributes;

/// Whether an array holds floats or doubles (interpolated, where others are copied).
bool OverlayStitchIsFloating(vtkAbstractArray* array);

/// Whether an array is Triangle's markers by that name: one integer per tuple.
bool OverlayStitchIsMarker(vtkAbstractArray* array, const char* name);

/// A marker's value as Triangle's int: a 64-bit marker beyond int's range is
/// clamped to it (casting it would be undefined).
int OverlayStitchMarkerValue(double value);

/// Whether an array is never carried: the ghost array (the outputs are one
/// piece) or one of the filter's internal ones (OverlayStitchInternalNames.h).
bool OverlayStitchIsNeverCarried(const char* name);

/// Whether in has arrays to carry: any but the block ids and the ghost array.
bool OverlayStitchHasUserArrays(vtkDataSetAttributes* in);

/// The arrays of in (data on `items` points or cells: kind "point" or
/// "cell") that may go to an output (named for the warnings, "Mesh" or
/// "Edges"): not the ghost array, since the outputs are one piece, nor the
/// block ids a composite input's cells and points are given; not one
/// named like one of reserved, the output's own, nor one with fewer tuples
/// than items, each of those two with a warning.
std::vector<vtkAbstractArray*> OverlayStitchCarriedArrays(vtkDataSetAttributes* in, vtkIdType items,
  const char* kind, const char* output, const std::vector<std::string>& reserved,
  std::vector<std::string>& warnings);

/// The warning for an array with fewer tuples than its points or cells (kind
/// "point" or "cell"): "The input's point data array T is not carried: it has
/// 2 tuples for 9 points." (`where` names a block or piece instead of "it").
std::string OverlayStitchShortArrayNote(const char* kind, const char* name, vtkIdType tuples,
  vtkIdType items, const std::string& where = std::string());

/// Makes in's active attributes (scalars, vectors, ...) active in out where
/// they are among carried, the arrays carried there; not global or pedigree
/// ids, which the output repeats, so that they are ids no more; nor normals:
/// a flat mesh's are its plane's, and those carried from a curved surface
/// (a Slice of a sphere) would shade it as a dome (a review).
void OverlayStitchKeepActive(vtkDataSetAttributes* in, vtkDataSetAttributes* out,
  const std::vector<vtkAbstractArray*>& carried);

#endif
