// osm::Array must behave exactly like std::vector, whichever way its blocks
// are allocated; the huge pages themselves only change speed (measured by the
// benchmarks).

#include "HugePages.h"
#include "MemoryTestUtils.h"

#include <gtest/gtest.h>

#if defined(OSM_ADDRESS_SANITIZER)
#include <sanitizer/asan_interface.h>
#endif

#include <cstdint>
#include <fstream>
#include <future>
#include <string>
#include <thread>
#include <vector>

namespace osm
{
namespace
{

TEST(HugePages, ArrayKeepsEveryElementAcrossGrowth)
{
  // 40 MB of ints: growths from operator new's blocks into mappings of their own.
  Array<int> v;
  const int n = 10000000;
  for (int i = 0; i < n; ++i)
    v.push_back(i * 7);
  ASSERT_EQ(v.size(), static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    ASSERT_EQ(v[i], i * 7) << i;
}

TEST(HugePages, PushBackOfAnElementOfTheArrayItself)
{
  Array<double> v{ 0.5 };
  for (int i = 0; i < 3000000; ++i)
    v.push_back(v[v.size() / 2]); // often at a growth, which frees v's storage
  for (double x : v)
    ASSERT_EQ(x, 0.5);
}

TEST(HugePages, AssignCopyAndMoveAcrossTheThreshold)
{
  Array<std::int64_t> v{ 1, 2, 3 };
  v.assign(3000000, std::int64_t{ -5 });
  ASSERT_EQ(v.size(), 3000000u);
  for (std::int64_t x : v)
    ASSERT_EQ(x, -5);
  Array<std::int64_t> copy = v; // a mapping of its own, freed by its own size
  EXPECT_EQ(copy, v);
  Array<std::int64_t> moved = std::move(copy);
  EXPECT_EQ(moved.size(), 3000000u);
  v.assign(10, std::int64_t{ 4 }); // shrinking keeps the storage
  v.shrink_to_fit();               // and this frees the mapping for a small block
  EXPECT_EQ(v, (Array<std::int64_t>(10, 4)));
}

struct alignas(32) Wide
{
  double x[4];
};

TEST(HugePages, OverAlignedElementsAreAlignedInSmallAndLargeBlocks)
{
  for (std::size_t n : { std::size_t{ 3 }, std::size_t{ 1000 }, std::size_t{ 100000 } })
  {
    Array<Wide> v(n);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % 32, 0u) << n;
  }
}

/// Whether large blocks should get their own mappings in this environment.
bool expectOwnMappings()
{
  return expectHugePages();
}

// madvise marks the mapping (VmFlags "hg") whatever memory the kernel has
// free, so this checks that the advice is given, and not given when
// OSM_NO_HUGE_PAGES is set (the second CTest run of this test sets it).
TEST(HugePages, LargeBlocksGetAlignedAdvisedMappingsUnlessTurnedOff)
{
  if (!std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled"))
    GTEST_SKIP() << "no transparent huge pages in this kernel";
  EXPECT_EQ(hugePagesWanted(), expectHugePages());
  const bool expected = expectOwnMappings();
  EXPECT_EQ(pages::ownMapping(pages::kOwnMappingBytes), expected);
  EXPECT_FALSE(pages::ownMapping(pages::kOwnMappingBytes - 1));
  constexpr std::uintptr_t huge = std::uintptr_t{ 2 } << 20;
  // From a block just over the threshold (one huge page) to several.
  for (std::size_t bytes : { pages::kOwnMappingBytes, std::size_t{ 5 } << 20 })
  {
    Array<char> v;
    v.reserve(bytes);
    if (expected) // an operator new block may be aligned by chance
      EXPECT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % huge, 0u) << bytes;
    const std::string flags = mappingFlags(v.data() + bytes - 1);
    ASSERT_FALSE(flags.empty()) << "no mapping found in /proc/self/smaps";
    EXPECT_EQ(flags.find(" hg") != std::string::npos, expected) << bytes << ": " << flags;
  }
}

// A block's mapping is given back whole when the array frees it: nothing
// stays mapped at its address (a wrong size would leave a tail or unmap a
// neighbour).
TEST(HugePages, FreedBlocksAreUnmapped)
{
  if (!expectOwnMappings() || !std::ifstream("/proc/self/smaps"))
    GTEST_SKIP() << "no mappings of their own (huge pages off), or no /proc/self/smaps";
  const std::size_t bytes = (std::size_t{ 3 } << 20) + 12345;
  const char* first = nullptr;
  const char* last = nullptr;
  {
    Array<char> v(bytes, 'y');
    first = v.data();
    last = v.data() + bytes - 1;
    ASSERT_FALSE(mappingFlags(last).empty());
  }
  EXPECT_TRUE(mappingFlags(first).empty());
  EXPECT_TRUE(mappingFlags(last).empty());
}

// Inside a Reuse scope freed mappings stay mapped: a request takes the front
// of the smallest kept range that holds it, ranges that touch merge, a request
// that nothing holds gives them all back first, and so does the scope's end.
// Sizes are whole huge pages less 1000 bytes, so that the red zone of the
// AddressSanitizer build does not add a page.
TEST(HugePages, ReuseKeepsFreedMappingsUntilItsScopeEnds)
{
  if (!expectOwnMappings() || !std::ifstream("/proc/self/smaps"))
    GTEST_SKIP() << "no mappings of their own (huge pages off), or no /proc/self/smaps";
  constexpr std::size_t huge = std::size_t{ 2 } << 20;
  auto block = [&](std::size_t k, char c) { return Array<char>(k * huge - 1000, c); };
  char* six = nullptr;
  {
    const pages::Reuse reuse;
    six = block(6, 'a').data(); // freed at once: one kept range of six pages
    EXPECT_FALSE(mappingFlags(six).empty()) << "a freed mapping is kept in the scope";
    EXPECT_EQ(pages::keptBytes(), 6 * huge);
    // Split: one, two and three pages from the front of the same range.
    Array<char> one = block(1, 'b'), two = block(2, 'c'), three = block(3, 'd');
    EXPECT_EQ(one.data(), six);
    EXPECT_EQ(two.data(), six + huge);
    EXPECT_EQ(three.data(), six + 3 * huge);
    EXPECT_EQ(pages::keptBytes(), 0u);
    EXPECT_EQ(three.back(), 'd');
    // Two ranges apart, of one and three pages: one page comes from the
    // smaller.
    one = Array<char>();
    three = Array<char>();
    EXPECT_EQ(pages::keptBytes(), 4 * huge);
    Array<char> again = block(1, 'e');
    EXPECT_EQ(again.data(), six) << "the smallest range that holds the request";
    // Freeing the middle merges all three into six pages: five fit, one stays.
    again = Array<char>();
    two = Array<char>();
    EXPECT_EQ(pages::keptBytes(), 6 * huge);
    Array<char> five = block(5, 'f');
    EXPECT_EQ(five.data(), six);
    EXPECT_EQ(pages::keptBytes(), huge) << "adjacent ranges merge";
    // Nothing kept holds eight pages: the kept page is given back first.
    Array<char> eight = block(8, 'g');
    EXPECT_EQ(pages::keptBytes(), 0u) << "a request nothing holds gives the kept back";
    EXPECT_EQ(eight.back(), 'g');
  }
  EXPECT_EQ(pages::keptBytes(), 0u);
  EXPECT_TRUE(mappingFlags(six).empty()) << "given back when the scope ends";
}

// Nested scopes (two meshes at once, say) keep the mappings until the last ends.
TEST(HugePages, ReuseScopesNest)
{
  if (!expectOwnMappings() || !std::ifstream("/proc/self/smaps"))
    GTEST_SKIP() << "no mappings of their own (huge pages off), or no /proc/self/smaps";
  const char* p = nullptr;
  {
    const pages::Reuse outer;
    {
      const pages::Reuse inner;
      Array<char> a(1u << 20, 'x');
      p = a.data();
    }
    EXPECT_FALSE(mappingFlags(p).empty());
  }
  EXPECT_TRUE(mappingFlags(p).empty());
}

// A scope keeps only what its own thread frees: a call on another thread
// (ParaView meshing in two pipelines) must not keep this one's freed arrays
// mapped until it ends (a review: 192 MB after us48.poly), and a mapping
// freed on a thread with no scope open is given back at once.
TEST(HugePages, AScopeOnAnotherThreadKeepsNothingOfThisThreads)
{
  if (!expectOwnMappings() || !std::ifstream("/proc/self/smaps"))
    GTEST_SKIP() << "no mappings of their own (huge pages off), or no /proc/self/smaps";
  std::promise<void> opened, done;
  std::thread other([&] {
    const pages::Reuse reuse;
    Array<char> theirs(1u << 20, 'y');
    const char* q = theirs.data();
    theirs = Array<char>();
    EXPECT_FALSE(mappingFlags(q).empty()) << "their own freed mapping is kept in their scope";
    opened.set_value();
    done.get_future().wait();
  });
  opened.get_future().wait();
  const char* p = nullptr;
  {
    const pages::Reuse reuse;
    Array<char> a(1u << 20, 'x');
    p = a.data();
    a = Array<char>();
    EXPECT_FALSE(mappingFlags(p).empty()) << "kept while this thread's scope lives";
  }
  EXPECT_TRUE(mappingFlags(p).empty()) << "kept after this thread's scope, for another thread's";
  Array<char> b(1u << 20, 'z');
  p = b.data();
  b = Array<char>();
  EXPECT_TRUE(mappingFlags(p).empty()) << "freed with no scope on this thread, yet kept";
  done.set_value();
  other.join();
}

#if defined(OSM_ADDRESS_SANITIZER)
// AddressSanitizer knows only operator new's blocks: in a mapping of our own,
// the bytes past a live block and the whole of a freed one kept for reuse are
// poisoned, so that the sanitized tests and the fuzzers see overflows there.
TEST(HugePages, UnderAddressSanitizerOnlyLiveBlocksAreAddressable)
{
  if (!expectOwnMappings())
    GTEST_SKIP() << "no mappings of their own (huge pages off)";
  const std::size_t bytes = (std::size_t{ 2 } << 20) - 3; // the red zone needs a second page
  const pages::Reuse reuse;
  char* p = nullptr;
  {
    Array<char> v(bytes, 'z');
    p = v.data();
    EXPECT_EQ(__asan_region_is_poisoned(p, bytes), nullptr);
    EXPECT_TRUE(__asan_address_is_poisoned(p + bytes));
    EXPECT_TRUE(__asan_address_is_poisoned(p + bytes + pages::kRedZoneBytes - 1));
  }
  EXPECT_TRUE(__asan_address_is_poisoned(p)) << "a freed mapping kept for reuse";
  EXPECT_TRUE(__asan_address_is_poisoned(p + bytes / 2));
  Array<char> w(bytes - 5, 'w'); // the same mapping, handed out again
  ASSERT_EQ(w.data(), p);
  EXPECT_EQ(__asan_region_is_poisoned(p, bytes - 5), nullptr);
  EXPECT_TRUE(__asan_address_is_poisoned(p + bytes - 5));
}

TEST(HugePages, UnderAddressSanitizerAnOverflowIsReported)
{
  if (!expectOwnMappings())
    GTEST_SKIP() << "no mappings of their own (huge pages off)";
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(
    {
      Array<int> v(1u << 20, 1);
      volatile int* q = v.data();
      q[v.size()] = 2;
    },
    "use-after-poison");
}
#endif

} // namespace
} // namespace osm
