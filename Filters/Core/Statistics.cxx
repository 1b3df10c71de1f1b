#include "Statistics.h"

namespace osm
{
std::vector<std::pair<std::string, double>> Statistics::items() const
{
  auto n = [](std::size_t v) { return static_cast<double>(v); };
  return {
    { "InputPoints", n(inputPoints) },
    { "InputSegments", n(inputSegments) },
    { "DuplicatePointsMerged", n(duplicatePointsMerged) },
    { "ZeroLengthSegmentsDropped", n(zeroLengthSegmentsDropped) },
    { "DuplicateSegmentsMerged", n(duplicateSegmentsMerged) },
    { "SegmentsSplitAtVertices", n(segmentsSplitAtVertices) },
    { "PointsSnappedOntoSegments", n(pointsSnappedOntoSegments) },
    { "CrossingsSplit", n(crossingsSplit) },
    { "Gamma", gamma },
    { "Theta1Deg", theta1Deg },
    { "PredictedMaxAngleDeg", predictedMaxAngleDeg },
    { "GapRatioOverlay", gapRatioOverlay ? 1.0 : 0.0 },
    { "OverlayVertices", n(overlayVertices) },
    { "OverlaySteinerPoints", n(overlaySteinerPoints) },
    { "OverlayTriangles", n(overlayTriangles) },
    { "Crossings", n(crossings) },
    { "GoodCrossings", n(goodCrossings) },
    { "BadCrossings", n(badCrossings) },
    { "UncrossedEdges", n(uncrossedEdges) },
    { "KeptEdges", n(keptEdges) },
    { "DiscardedEdges", n(discardedEdges) },
    { "StitchVertices", n(stitchVertices) },
    { "FacesCompleted", n(facesCompleted) },
    { "LargestFace", n(largestFace) },
    { "LongEdgesSplit", n(longEdgesSplit) },
    { "OutputVertices", n(outputVertices) },
    { "OutputTriangles", n(outputTriangles) },
    { "Regions", n(regions) },
    { "MinAngleDeg", minAngleDeg },
    { "MaxAngleDeg", maxAngleDeg },
    { "SecondsClean", secondsClean },
    { "SecondsOverlay", secondsOverlay },
    { "SecondsStitch", secondsStitch },
    { "SecondsComplete", secondsComplete },
    { "SecondsDomain", secondsDomain },
    { "SecondsTotal", secondsTotal },
  };
}
}
