// Statistics::items() names every figure once, each with its own field's
// value (a mutation test: MinAngleDeg read maxAngleDeg, GapRatioOverlay was
// always 0 and SecondsTotal read secondsDomain, and no test noticed).
#include "Statistics.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

using namespace osm;

TEST(Statistics, EveryItemReadsItsOwnField)
{
  Statistics s;
  // Distinct values, so that reading another field shows.
  std::vector<std::pair<std::string, std::size_t*>> counts{ { "InputPoints", &s.inputPoints },
    { "InputSegments", &s.inputSegments }, { "DuplicatePointsMerged", &s.duplicatePointsMerged },
    { "ZeroLengthSegmentsDropped", &s.zeroLengthSegmentsDropped },
    { "DuplicateSegmentsMerged", &s.duplicateSegmentsMerged },
    { "SegmentsSplitAtVertices", &s.segmentsSplitAtVertices },
    { "PointsSnappedOntoSegments", &s.pointsSnappedOntoSegments },
    { "CrossingsSplit", &s.crossingsSplit }, { "OverlayVertices", &s.overlayVertices },
    { "OverlaySteinerPoints", &s.overlaySteinerPoints },
    { "OverlayTriangles", &s.overlayTriangles }, { "Crossings", &s.crossings },
    { "GoodCrossings", &s.goodCrossings }, { "BadCrossings", &s.badCrossings },
    { "UncrossedEdges", &s.uncrossedEdges }, { "KeptEdges", &s.keptEdges },
    { "DiscardedEdges", &s.discardedEdges }, { "StitchVertices", &s.stitchVertices },
    { "FacesCompleted", &s.facesCompleted }, { "LargestFace", &s.largestFace },
    { "LongEdgesSplit", &s.longEdgesSplit }, { "OutputVertices", &s.outputVertices },
    { "OutputTriangles", &s.outputTriangles }, { "Regions", &s.regions } };
  std::vector<std::pair<std::string, double*>> reals{ { "Gamma", &s.gamma },
    { "Theta1Deg", &s.theta1Deg }, { "PredictedMaxAngleDeg", &s.predictedMaxAngleDeg },
    { "MinAngleDeg", &s.minAngleDeg }, { "MaxAngleDeg", &s.maxAngleDeg },
    { "SecondsClean", &s.secondsClean }, { "SecondsOverlay", &s.secondsOverlay },
    { "SecondsStitch", &s.secondsStitch }, { "SecondsComplete", &s.secondsComplete },
    { "SecondsDomain", &s.secondsDomain }, { "SecondsTotal", &s.secondsTotal } };
  std::map<std::string, double> expected;
  std::size_t k = 1;
  for (auto& [name, field] : counts)
    expected[name] = static_cast<double>(*field = k++);
  for (auto& [name, field] : reals)
    expected[name] = *field = 0.5 + static_cast<double>(k++);
  for (bool gapRatio : { false, true })
  {
    s.gapRatioOverlay = gapRatio;
    expected["GapRatioOverlay"] = gapRatio ? 1.0 : 0.0;
    std::map<std::string, double> items;
    for (const auto& [name, value] : s.items())
      EXPECT_TRUE(items.emplace(name, value).second) << name << " is named twice";
    EXPECT_EQ(items, expected);
  }
}
