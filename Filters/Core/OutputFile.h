// An output file's state before a write, so that a failed write can remove
// what it wrote and nothing else.
#ifndef osm_OutputFile_h
#define osm_OutputFile_h

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>

namespace osm
{

/// The file a write to path changes: through symbolic links (a dangling one
/// too), the file they name.
std::filesystem::path linkTarget(const std::filesystem::path& path);

/// The file a write to path will change, as it is before the write.
class OutputFile
{
public:
  explicit OutputFile(const std::string& path);

  /// After a failed write: removes the file if the write made or changed it
  /// (a file it did not touch, and a link's own entry, stay); returns whether
  /// it removed one.
  bool removeIfWritten() const;

private:
  using Stamp = std::pair<std::uintmax_t, std::filesystem::file_time_type>;
  Stamp stamp() const;

  std::filesystem::path target_;
  bool existed_ = false;
  Stamp before_;
};

} // namespace osm

#endif
