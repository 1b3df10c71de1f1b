// The real inputs of ../shared/data/pslg, which the tests use where they are:
// a folder that is absent, or holds no .poly file, skips those tests.
#ifndef osm_SharedData_h
#define osm_SharedData_h

#include <algorithm>
#include <filesystem>
#include <system_error>
#include <vector>

#ifndef OSM_SHARED_DATA_DIR
#define OSM_SHARED_DATA_DIR "" // no data folder known: the real-data tests skip
#endif

namespace shared_data
{

inline std::filesystem::path folder()
{
  return std::filesystem::path(OSM_SHARED_DATA_DIR);
}

/// The .poly files of the folder, sorted by name; none if it is absent or unreadable.
inline std::vector<std::filesystem::path> polyFiles()
{
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (std::filesystem::directory_iterator it(folder(), error), end; !error && it != end;
       it.increment(error))
    if (it->path().extension() == ".poly")
      files.push_back(it->path());
  std::sort(files.begin(), files.end());
  return files;
}

} // namespace shared_data

#endif
