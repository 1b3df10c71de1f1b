// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
// Seeds given as field data (HolePoints, RegionAttributes) follow the points.
//
// Field data is passed through by geometric filters (Transform, Reflect, ...)
// unchanged, so seeds written as coordinates stay behind when the points
// move: a review's face.poly, scaled by 2, lost its main region to a seed
// that then lay inside it. The .poly reader therefore records four input
// points beside its seeds (OverlayStitchAddSeedReference); the filter maps
// the seeds by the affine map that takes the first three where they are now,
// if it takes the fourth there too (OverlayStitchSeedsFollowingPoints).
#ifndef OverlayStitchSeeds_h
#define OverlayStitchSeeds_h

#include "vtkSmartPointer.h"

#include <string>

class vtkDataObject;
class vtkPolyData;

/// The field data array of the reference points: rows (point id, x, y, z) of
/// three input points far apart and a fourth, then (number of points, 0, 0, 0).
extern const char* const OverlayStitchSeedReferenceName;

/// Adds the reference array to output's field data, from its points.
void OverlayStitchAddSeedReference(vtkPolyData* output);

/// input (a dataset) with its field data seeds moved by the affine map that
/// takes the reference points recorded with them to where those points are
/// now (a region's maximum area scaled with the areas), or null where
/// nothing moves: no reference array, another number of points than it
/// recorded (a piece of a distributed dataset, merged points: the seeds are
/// then used as they are, while the recorded points are still among them),
/// or the points where it recorded them. note: why the seeds could not
/// follow, where the points moved but by no affine map (the fourth point not
/// where the first three's map takes it), or where the number of points
/// changed and the recorded points are gone (renumbered and moved).
vtkSmartPointer<vtkDataObject> OverlayStitchSeedsFollowingPoints(
  vtkDataObject* input, std::string& note);

#endif
