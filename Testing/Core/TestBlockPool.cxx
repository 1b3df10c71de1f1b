// The block pool serves medium blocks from huge-page chunks while a Reuse
// scope lives; outside one, or with huge pages off, operator new does. Its
// speed is measured by the benchmarks; these tests check where blocks come
// from, that freed ones are reused, and that no block or chunk is lost or
// given back while in use.

#include "BlockPool.h"
#include "HugePages.h"
#include "MemoryTestUtils.h"

#include <gtest/gtest.h>

#if defined(OSM_ADDRESS_SANITIZER)
#include <sanitizer/asan_interface.h>
#endif

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/resource.h>
#endif

namespace osm
{
namespace
{

constexpr std::size_t kKiB = 1024;
// The sizes below take a block just under the threshold and PoolScope's 64 KiB.
static_assert(pool::kFirstPooledBytes >= 8 * kKiB && pool::kFirstPooledBytes <= 64 * kKiB);

/// A medium block that takes this many KiB of its chunk, filled with c (a
/// little less than that many KiB, for AddressSanitizer's red zone).
Array<char> block(std::size_t kib, char c)
{
  return Array<char>(kib * kKiB - 100, c);
}

/// Whether p lies in a huge-page chunk of the pool's (advised, 2 MiB aligned).
bool inChunk(const void* p)
{
  return mappingFlags(p).find(" hg") != std::string::npos;
}

/// Opens a scope and asks for a block of 64 KiB (at least kFirstPooledBytes),
/// so that the pool serves every medium block from then on.
struct PoolScope
{
  pages::Reuse reuse;
  Array<char> first = block(64, 'w');
};

bool poolExpected()
{
  return expectHugePages() && std::ifstream("/proc/self/smaps").good();
}

TEST(BlockPool, OutsideAScopeMediumBlocksComeFromOperatorNew)
{
  const std::size_t before = pool::chunks();
  EXPECT_EQ(pool::take(64 * kKiB), nullptr);
  Array<char> a = block(64, 'a');
  EXPECT_EQ(pool::chunks(), before);
  EXPECT_FALSE(pool::give(a.data(), a.size())) << "an operator new block is not the pool's";
}

TEST(BlockPool, TheFirstBlocksOfAScopeComeFromOperatorNewThenFromAChunk)
{
  if (!poolExpected())
    GTEST_SKIP() << "huge pages off, or no /proc/self/smaps";
  const std::size_t before = pool::chunks();
  const pages::Reuse reuse;
  const std::size_t firstKiB = pool::kFirstPooledBytes / kKiB;
  Array<char> small = block(firstKiB - 4, 's');
  EXPECT_EQ(pool::chunks(), before) << "before the scope's first block of kFirstPooledBytes";
  EXPECT_FALSE(inChunk(small.data()));
  Array<char> first = block(firstKiB, 'f');
  EXPECT_EQ(pool::chunks(), before + 1) << "from the scope's first block of kFirstPooledBytes on";
  EXPECT_TRUE(inChunk(first.data()));
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(first.data()) % (2 * kKiB * kKiB), 0u)
    << "the front of a fresh chunk";
  Array<char> after = block(8, 'a');
  EXPECT_EQ(after.data(), first.data() + firstKiB * kKiB) << "any medium block after it";
  // Freed inside the scope, operator new's block still goes back to it.
  small = Array<char>();
  EXPECT_EQ(after.back(), 'a');
}

TEST(BlockPool, FreedBlocksAreReusedAndMergeWithinTheirChunk)
{
  if (!poolExpected())
    GTEST_SKIP() << "huge pages off, or no /proc/self/smaps";
  const std::size_t before = pool::chunks();
  PoolScope scope;
  Array<char> a = block(64, 'a'), b = block(64, 'b'), c = block(64, 'c');
  EXPECT_EQ(b.data(), a.data() + 64 * kKiB) << "carved one after the other";
  EXPECT_EQ(c.data(), b.data() + 64 * kKiB);
  char* first = a.data();
  a = Array<char>();
  Array<char> again = block(60, 'x'); // rounds up to the same 64 KiB
  EXPECT_EQ(again.data(), first) << "a freed block is handed out again";
  again = Array<char>();
  b = Array<char>();
  Array<char> both = block(128, 'y');
  EXPECT_EQ(both.data(), first) << "adjacent freed blocks merge";
  EXPECT_EQ(c.front(), 'c');
  EXPECT_EQ(pool::chunks(), before + 1);
}

TEST(BlockPool, AChunkIsGivenBackWhenItsScopeEndsOrItsLastBlockIsFreed)
{
  if (!poolExpected())
    GTEST_SKIP() << "huge pages off, or no /proc/self/smaps";
  const std::size_t before = pool::chunks();
  const char* freed = nullptr;
  Array<char> outlives;
  {
    PoolScope scope;
    Array<char> inside = block(100, 'i');
    freed = inside.data();
    outlives = block(100, 'o');
    EXPECT_EQ(pool::chunks(), before + 1);
  }
  // The chunk stays mapped while a block in it lives, whole and writable.
  EXPECT_EQ(pool::chunks(), before + 1);
  EXPECT_FALSE(mappingFlags(freed).empty()) << "its addresses stay the chunk's";
  for (char ch : outlives)
    ASSERT_EQ(ch, 'o');
  outlives.assign(outlives.size(), 'z');
  const char* last = outlives.data();
  outlives = Array<char>();
  EXPECT_EQ(pool::chunks(), before);
  EXPECT_TRUE(mappingFlags(last).empty()) << "given back with its last block";
  {
    PoolScope scope;
    Array<char> inside = block(100, 'i');
    last = inside.data();
  }
  EXPECT_EQ(pool::chunks(), before);
  EXPECT_TRUE(mappingFlags(last).empty()) << "given back when the scope ends";
}

// Giving a free part of a huge page back splits the page, which cost more at
// the end of a medium mesh call than keeping the chunk until its last block.
TEST(BlockPool, AChunkThatOutlivesItsScopeStaysWhole)
{
  if (!poolExpected())
    GTEST_SKIP() << "huge pages off, or no /proc/self/smaps";
  Array<char> outlives;
  long residentInScope = 0;
  {
    PoolScope scope;
    outlives = block(100, 'o');
    // Touch most of the chunk: freed, it is kept for reuse in the scope.
    Array<char> freed = block(1500, 'f');
    ASSERT_TRUE(inChunk(outlives.data()));
    ASSERT_TRUE(inChunk(freed.data()));
    freed = Array<char>();
    residentInScope = mappingRssKiB(outlives.data());
    ASSERT_GE(residentInScope, 1600);
  }
  EXPECT_EQ(mappingRssKiB(outlives.data()), residentInScope) << "no part given back";
  for (char ch : outlives)
    ASSERT_EQ(ch, 'o');
}

TEST(BlockPool, BlocksBelowOrAboveTheMediumSizesAreNotPooled)
{
  if (!poolExpected())
    GTEST_SKIP() << "huge pages off, or no /proc/self/smaps";
  const std::size_t before = pool::chunks();
  PoolScope scope;
  EXPECT_EQ(pool::take(pool::kPooledBytes - 1), nullptr);
  EXPECT_EQ(pool::take(pages::kOwnMappingBytes), nullptr);
  Array<char> small(pool::kPooledBytes - 1, 's');
  Array<char> large(pages::kOwnMappingBytes, 'l');
  EXPECT_FALSE(inChunk(small.data()));
  EXPECT_EQ(pool::chunks(), before + 1) << "the chunk of the scope's first block only";
}

#if defined(__GLIBC__) && !defined(OSM_ADDRESS_SANITIZER)
/// The process's address space now, in bytes (VmSize), or 0 if unknown.
std::size_t addressSpace()
{
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmSize:", 0) == 0)
      return std::stoul(line.substr(7)) * kKiB;
  return 0;
}

/// Run in a child process: caps the address space so that no chunk can be
/// mapped, then asks for medium blocks in a scope. Exits with 0 if they came
/// from operator new and hold their values, else with the failed check's code.
void mediumBlocksWithoutRoomForAChunk()
{
  // Room in the heap first, which malloc keeps (no trimming) and serves
  // blocks of up to 64 MiB from, instead of mapping them.
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  std::free(std::malloc(std::size_t{ 8 } << 20));
  const std::size_t before = pool::chunks();
  const rlimit cap{ addressSpace() + (std::size_t{ 1 } << 20), RLIM_INFINITY };
  if (cap.rlim_cur <= (1u << 20) || setrlimit(RLIMIT_AS, &cap) != 0)
    std::_Exit(2);
  if (pages::mapHuge(std::size_t{ 2 } << 20))
    std::_Exit(3); // the cap did not stop a chunk: this would test nothing
  {
    pages::Reuse reuse;
    Array<char> first = block(64, 'f');
    Array<char> second = block(200, 's');
    first.resize(first.size() + 100 * kKiB, 'g'); // grows by a new block
    if (pool::chunks() != before || inChunk(first.data()) || inChunk(second.data()))
      std::_Exit(4);
    if (first.front() != 'f' || first.back() != 'g' || second[150 * kKiB] != 's')
      std::_Exit(5);
  }
  std::_Exit(pool::chunks() == before ? 0 : 6);
}

// take() falls back to operator new when mmap fails (address space exhausted,
// or a limit): the caller's blocks must still come, from the heap.
TEST(BlockPool, WhenNoChunkCanBeMappedBlocksComeFromOperatorNew)
{
  if (!poolExpected())
    GTEST_SKIP() << "huge pages off, or no /proc/self/smaps";
  EXPECT_EXIT(mediumBlocksWithoutRoomForAChunk(), ::testing::ExitedWithCode(0), "");
}
#endif

TEST(BlockPool, TurnedOffWithHugePages)
{
  if (expectHugePages())
    GTEST_SKIP() << "run with OSM_NO_HUGE_PAGES=1 (its own CTest entry)";
  const std::size_t before = pool::chunks();
  PoolScope scope;
  EXPECT_EQ(pool::take(100 * kKiB), nullptr);
  Array<char> a = block(100, 'a');
  EXPECT_EQ(pool::chunks(), before);
}

#if defined(OSM_ADDRESS_SANITIZER)
// Past a live pooled block, and all of a freed one, the bytes are poisoned.
TEST(BlockPool, UnderAddressSanitizerOnlyLiveBlocksAreAddressable)
{
  if (!poolExpected())
    GTEST_SKIP() << "huge pages off";
  PoolScope scope;
  const std::size_t bytes = 70 * kKiB + 3;
  char* p = nullptr;
  {
    Array<char> v(bytes, 'v');
    p = v.data();
    ASSERT_TRUE(inChunk(p));
    EXPECT_EQ(__asan_region_is_poisoned(p, bytes), nullptr);
    EXPECT_TRUE(__asan_address_is_poisoned(p + bytes));
  }
  EXPECT_TRUE(__asan_address_is_poisoned(p)) << "a freed block kept for reuse";
  Array<char> w(bytes - 7, 'w');
  ASSERT_EQ(w.data(), p);
  EXPECT_EQ(__asan_region_is_poisoned(p, bytes - 7), nullptr);
  EXPECT_TRUE(__asan_address_is_poisoned(p + bytes - 7));
}
#endif

} // namespace
} // namespace osm
