#include "HugePages.h"

#include <cstdint>
#include <cstdlib>
#include <string_view>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace osm
{

bool hugePagesWanted()
{
  // Read once: the environment is the host's to set, before meshing.
  static const bool wanted = [] {
    const char* off = std::getenv("OSM_NO_HUGE_PAGES");
    return !off || !*off || std::string_view(off) == "0";
  }();
  return wanted;
}

void adviseHugePages(const void* p, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t huge = std::uintptr_t{ 2 } << 20;
  // Below a few huge pages the gain is nil and the rounding wastes memory.
  if (!p || bytes < 4 * huge || !hugePagesWanted())
    return;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(p) + huge - 1) & ~(huge - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(huge - 1);
  if (end > begin)
    madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE); // advice: may fail
#else
  (void)p;
  (void)bytes;
#endif
}

} // namespace osm
