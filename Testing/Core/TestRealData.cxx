// Every .poly input in ../shared/data/pslg: mesh, validate, report a table.
// Skips cleanly where the folder is absent (a user's clone has no ../shared).
#include "MeshTestUtils.h"
#include "PolyReader.h"
#include "SharedData.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

using namespace osm;
namespace fs = std::filesystem;

TEST(RealData, EveryPolyFileMeshesWithinTheBound)
{
  const std::vector<fs::path> files = shared_data::polyFiles();
  if (files.empty())
    GTEST_SKIP() << "no .poly file in " << shared_data::folder();
  std::printf("%-26s %9s %9s %9s %9s %8s %5s %8s\n", "input", "in.verts", "verts", "triangles",
    "min.angle", "max.angle", "face", "seconds");
  for (const fs::path& f : files)
  {
    const PolyFile poly = readPolyFile(f.string());
    ASSERT_TRUE(poly.ok) << poly.error;
    const auto t0 = std::chrono::steady_clock::now();
    const Result r = meshAndValidate(poly.pslg, f.filename().string());
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_LE(r.stats.maxAngleDeg, 170.0) << f;
    std::printf("%-26s %9zu %9zu %9zu %9.4f %9.4f %5zu %8.3f\n", f.filename().c_str(),
      poly.pslg.points.size(), r.mesh.vertices.size(), r.mesh.triangles.size(), r.stats.minAngleDeg,
      r.stats.maxAngleDeg, r.stats.largestFace, s);
  }
}

TEST(RealData, MaximumEdgeLengthHoldsOnEveryEdge)
{
  // A bound of 1/250 of the input's extent: completion's diagonals exceed it
  // on most of these inputs (by up to 8%) and are split.
  const std::vector<fs::path> files = shared_data::polyFiles();
  if (files.empty())
    GTEST_SKIP() << "no .poly file in " << shared_data::folder();
  std::size_t split = 0;
  for (const fs::path& file : files)
  {
    const PolyFile poly = readPolyFile(file.string());
    ASSERT_TRUE(poly.ok) << poly.error;
    const Pslg& p = poly.pslg;
    double lx = p.points[0].x, hx = lx, ly = p.points[0].y, hy = ly;
    for (const Point& q : p.points)
      lx = std::min(lx, q.x), hx = std::max(hx, q.x), ly = std::min(ly, q.y),
      hy = std::max(hy, q.y);
    Options o;
    o.maxEdgeLength = std::max(hx - lx, hy - ly) / 250;
    // The validator checks every edge against the bound.
    const Result r = meshAndValidate(p, file.filename().string(), o);
    split += r.stats.longEdgesSplit;
  }
  EXPECT_GT(split, 0u);
}
