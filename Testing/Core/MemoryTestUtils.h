// What the tests of the mesher's memory (huge pages, block pool) share: where
// a block lies in the process's mappings, and whether huge pages are wanted.
#ifndef osm_MemoryTestUtils_h
#define osm_MemoryTestUtils_h

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace osm
{

/// The line starting with field of the mapping that holds address a
/// (/proc/self/smaps), or "" where there is no such mapping or file.
inline std::string mappingLine(const void* a, const std::string& field)
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
    else if (inside && line.rfind(field, 0) == 0)
      return line;
  }
  return "";
}

/// The VmFlags of the mapping that holds address a, or "".
inline std::string mappingFlags(const void* a)
{
  return mappingLine(a, "VmFlags:");
}

/// The resident KiB of the mapping that holds address a, or -1.
inline long mappingRssKiB(const void* a)
{
  const std::string line = mappingLine(a, "Rss:");
  return line.empty() ? -1 : std::stol(line.substr(4));
}

/// Whether OSM_NO_HUGE_PAGES leaves huge pages on (unset, empty or 0).
inline bool expectHugePages()
{
  const char* off = std::getenv("OSM_NO_HUGE_PAGES");
  return !off || !*off || std::string(off) == "0";
}

} // namespace osm

#endif
