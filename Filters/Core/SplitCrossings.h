// Splitting input segments where they cross, and joining the points that
// rounding or the merge tolerance makes one, between meshing rounds.
#ifndef osm_SplitCrossings_h
#define osm_SplitCrossings_h

#include "Stitch.h"
#include "Work.h"

#include <cstddef>
#include <string>

namespace osm
{

struct Statistics;

/// Split every segment of w at the points where others cross it, crossings
/// rounded apart by a few units in the last place joined into one point.
void splitCrossings(Work& w, const Array<SegmentCrossing>& crossings, Statistics& stats);

/// Hole and region seeds that a join moved to the other side of a segment:
/// count of them, and one named ("hole 2 and segment 5", the user's numbers).
struct SeedsAcross
{
  std::size_t count = 0;
  std::string example;
};

/// Crossing points can coincide after rounding: merge them, drop what
/// degenerates; with a merge tolerance tol (scaled), join the crossings within
/// it of a point (SplitCrossings.cxx says how). Returns how many points joined
/// another; seeds receives the hole and region seeds that segments bent across.
std::size_t mergeEqualPoints(Work& w, double tol, SeedsAcross& seeds);

} // namespace osm

#endif
