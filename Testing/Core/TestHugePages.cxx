// The huge-page helpers must behave exactly like the std::vector calls they
// wrap; the advice itself only changes speed (measured by the benchmarks).

#include "HugePages.h"

#include <gtest/gtest.h>

#include <cstdint>
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

} // namespace
} // namespace osm
