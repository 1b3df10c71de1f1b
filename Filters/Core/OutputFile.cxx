#include "OutputFile.h"

#include <system_error>

namespace osm
{

std::filesystem::path linkTarget(const std::filesystem::path& path)
{
  std::error_code ec;
  std::filesystem::path p = path;
  for (int links = 0; links < 40 && std::filesystem::is_symlink(p, ec); ++links)
  {
    const std::filesystem::path next = std::filesystem::read_symlink(p, ec);
    if (ec)
      break;
    p = next.is_absolute() ? next : p.parent_path() / next;
  }
  return p;
}

OutputFile::OutputFile(const std::string& path)
  : target_(linkTarget(path))
{
  std::error_code ec;
  existed_ = std::filesystem::exists(target_, ec);
  before_ = stamp();
}

OutputFile::Stamp OutputFile::stamp() const
{
  std::error_code ec;
  const auto size = std::filesystem::file_size(target_, ec);
  const auto time = std::filesystem::last_write_time(target_, ec);
  return { ec ? std::uintmax_t(-1) : size, time };
}

bool OutputFile::removeIfWritten() const
{
  std::error_code ec;
  return !target_.empty() && std::filesystem::is_regular_file(target_, ec) &&
    (!existed_ || stamp() != before_) && std::filesystem::remove(target_, ec);
}

} // namespace osm
