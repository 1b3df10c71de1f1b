#include "OutputFile.h"

#include <system_error>

namespace osm
{

OutputFile::OutputFile(const std::string& path)
  : target_(path)
{
  std::error_code ec;
  for (int links = 0; links < 40 && std::filesystem::is_symlink(target_, ec); ++links)
  {
    const std::filesystem::path next = std::filesystem::read_symlink(target_, ec);
    target_ = next.is_absolute() ? next : target_.parent_path() / next;
  }
  existed_ = !ec && std::filesystem::exists(target_, ec);
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
