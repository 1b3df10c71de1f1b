#include "HugePages.h"

#include "FreeRanges.h"

#include <cstdint>
#include <cstdlib>
#include <string_view>

#if defined(__linux__)
#include <sys/mman.h>
#endif
#if defined(OSM_ADDRESS_SANITIZER)
#include <sanitizer/asan_interface.h>
#endif

namespace osm
{

namespace
{
constexpr std::uintptr_t kHuge = std::uintptr_t{ 2 } << 20;

/// The size of the mapping holding a block of these bytes.
std::size_t mappedSize(std::size_t bytes)
{
  return (bytes + pages::kRedZoneBytes + kHuge - 1) & ~(kHuge - 1);
}

/// A block of bytes at the start of a mapping of size: usable up to its end.
void* handOut(void* p, std::size_t bytes, std::size_t size)
{
  pages::unpoison(p, bytes);
  pages::poison(static_cast<char*>(p) + bytes, size - bytes);
  return p;
}

/// The freed ranges kept while a pages::Reuse lives on this thread; adjacent
/// ones are merged. One per thread, so that a call keeps only what it frees
/// itself: shared, one call's freed arrays stayed mapped until every call on
/// other threads had ended (a review: 192 MB after meshing us48.poly, while
/// another thread meshed). A mapping freed on a thread with no scope open
/// (a result freed elsewhere) is given back at once.
struct Kept
{
  int scopes = 0;
  FreeRanges ranges; // whole huge pages, freed and kept mapped for reuse
};

Kept& kept()
{
  thread_local Kept k;
  return k;
}

/// Gives every kept range back to the kernel.
void giveBackAll(Kept& k) noexcept
{
  for (const AddressRange& r : k.ranges.ranges())
    pages::unmapNow(r.p, r.size);
  k.ranges.clear();
}

} // namespace

bool hugePagesWanted()
{
  // Read once: the environment is the host's to set, before meshing. Every
  // block is then freed the way it was allocated.
  static const bool wanted = [] {
    const char* off = std::getenv("OSM_NO_HUGE_PAGES");
    return !off || !*off || std::string_view(off) == "0";
  }();
  return wanted;
}

namespace pages
{

void poison(void* p, std::size_t bytes)
{
#if defined(OSM_ADDRESS_SANITIZER)
  __asan_poison_memory_region(p, bytes);
#else
  (void)p;
  (void)bytes;
#endif
}

void unpoison(void* p, std::size_t bytes)
{
#if defined(OSM_ADDRESS_SANITIZER)
  __asan_unpoison_memory_region(p, bytes);
#else
  (void)p;
  (void)bytes;
#endif
}

void unmapNow(void* p, std::size_t size) noexcept
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  unpoison(p, size); // the address range may serve another mapping later
  munmap(p, size);
#else
  (void)p;
  (void)size;
#endif
}

void* mapHuge(std::size_t size) noexcept
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // mmap aligns to small pages only: map one huge page more, keep the
  // aligned part and give back the rest.
  const std::size_t span = size + kHuge;
  void* m = mmap(nullptr, span, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (m == MAP_FAILED)
    return nullptr;
  const auto start = reinterpret_cast<std::uintptr_t>(m);
  const std::uintptr_t aligned = (start + kHuge - 1) & ~(kHuge - 1);
  if (aligned > start)
    munmap(m, aligned - start);
  if (const std::uintptr_t end = aligned + size; start + span > end)
    munmap(reinterpret_cast<void*>(end), start + span - end);
  madvise(reinterpret_cast<void*>(aligned), size, MADV_HUGEPAGE); // advice: may fail
  return reinterpret_cast<void*>(aligned);
#else
  (void)size;
  return nullptr;
#endif
}

bool ownMapping(std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  return bytes >= kOwnMappingBytes && hugePagesWanted();
#else
  (void)bytes;
  return false;
#endif
}

void* map(std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const std::size_t size = mappedSize(bytes);
  Kept& k = kept();
  if (void* p = k.ranges.takeSmallestHolding(size))
    return handOut(p, bytes, size);
  // Nothing kept fits: give it all back before mapping more, so that the
  // mappings never exceed the largest total the live arrays have had.
  giveBackAll(k);
  void* p = mapHuge(size);
  if (!p)
    throw std::bad_alloc();
  return handOut(p, bytes, size);
#else
  (void)bytes;
  throw std::bad_alloc(); // ownMapping() is false here: never called
#endif
}

void unmap(void* p, std::size_t bytes) noexcept
{
  const std::size_t size = mappedSize(bytes);
  Kept& k = kept();
  const auto any = [](const AddressRange&) { return true; };
  if (k.scopes == 0 || !k.ranges.add({ static_cast<char*>(p), size }, any))
  {
    unmapNow(p, size);
    return;
  }
  poison(p, size); // freed: any use until it is handed out again is an error
}

std::size_t keptBytes()
{
  const Kept& k = kept();
  std::size_t bytes = 0;
  for (const AddressRange& r : k.ranges.ranges())
    bytes += r.size;
  return bytes;
}

Reuse::Reuse()
{
  ++kept().scopes;
  pool::openScope();
}

Reuse::~Reuse()
{
  pool::closeScope();
  Kept& k = kept();
  if (--k.scopes > 0)
    return;
  giveBackAll(k);
}

} // namespace pages

} // namespace osm
