// The memory the mesher plans for: control-group limits read along the
// group's path, and a second mesh that memory could not hold not tried.

#include "Mesher.h"
#include "Overlay.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <sys/stat.h>

namespace osm
{
namespace
{

/// A directory tree under /tmp standing for / (its proc and sys parts).
class FakeRoot
{
public:
  FakeRoot()
  {
    char name[] = "/tmp/osm-cgroup-XXXXXX";
    root = mkdtemp(name) ? name : "";
  }
  ~FakeRoot() { std::system(("rm -rf '" + root + "'").c_str()); }
  /// Writes text to root + path, making the folders on the way.
  void write(const std::string& path, const std::string& text) const
  {
    for (std::size_t at = path.find('/', 1); at != std::string::npos; at = path.find('/', at + 1))
      ::mkdir((root + path.substr(0, at)).c_str(), 0755);
    std::ofstream(root + path) << text;
  }
  std::string root;
};

TEST(MemoryLimit, ControlGroupLimitsAreReadAlongTheGroupsPath)
{
  // cgroup v1: the group has no limit (v1's "none" is a huge number), its
  // parent a tighter one than the root's.
  {
    FakeRoot f;
    ASSERT_FALSE(f.root.empty());
    f.write("/proc/self/cgroup", "5:devices:/a/b\n4:memory:/a/b\n1:cpu,cpuacct:/\n");
    const std::string v1 = "/sys/fs/cgroup/memory";
    f.write(v1 + "/a/b/memory.limit_in_bytes", "9223372036854771712\n");
    f.write(v1 + "/a/memory.limit_in_bytes", "2000000000\n");
    f.write(v1 + "/memory.limit_in_bytes", "8000000000\n");
    EXPECT_EQ(cgroupMemoryLimit(f.root), 2e9);
    // Another controller's group of the same name sets nothing.
    f.write("/sys/fs/cgroup/devices/a/memory.limit_in_bytes", "1000\n");
    EXPECT_EQ(cgroupMemoryLimit(f.root), 2e9);
  }
  // cgroup v2: "max" is no limit; the ancestor's holds; a trailing slash.
  {
    FakeRoot f;
    ASSERT_FALSE(f.root.empty());
    f.write("/proc/self/cgroup", "0::/user.slice/job.scope/\n");
    f.write("/sys/fs/cgroup/user.slice/job.scope/memory.max", "max\n");
    f.write("/sys/fs/cgroup/user.slice/memory.max", "1073741824\n");
    EXPECT_EQ(cgroupMemoryLimit(f.root), 1073741824.0);
    f.write("/sys/fs/cgroup/user.slice/job.scope/memory.max", "536870912\n");
    EXPECT_EQ(cgroupMemoryLimit(f.root), 536870912.0);
  }
  // Both hierarchies listed (a hybrid system): the tighter of the two.
  {
    FakeRoot f;
    ASSERT_FALSE(f.root.empty());
    f.write("/proc/self/cgroup", "4:memory:/g\n0::/h\n");
    f.write("/sys/fs/cgroup/memory/g/memory.limit_in_bytes", "3000000000\n");
    f.write("/sys/fs/cgroup/h/memory.max", "4000000000\n");
    EXPECT_EQ(cgroupMemoryLimit(f.root), 3e9);
  }
  // No limit files, no memory controller, no cgroup file: no limit.
  {
    FakeRoot f;
    ASSERT_FALSE(f.root.empty());
    EXPECT_EQ(cgroupMemoryLimit(f.root), 0.0);
    f.write("/proc/self/cgroup", "4:memory:/g\n0::/\n");
    EXPECT_EQ(cgroupMemoryLimit(f.root), 0.0);
    f.write("/proc/self/cgroup", "3:cpuset:/g\ngarbage\n");
    f.write("/sys/fs/cgroup/memory/g/memory.limit_in_bytes", "1000\n");
    EXPECT_EQ(cgroupMemoryLimit(f.root), 0.0);
  }
}

TEST(MemoryLimit, ASecondMeshMemoryCouldNotHoldIsNotTried)
{
  // Run by the test MemoryLimit.InAControlGroup (in_memory_group.sh), in a
  // group limited to OSM_TEST_MEMORY_GROUP_BYTES; skipped otherwise.
  const char* bytes = std::getenv("OSM_TEST_MEMORY_GROUP_BYTES");
  if (!bytes)
    GTEST_SKIP() << "run in a memory-limited control group by in_memory_group.sh only";
  const double limit = std::strtod(bytes, nullptr);
  ASSERT_EQ(physicalMemoryBytes(), limit);
  // A unit square at a maximum edge of 0.004 takes about 3e5 triangles: a
  // gap-ratio mesh of 13 times as many, at 150 bytes each, would not fit.
  Pslg p;
  p.points = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  p.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
  Options o;
  o.maxEdgeLength = 0.004;
  o.remeshAboveDeg = 1; // every mesh is above it: a second one is wanted
  const Result r = mesh(p, o);
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_GT(13.0 * double(r.stats.outputTriangles) * kBytesPerTriangle, limit);
  bool warned = false;
  for (const std::string& w : r.warnings)
    warned = warned ||
      (w.find("it was not made again from a gap-ratio overlay, which could take 13 times the "
              "triangles") != std::string::npos &&
        w.find("more than this machine's") != std::string::npos);
  EXPECT_TRUE(warned) << (r.warnings.empty() ? std::string("no warning") : r.warnings[0]);
}

TEST(MemoryLimit, AnOverlayMemoryCannotHoldEndsInAnError)
{
  // Run by the test MemoryLimit.OverlayInAControlGroup (in_memory_group.sh):
  // the overlay asks for the memory only once past the points it leaves
  // unchecked (Refiner::checkHardCap), and must then stop at what it holds.
  const char* bytes = std::getenv("OSM_TEST_MEMORY_GROUP_BYTES");
  if (!bytes)
    GTEST_SKIP() << "run in a memory-limited control group by in_memory_group.sh only";
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer's shadow memory and quarantine would not fit the group";
#endif
  const double limit = std::strtod(bytes, nullptr);
  ASSERT_EQ(physicalMemoryBytes(), limit);
  // A square and a point at 35 degrees with the gap-ratio overlay: a
  // refinement that does not end (found by trying), its own cap 1.5e6 points.
  Pslg p;
  p.points = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 }, { 0.3, 0.6 } };
  p.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
  Options o;
  o.minAngleDeg = 35;
  o.gapRatioOverlay = true;
  const std::size_t holds = std::size_t(meshPointsMemoryHolds(limit));
  ASSERT_LT(double(holds), 1.5e6);
  ASSERT_GT(double(holds), kPointsUncheckedAgainstMemory);
  const Result r = mesh(p, o);
  ASSERT_FALSE(r.ok);
  EXPECT_NE(r.error.find("exceeded " + std::to_string(holds) +
              " Steiner points, as many as this machine's memory"),
    std::string::npos)
    << r.error;
}

} // namespace
} // namespace osm
