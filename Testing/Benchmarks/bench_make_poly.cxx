// Benchmark helper: writes a generated input (family:N:seed, see Generators.h)
// as a Triangle .poly file, so that tools that read files (the osm-mesh command
// line) mesh exactly what the drivers generate in memory. Coordinates are
// written with 17 significant digits, which read back bit for bit.
//
//   bench_make_poly <family:N:seed> <out.poly>
#include "Generators.h"

#include <cstdio>
#include <string>

int main(int argc, char** argv)
{
  if (argc != 3)
  {
    std::fprintf(stderr, "usage: %s <family:N:seed> <out.poly>\n", argv[0]);
    return 2;
  }
  osm::Pslg pslg;
  std::string error;
  if (!osmbench::generate(argv[1], pslg, error))
  {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  std::FILE* f = std::fopen(argv[2], "w");
  if (!f)
  {
    std::perror(argv[2]);
    return 1;
  }
  std::fprintf(f, "# %s\n%zu 2 0 0\n", argv[1], pslg.points.size());
  for (std::size_t i = 0; i < pslg.points.size(); ++i)
    std::fprintf(f, "%zu %.17g %.17g\n", i, pslg.points[i].x, pslg.points[i].y);
  std::fprintf(f, "%zu 0\n", pslg.segments.size());
  for (std::size_t i = 0; i < pslg.segments.size(); ++i)
    std::fprintf(f, "%zu %d %d\n", i, pslg.segments[i][0], pslg.segments[i][1]);
  std::fprintf(f, "%zu\n", pslg.holes.size());
  for (std::size_t i = 0; i < pslg.holes.size(); ++i)
    std::fprintf(f, "%zu %.17g %.17g\n", i, pslg.holes[i].x, pslg.holes[i].y);
  const bool ok = std::fclose(f) == 0;
  if (!ok)
    std::perror(argv[2]);
  return ok ? 0 : 1;
}
