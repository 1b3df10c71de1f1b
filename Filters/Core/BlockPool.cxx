#include "BlockPool.h"

#include "FreeRanges.h"
#include "HugePages.h"

#include <atomic>
#include <mutex>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace osm
{
namespace pool
{
namespace
{
constexpr std::size_t kSmallPage = std::size_t{ 4 } << 10;
constexpr std::size_t kHugePage = std::size_t{ 2 } << 20;

/// Whole small pages holding the bytes and, under AddressSanitizer, the red zone.
std::size_t blockSize(std::size_t bytes)
{
  return (bytes + pages::kRedZoneBytes + kSmallPage - 1) & ~(kSmallPage - 1);
}

/// A mapping of the pool's and the bytes of it handed out and not yet freed.
struct Chunk
{
  AddressRange range;
  std::size_t live;
};

struct Pool
{
  std::mutex mutex;
  int scopes = 0;
  bool pooling = false; // since the scope's first block of kFirstPooledBytes or more
  std::vector<Chunk> chunks;
  FreeRanges free; // in chunks, only while a scope lives; merged within a chunk
  std::atomic<std::size_t> mapped{ 0 }; // chunks.size(), read without the lock
};

Pool& pool()
{
  static Pool p;
  return p;
}

Chunk* chunkHolding(Pool& pl, const char* q)
{
  for (Chunk& c : pl.chunks)
    if (c.range.holds(q))
      return &c;
  return nullptr;
}

void forget(Pool& pl, const Chunk* c)
{
  pl.chunks.erase(pl.chunks.begin() + (c - pl.chunks.data()));
  pl.mapped.store(pl.chunks.size(), std::memory_order_release);
}

/// Gives the memory of a range in a chunk back to the kernel; the addresses stay
/// the chunk's, so that nothing else is mapped where the pool's blocks may lie.
void release(const AddressRange& r) noexcept
{
#if defined(__linux__)
  madvise(r.p, r.size, MADV_DONTNEED);
#else
  (void)r;
#endif
}

/// Adds a freed range, merged with the free ranges of its chunk that it touches.
/// False if there is no memory to note it in.
bool keepFree(Pool& pl, const Chunk& c, AddressRange freed) noexcept
{
  // Chunks may touch: never merge across them.
  return pl.free.add(freed, [&c](const AddressRange& r) { return c.range.holds(r.p); });
}

/// A new chunk (one huge page) for a block of size bytes, its front handed out
/// and the rest free; null if there is no memory.
char* newChunk(Pool& pl, std::size_t size)
{
  try
  {
    pl.chunks.reserve(pl.chunks.size() + 1);
  }
  catch (const std::bad_alloc&)
  {
    return nullptr;
  }
  char* p = static_cast<char*>(pages::mapHuge(kHugePage));
  if (!p)
    return nullptr;
  pl.chunks.push_back({ { p, kHugePage }, size });
  pl.mapped.store(pl.chunks.size(), std::memory_order_release);
  pages::poison(p + size, kHugePage - size);
  // The rest is free (lost for reuse only if there is no memory to note it).
  keepFree(pl, pl.chunks.back(), { p + size, kHugePage - size });
  return p;
}

} // namespace

void* take(std::size_t bytes)
{
  if (bytes < kPooledBytes || bytes >= pages::kOwnMappingBytes || !hugePagesWanted())
    return nullptr;
  const std::size_t size = blockSize(bytes);
  Pool& pl = pool();
  const std::lock_guard<std::mutex> lock(pl.mutex);
  if (pl.scopes == 0)
    return nullptr;
  // A fresh huge page costs about as much as 10 to 20 small-page faults
  // (120-220 us against 12 us on the benchmark machine): a chunk pays only in
  // a mesh large enough to need a block of 32 KiB (about a thousand
  // triangles), and the blocks before the first such one come from operator
  // new. Pooling from 16 KiB slowed meshes of about 100 triangles by up to 24%.
  pl.pooling = pl.pooling || size >= kFirstPooledBytes;
  if (!pl.pooling)
    return nullptr;
  char* p = pl.free.takeSmallestHolding(size);
  if (p)
    chunkHolding(pl, p)->live += size;
  else if (!(p = newChunk(pl, size)))
    return nullptr;
  pages::unpoison(p, bytes);
  pages::poison(p + bytes, size - bytes);
  return p;
}

bool give(void* block, std::size_t bytes) noexcept
{
  Pool& pl = pool();
  if (bytes < kPooledBytes || pl.mapped.load(std::memory_order_acquire) == 0)
    return false;
  char* p = static_cast<char*>(block);
  const std::size_t size = blockSize(bytes);
  const std::lock_guard<std::mutex> lock(pl.mutex);
  Chunk* c = chunkHolding(pl, p);
  if (!c)
    return false;
  c->live -= size;
  pages::poison(p, size); // freed: any use until it is handed out again is an error
  if (pl.scopes > 0)
  {
    // Kept for reuse; a chunk is given back only when the last scope closes,
    // since the free list may hold parts of it.
    if (!keepFree(pl, *c, { p, size }))
      release({ p, size });
  }
  else if (c->live == 0)
  {
    pages::unmapNow(c->range.p, c->range.size);
    forget(pl, c);
  }
  return true;
}

std::size_t chunks()
{
  return pool().mapped.load(std::memory_order_acquire);
}

void openScope()
{
  Pool& pl = pool();
  const std::lock_guard<std::mutex> lock(pl.mutex);
  if (pl.scopes++ == 0)
    pl.pooling = false;
}

void closeScope() noexcept
{
  Pool& pl = pool();
  const std::lock_guard<std::mutex> lock(pl.mutex);
  if (--pl.scopes > 0)
    return;
  for (std::size_t i = 0; i < pl.chunks.size();)
  {
    if (pl.chunks[i].live > 0)
    {
      ++i;
      continue;
    }
    pages::unmapNow(pl.chunks[i].range.p, pl.chunks[i].range.size);
    forget(pl, &pl.chunks[i]);
  }
  // Chunks with blocks that outlive the scope (a Result's arrays) stay whole
  // until their last block is freed: giving part of a huge page back splits
  // it, which took 0.16-0.22 ms at the end of every call on medium inputs
  // (lake_superior.poly: 7% of its time).
  pl.free.clear();
}

} // namespace pool
} // namespace osm
