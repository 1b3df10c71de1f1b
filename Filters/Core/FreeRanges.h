// Free address ranges in the mesher's own mappings, for reuse: a request
// takes the front of the smallest range that holds it, and a freed range
// merges with the ranges it touches. Shared by the kept huge-page mappings
// (HugePages.cxx) and the block pool's chunks (BlockPool.cxx); the callers
// hold their own locks.
#ifndef osm_FreeRanges_h
#define osm_FreeRanges_h

#include <algorithm>
#include <cstddef>
#include <new>
#include <vector>

namespace osm
{

struct AddressRange
{
  char* p;
  std::size_t size;
  bool holds(const char* q) const { return q >= p && q < p + size; }
};

class FreeRanges
{
public:
  /// The front of the smallest range of at least size bytes (the rest stays
  /// free), or null.
  char* takeSmallestHolding(std::size_t size)
  {
    AddressRange* best = nullptr;
    for (AddressRange& r : items)
      if (r.size >= size && (!best || r.size < best->size))
        best = &r;
    if (!best)
      return nullptr;
    char* p = best->p;
    best->p += size;
    best->size -= size;
    if (best->size == 0)
      items.erase(items.begin() + (best - items.data()));
    return p;
  }

  /// Adds a freed range, merged with each range it touches for which
  /// mayMerge(range) holds; false if there is no memory to note it in.
  template <class MayMerge>
  bool add(AddressRange freed, MayMerge mayMerge) noexcept
  {
    try
    {
      items.reserve(items.size() + 1); // then nothing below throws
    }
    catch (const std::bad_alloc&)
    {
      return false;
    }
    for (std::size_t i = 0; i < items.size();)
    {
      const AddressRange r = items[i];
      const bool touches = r.p + r.size == freed.p || freed.p + freed.size == r.p;
      if (touches && mayMerge(r))
      {
        freed = { std::min(r.p, freed.p), r.size + freed.size };
        items.erase(items.begin() + static_cast<std::ptrdiff_t>(i));
      }
      else
        ++i;
    }
    items.push_back(freed);
    return true;
  }

  const std::vector<AddressRange>& ranges() const { return items; }
  void clear() { items.clear(); }

private:
  std::vector<AddressRange> items;
};

} // namespace osm

#endif
