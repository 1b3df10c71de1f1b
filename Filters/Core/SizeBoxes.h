// Tighter size bounds within boxes (the regions with a maximum area), indexed
// by a grid so that the overlay's test per triangle does not scan them all.
#ifndef osm_SizeBoxes_h
#define osm_SizeBoxes_h

#include "Geometry.h"
#include "HugePages.h"

namespace osm
{

/// A tighter size bound within a box (a region's, for its maximum area).
struct SizeBox
{
  Bounds box;
  double maxEdgeLength = 0.0;
};

class SizeBoxes
{
public:
  explicit SizeBoxes(const Array<SizeBox>& boxes);

  bool empty() const { return boxes.empty(); }
  /// Whether the triangle abc, whose longest edge has the square longest2,
  /// meets a box whose bound is shorter.
  bool tooLong(const Point& a, const Point& b, const Point& c, double longest2) const;
  /// Whether b lies within one of the boxes.
  bool covers(const Bounds& b) const;
  /// An estimate of the points that the boxes' bounds ask for: each box's
  /// area over that of the equilateral triangle of its bound, times 2, and no
  /// more than all of them covered at the tightest bound (they may overlap).
  /// within: the mesh's box, which no box extends beyond here.
  double pointsNeeded(const Bounds& within) const;

private:
  int cellX(double x) const;
  int cellY(double y) const;

  Array<SizeBox> boxes;
  Bounds all;             ///< the union of the boxes' bounds
  int nx = 0, ny = 0;     ///< grid cells over all
  double loosest2 = 0;    ///< no box bounds an edge shorter than this (squared)
  Array<int> cellStart;   ///< per cell, its first entry in cellBoxes (CSR)
  Array<int> cellBoxes;   ///< the boxes meeting each cell
  Array<double> cellMin2; ///< per cell, the tightest bound (squared) of its boxes
};

} // namespace osm

#endif
