// Transparent huge pages for the mesher's large arrays.
//
// The refinement reads and writes its triangle slots in an order the mesh
// decides, all over arrays of hundreds of megabytes: with 4 KiB pages nearly
// every access misses the TLB, and every first touch of a fresh page is a
// page fault. On a virtual machine a small-page fault costs about 10 us, so
// that a fresh 8 MiB array takes 22 ms to fill in 4 KiB pages and 0.3-0.7 ms
// in 2 MiB pages. Debian's kernels give huge pages only to memory that asks
// (transparent_hugepage=madvise), so the mesher asks for its own arrays; the
// host application's heap stays as it was.
//
// osm::Array is the mesher's std::vector: a block of kOwnMappingBytes or more
// gets whole 2 MiB pages of a mapping of the mesher's own, aligned and
// advised (a fresh one, or freed ones kept for reuse, see Reuse); medium ones
// come from the block pool while a Reuse scope lives (BlockPool.h), the rest
// from operator new. A mapping of its own, not
// advice on the heap's memory, because the heap's blocks start anywhere, and
// the small pages at both ends of a block were most of the faults left.
// Where huge pages cost more than they save (a kernel that compacts memory
// on every such fault), OSM_NO_HUGE_PAGES=1 in the environment turns the
// mappings off.
#ifndef osm_HugePages_h
#define osm_HugePages_h

#include "BlockPool.h"

#include <cstddef>
#include <new>
#include <vector>

namespace osm
{

/// Whether huge pages are wanted: OSM_NO_HUGE_PAGES unset, empty or 0.
bool hugePagesWanted();

namespace pages
{
/// Blocks from this size up get their own huge-page mapping. Below it, the
/// up to 2 MiB that the last huge page of a block holds beyond it costs more
/// memory than its faults cost time: clearing one 2 MiB page costs about as
/// much as 128 small-page faults on bare metal, and much less on a virtual
/// machine.
constexpr std::size_t kOwnMappingBytes = std::size_t{ 512 } << 10;

/// Under AddressSanitizer, which knows nothing of these mappings, every
/// mapping keeps at least this many bytes past its block, and the mapped bytes
/// outside a live block are poisoned: reading or writing past an array's end,
/// or a freed block kept for reuse, is reported as it is for operator new's
/// blocks. The sanitized tests and the fuzzers thus run the mapping paths too.
#if defined(__SANITIZE_ADDRESS__)
#define OSM_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define OSM_ADDRESS_SANITIZER 1
#endif
#endif
#if defined(OSM_ADDRESS_SANITIZER)
constexpr std::size_t kRedZoneBytes = 64;
#else
constexpr std::size_t kRedZoneBytes = 0;
#endif

/// Whether a block of this many bytes has (or would get) its own mapping.
/// Depends on the size alone, so that freeing takes the allocation's path.
bool ownMapping(std::size_t bytes);

/// Whole 2 MiB pages holding the bytes (and, under AddressSanitizer, at least
/// kRedZoneBytes more), aligned to 2 MiB and advised: the front of a kept
/// range if one holds them, else a fresh mapping. Throws std::bad_alloc if
/// there is no room.
void* map(std::size_t bytes);

/// Gives back a mapping from map(bytes), or keeps it for reuse (see Reuse).
void unmap(void* p, std::size_t bytes) noexcept;

/// A fresh mapping of size bytes (whole huge pages), aligned to 2 MiB and
/// advised; null if there is no room.
void* mapHuge(std::size_t size) noexcept;

/// Gives a mapping or a part of one back to the kernel.
void unmapNow(void* p, std::size_t size) noexcept;

/// Declares bytes unusable or usable to AddressSanitizer (no-ops without it).
void poison(void* p, std::size_t bytes);
void unpoison(void* p, std::size_t bytes);

/// The bytes of freed mappings this thread keeps for reuse now.
std::size_t keptBytes();

/// While one lives on a thread (osm::mesh keeps one for its whole call), mappings freed on that
/// thread stay mapped, merged where they touch, and a request takes the front of the smallest kept
/// range that holds it: the kernel clears every fresh page, and each phase frees arrays the next
/// one could fill (a run of 10^6 triangles would otherwise map about 200 MB more, 440 instead of
/// 240). A request that no kept range holds first gives them all back, so these mappings never
/// exceed the largest total that the live arrays have had (operator new's memory cannot use them).
/// When the thread's last one ends, its kept ranges are given back. While one lives on any thread,
/// the block pool serves medium blocks (BlockPool.h).
class Reuse
{
public:
  Reuse();
  ~Reuse();
  Reuse(const Reuse&) = delete;
  Reuse& operator=(const Reuse&) = delete;
};

} // namespace pages

/// The allocator of osm::Array (stateless: any instance frees any block).
template <class T>
struct HugeAllocator
{
  using value_type = T;

  HugeAllocator() noexcept = default;
  template <class U>
  HugeAllocator(const HugeAllocator<U>&) noexcept
  {}

  T* allocate(std::size_t n)
  {
    if (n > static_cast<std::size_t>(-1) / sizeof(T))
      throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if (pages::ownMapping(bytes))
      return static_cast<T*>(pages::map(bytes));
    if (bytes >= pool::kPooledBytes && alignof(T) <= 4096)
      if (void* p = pool::take(bytes))
        return static_cast<T*>(p);
    if constexpr (alignof(T) > __STDCPP_DEFAULT_NEW_ALIGNMENT__)
      return static_cast<T*>(::operator new(bytes, std::align_val_t(alignof(T))));
    else
      return static_cast<T*>(::operator new(bytes));
  }

  void deallocate(T* p, std::size_t n) noexcept
  {
    const std::size_t bytes = n * sizeof(T);
    if (pages::ownMapping(bytes))
      pages::unmap(p, bytes);
    else if (bytes >= pool::kPooledBytes && pool::give(p, bytes))
      return;
    else if constexpr (alignof(T) > __STDCPP_DEFAULT_NEW_ALIGNMENT__)
      ::operator delete(p, std::align_val_t(alignof(T)));
    else
      ::operator delete(p);
  }
};

template <class T, class U>
bool operator==(const HugeAllocator<T>&, const HugeAllocator<U>&) noexcept
{
  return true;
}

template <class T, class U>
bool operator!=(const HugeAllocator<T>&, const HugeAllocator<U>&) noexcept
{
  return false;
}

/// The mesher's arrays: a std::vector whose large blocks are in huge pages.
template <class T>
using Array = std::vector<T, HugeAllocator<T>>;

} // namespace osm

#endif
