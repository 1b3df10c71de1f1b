// libFuzzer target: the .poly reader on arbitrary text. It must never crash,
// hang or allocate absurdly; a failure must come with "name:line: reason".
#include "PolyReader.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  // Half the inputs also supply a .node text, split at the first form feed.
  const std::size_t split = text.find('\f');
  std::istringstream poly(text.substr(0, split));
  std::istringstream node(split == std::string::npos ? std::string() : text.substr(split + 1));
  const osm::PolyFile f =
    osm::parsePoly(poly, "fuzz.poly", split == std::string::npos ? nullptr : &node);
  if (!f.ok && f.error.rfind("fuzz.", 0) != 0)
  {
    std::fprintf(stderr, "error without a location: %s\n", f.error.c_str());
    std::abort();
  }
  if (f.ok)
    for (const osm::Segment& s : f.pslg.segments)
      if (s[0] < 0 || s[1] < 0 || static_cast<std::size_t>(s[0]) >= f.pslg.points.size() ||
        static_cast<std::size_t>(s[1]) >= f.pslg.points.size())
        std::abort(); // an accepted file must have valid indices
  return 0;
}
