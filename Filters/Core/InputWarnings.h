// What the mesher says about its input, in the user's numbers and
// coordinates: segments and crossings by name, outlines that miss closing,
// segment ends that dangle a hair from a segment, a merge tolerance to try.
#ifndef osm_InputWarnings_h
#define osm_InputWarnings_h

#include "Clean.h"
#include "Stitch.h"
#include "Work.h"

#include <string>

namespace osm
{

/// Segment s of a round (the input's, then the hull's) as the user numbers it.
std::string segmentName(const Work& w, int s);

/// "input segment A and input segment B cross near (x, y)", in user coordinates.
std::string describeCrossing(
  const Work& w, const SegmentCrossing& c, const Frame& frame, const PointFormat& format);

/// The first crossing, and how many more there are.
std::string crossingError(const Work& w, const Array<SegmentCrossing>& crossings,
  const Frame& frame, const PointFormat& format);

/// Why the auto domain meshed the hull where the segments look meant to
/// enclose a region (InputWarnings.cxx says when); "" otherwise.
std::string openOutlineWarning(
  const Work& w, const Pslg& input, const Array<int>& pointOf, const PointFormat& format);

/// Input segment ends that dangle within kNearMissExtent of the extent (or
/// float rounding) of a segment they do not touch, found by the walk over the
/// segments walked (overlay vertices); "" if none.
constexpr double kNearMissExtent = 1e-6;

std::string nearMissWarning(const Work& w, const Walk& walk, const Array<Segment>& walked,
  const Pslg& input, const Array<int>& pointOf, const Frame& frame, const PointFormat& format);

/// Pairs of input points closer than kClosePointsExtent of the extent (or
/// float rounding, by search.at) of each other, found among the overlay's
/// edges: the first input point of each (a < b) and their distance.
constexpr double kClosePointsExtent = 1e-6;

struct ClosePair
{
  int a = -1, b = -1;
  double distance = 0;
};

Array<ClosePair> closePointPairs(const Work& w, const Overlay& overlay, const OverlayEdges& ov,
  const NearMissSearch& search, const Pslg& input, const Array<int>& pointOf);

/// The warning about the pairs whose points are both in the mesh
/// (inputVertex, Result's), naming the nearest; "" if none.
std::string closePointsWarning(const Array<ClosePair>& pairs, const Array<int>& inputVertex,
  const Pslg& input, const PointFormat& format);

/// Where segments a and b of a round, too close to tell apart, share an end
/// and their far ends lie farther than reach (user units) from each other's
/// segment: the end, their angle there and the nearest other input point,
/// which makes the mesh as fine as the angle cannot be resolved at, and what
/// helps (the merge tolerance that bends one onto the other is that far);
/// "" otherwise, where the usual remedy, a small merge tolerance, applies.
std::string sharedEndNote(const Work& w, int a, int b, const Pslg& input, const Array<int>& pointOf,
  const Frame& frame, double reach, const PointFormat& format);

/// "; the input points nearest there are point A at (x, y) and point B at
/// (x, y), D apart" for a stop at `at` (working coordinates) where points are
/// too close; "" unless the pair nearest `at` is within 1e-12 of the
/// coordinates' magnitude of each other and 1e-9 of it from `at`.
std::string nearestPointsNote(const Work& w, const Point& at, const Pslg& input,
  const Array<int>& pointOf, const PointFormat& format);

/// The merge tolerance toleranceToTry suggests: 1e-9 of the input's extent.
double toleranceSuggested(const Bounds& input);

/// " (try about ...)": a merge tolerance to try where segments meet closer
/// than double precision separates, or "" where the one given is as large.
std::string toleranceToTry(const Bounds& input, double given);

} // namespace osm

#endif
