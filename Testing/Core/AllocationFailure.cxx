// Allocation failure injected into the mesher, one large allocation at a time.
//
// The mesher reserves its large arrays up front and falls back to growing them
// when the reservation fails (strict overcommit, little address space). This
// executable replaces the global operator new so that the k-th large
// allocation of a mesh call throws std::bad_alloc, for every k in turn. Each
// run must end either with the same mesh as without the failure (the failure
// hit a reservation that has a fallback) or with the clean "out of memory"
// error: never a crash, a hang, a changed mesh or a partial result.
// It is its own executable because the replacement applies to the whole
// program.

#include "FailingAllocation.h"
#include "Mesher.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace osm
{
namespace
{

/// Random points inside a square with a triangular hole: every phase runs
/// (refinement, stitching with crossings, completion, carving a hole).
Pslg squareWithHole()
{
  Pslg in;
  in.points = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 }, { 0.4, 0.4 }, { 0.6, 0.4 }, { 0.5, 0.6 } };
  in.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 6 }, { 6, 4 } };
  in.holes = { { 0.5, 0.45 } };
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.01, 0.99);
  while (in.points.size() < 3000)
    in.points.push_back({ u(rng), u(rng) });
  return in;
}

/// Mesh with the k-th large allocation failing (k < 0: none); returns the
/// number of large allocations made.
long meshFailingAt(const Pslg& in, long k, Result& r)
{
  failing_allocation::start(k);
  r = mesh(in, Options{});
  return failing_allocation::stop();
}

bool sameMesh(const Result& a, const Result& b)
{
  return a.mesh.vertices == b.mesh.vertices && a.mesh.triangles == b.mesh.triangles &&
    a.regionId == b.regionId && a.vertexOrigin == b.vertexOrigin && a.inputVertex == b.inputVertex;
}

TEST(AllocationFailure, EveryLargeAllocationFailsCleanlyOrFallsBack)
{
  const Pslg in = squareWithHole();
  Result reference;
  const long large = meshFailingAt(in, -1, reference);
  ASSERT_TRUE(reference.ok) << reference.error;
  ASSERT_GT(reference.mesh.triangles.size(), 10000u);
  ASSERT_GT(large, 10) << "the input is too small to exercise the large arrays";

  long same = 0, outOfMemory = 0;
  for (long k = 0; k < large; ++k)
  {
    Result r;
    meshFailingAt(in, k, r);
    if (r.ok)
    {
      EXPECT_TRUE(sameMesh(r, reference)) << "allocation " << k << " failed: the mesh changed";
      ++same;
    }
    else
    {
      EXPECT_EQ(r.error.rfind("out of memory", 0), 0u)
        << "allocation " << k << " failed: " << r.error;
      EXPECT_TRUE(r.mesh.triangles.empty()) << "allocation " << k << ": partial mesh";
      ++outOfMemory;
    }
  }
  // The fallbacks: the refinement reserves its points, triangle slots and
  // input flags (Overlay.cxx), compaction its triangles and neighbours
  // (Stitch.cxx). Every other large allocation is needed.
  EXPECT_EQ(same, 5) << "of " << large << " large allocations";
  EXPECT_EQ(outOfMemory, large - same);
}

TEST(AllocationFailure, OutOfMemoryAfterSplittingManyCrossingsSaysSo)
{
  // 60 horizontal and 60 vertical segments: 3,600 crossings split, 15 times
  // the 240 input points, before the round that meshes them runs out of
  // memory (a streamline circling a limit cycle did so with no word of why).
  Pslg in;
  for (int i = 0; i < 60; ++i)
  {
    const double c = i + 0.5;
    const int first = static_cast<int>(in.points.size());
    in.points.insert(in.points.end(), { { 0, c }, { 60, c }, { c, 0 }, { c, 60 } });
    in.segments.insert(in.segments.end(), { { first, first + 1 }, { first + 2, first + 3 } });
  }
  Result r;
  const long large = meshFailingAt(in, -1, r);
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(r.stats.crossingsSplit, 3600u);
  // The last large allocation without a fallback.
  for (long k = large - 1; k >= 0 && r.ok; --k)
    meshFailingAt(in, k, r);
  ASSERT_FALSE(r.ok);
  EXPECT_EQ(r.error.rfind("out of memory", 0), 0u) << r.error;
  EXPECT_NE(
    r.error.find("splitting them added 3600 points so far to the input's 240"), std::string::npos)
    << r.error;
}

TEST(AllocationFailure, OutOfMemoryAbove30DegreesBlamesTheAngle)
{
  // Above 30 degrees the refinement need not end, and a runaway is the
  // likelier cause: no larger machine helps (a review). The warning stays.
  Pslg in;
  in.points = { { 0, 0 }, { 1, 0 }, { 0, 1 }, { 0.02, 0.01 } };
  Options o;
  o.minAngleDeg = 35;
  failing_allocation::start(0);
  const Result r = mesh(in, o);
  failing_allocation::stop();
  ASSERT_FALSE(r.ok);
  EXPECT_EQ(r.error,
    "out of memory: with a minimum angle above 30 degrees the overlay refinement need not end; "
    "use 30 degrees or less");
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings[0].find("(here 35) has no guarantee"), std::string::npos) << r.warnings[0];
}

} // namespace
} // namespace osm
