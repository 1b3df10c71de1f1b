// The huge-page helpers must behave exactly like the std::vector calls they
// wrap; the advice itself only changes speed (measured by the benchmarks).

#include "HugePages.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace osm
{
namespace
{

TEST(HugePages, PushBackKeepsEveryElementAcrossGrowth)
{
  // 40 MB of ints: several growths beyond the advice threshold.
  std::vector<int> v;
  const int n = 10000000;
  for (int i = 0; i < n; ++i)
    pushBackHuge(v, i * 7);
  ASSERT_EQ(v.size(), static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    ASSERT_EQ(v[i], i * 7) << i;
}

TEST(HugePages, PushBackOfAnElementOfTheVectorItself)
{
  std::vector<double> v{ 0.5 };
  for (int i = 0; i < 3000000; ++i)
    pushBackHuge(v, v[v.size() / 2]); // often at a growth, which frees v's storage
  for (double x : v)
    ASSERT_EQ(x, 0.5);
}

TEST(HugePages, AssignAndReserveGiveTheRequestedContents)
{
  std::vector<std::int64_t> v{ 1, 2, 3 };
  assignHuge(v, 3000000, std::int64_t{ -5 });
  ASSERT_EQ(v.size(), 3000000u);
  for (std::int64_t x : v)
    ASSERT_EQ(x, -5);
  // Shrinking reuses the storage, as assign does.
  const std::int64_t* before = v.data();
  assignHuge(v, 10, std::int64_t{ 4 });
  EXPECT_EQ(v.data(), before);
  EXPECT_EQ(v, std::vector<std::int64_t>(10, 4));

  std::vector<double> w{ 1.5, 2.5 };
  reserveHuge(w, 5000000);
  EXPECT_GE(w.capacity(), 5000000u);
  EXPECT_EQ(w, (std::vector<double>{ 1.5, 2.5 }));
}

TEST(HugePages, AdviceOnAnyRangeIsHarmless)
{
  adviseHugePages(nullptr, 1u << 30);
  char small[100] = {};
  adviseHugePages(small + 1, sizeof small - 1);
  std::vector<char> big(20u << 20, 'x');
  adviseHugePages(big.data() + 3, big.size() - 3); // unaligned both ends
  for (char c : big)
    ASSERT_EQ(c, 'x');
}

/// The VmFlags of the mapping that holds address a (/proc/self/smaps), or ""
/// where there is no such file.
std::string mappingFlags(const void* a)
{
  std::ifstream smaps("/proc/self/smaps");
  const auto at = reinterpret_cast<std::uintptr_t>(a);
  bool inside = false;
  for (std::string line; std::getline(smaps, line);)
  {
    std::uintptr_t lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> lo >> dash >> hi && dash == '-')
      inside = lo <= at && at < hi;
    else if (inside && line.rfind("VmFlags:", 0) == 0)
      return line;
  }
  return "";
}

// madvise marks the mapping (VmFlags "hg") whatever memory the kernel has
// free, so this checks that the advice is given, and not given when
// OSM_NO_HUGE_PAGES is set (the second CTest run of this test sets it).
TEST(HugePages, AdviceMarksTheMappingUnlessTurnedOff)
{
  if (!std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled"))
    GTEST_SKIP() << "no transparent huge pages in this kernel";
  const char* off = std::getenv("OSM_NO_HUGE_PAGES");
  const bool expected = !off || !*off || std::string(off) == "0";
  EXPECT_EQ(hugePagesWanted(), expected);
  std::vector<char> v;
  reserveHuge(v, 64u << 20);
  const std::string flags = mappingFlags(v.data() + (32u << 20));
  ASSERT_FALSE(flags.empty()) << "no mapping found in /proc/self/smaps";
  EXPECT_EQ(flags.find(" hg") != std::string::npos, expected) << flags;
}

// Arrays of a few MiB are advised too: the whole huge page that a 5 MiB array
// always contains is marked.
TEST(HugePages, AdviceReachesArraysOfAFewMegabytes)
{
  if (!std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled"))
    GTEST_SKIP() << "no transparent huge pages in this kernel";
  std::vector<char> v;
  reserveHuge(v, 5u << 20);
  constexpr std::uintptr_t huge = std::uintptr_t{ 2 } << 20;
  const std::uintptr_t page = (reinterpret_cast<std::uintptr_t>(v.data()) + huge - 1) & ~(huge - 1);
  const std::string flags = mappingFlags(reinterpret_cast<const char*>(page + huge / 2));
  ASSERT_FALSE(flags.empty()) << "no mapping found in /proc/self/smaps";
  EXPECT_EQ(flags.find(" hg") != std::string::npos, hugePagesWanted()) << flags;
}

} // namespace
} // namespace osm
