// Counts, timings and quality figures of one run of the mesher.
#ifndef osm_Statistics_h
#define osm_Statistics_h

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace osm
{

struct Statistics
{
  // Input and cleaning.
  std::size_t inputPoints = 0;
  std::size_t inputSegments = 0;
  std::size_t duplicatePointsMerged = 0;
  std::size_t zeroLengthSegmentsDropped = 0;
  std::size_t duplicateSegmentsMerged = 0;
  std::size_t segmentsSplitAtVertices = 0;   ///< T-junctions and collinear overlaps
  std::size_t pointsSnappedOntoSegments = 0; ///< splits at points within the merge tolerance
  /// Crossings of two segments that the walks found and split, over the
  /// rounds. Where many segments cross at one point, the walks of a round may
  /// find only some of the pairs (star60: 59 of 1,770): splitting at that
  /// point makes every segment pass through it, and the rest are not counted.
  std::size_t crossingsSplit = 0;
  // Phase 1: overlay.
  double gamma = 0.0; ///< radius/edge bound Γ (with gapRatioOverlay, the gap-ratio bound)
  double theta1Deg = 0.0;
  double predictedMaxAngleDeg = 0.0; ///< 180° − θ2
  /// The overlay bounds the gap ratio, not only radius / shortest edge
  /// (Options::gapRatioOverlay, or a mesh made again from one).
  bool gapRatioOverlay = false;
  std::size_t overlayVertices = 0;
  std::size_t overlaySteinerPoints = 0;
  std::size_t overlayTriangles = 0;
  // Phase 2: stitch.
  std::size_t crossings = 0;
  std::size_t goodCrossings = 0;
  std::size_t badCrossings = 0;
  std::size_t uncrossedEdges = 0;
  std::size_t keptEdges = 0; ///< crossed overlay edges that were kept
  std::size_t discardedEdges = 0;
  std::size_t stitchVertices = 0;
  // Phase 3: complete.
  std::size_t facesCompleted = 0; ///< non-triangular faces triangulated
  std::size_t largestFace = 0;    ///< most sides of a face (the paper's Lemma 1 says 6)
  /// Completed edges longer than the maximum edge length, split (LongEdges.h).
  std::size_t longEdgesSplit = 0;
  // Output.
  std::size_t outputVertices = 0;
  std::size_t outputTriangles = 0;
  std::size_t regions = 0;
  double minAngleDeg = 0.0;
  double maxAngleDeg = 0.0;
  // Seconds spent per phase.
  double secondsClean = 0.0;
  double secondsOverlay = 0.0;
  double secondsStitch = 0.0;
  double secondsComplete = 0.0;
  double secondsDomain = 0.0;
  double secondsTotal = 0.0;

  /// Every figure as (name, value) pairs, in a fixed order (for field data, JSON).
  std::vector<std::pair<std::string, double>> items() const;
};

} // namespace osm

#endif
