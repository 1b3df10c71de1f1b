#include "StagedOutput.h"

#include "OutputFile.h" // linkTarget

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace
{

/// The temporary file being written, for the signal handler: a fixed buffer,
/// since a handler may only call async-signal-safe functions (unlink).
char PendingTemp[4096];
volatile std::sig_atomic_t HavePending = 0;

void SetPending(const std::string& temp)
{
  HavePending = 0;
  if (temp.size() < sizeof PendingTemp)
  {
    std::memcpy(PendingTemp, temp.c_str(), temp.size() + 1);
    HavePending = 1;
  }
}

extern "C" void RemovePendingAndDie(int signal)
{
  if (HavePending)
  {
    ::unlink(PendingTemp);
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

/// The mode a new file gets: 0666 less the umask (mkstemp makes it 0600).
mode_t NewFileMode()
{
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

} // namespace

StagedOutput::StagedOutput(const std::string& path)
  : Path(path)
  , Target(osm::linkTarget(path).string())
{
  struct stat info;
  const bool exists = ::stat(this->Target.c_str(), &info) == 0;
  this->Existed = exists;
  if (exists && !S_ISREG(info.st_mode))
  {
    return;
  }
  const std::filesystem::path target(this->Target);
  std::string pattern =
    (target.parent_path() / ("." + target.filename().string() + ".osm-XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0)
  {
    return;
  }
  // The old file's permissions, or a new file's.
  ::fchmod(fd, exists ? (info.st_mode & 07777) : NewFileMode());
  ::close(fd);
  this->Temp = name.data();
  this->Staged = true;
  SetPending(this->Temp);
}

StagedOutput::~StagedOutput()
{
  this->Discard();
}

int StagedOutput::Commit()
{
  if (!this->Staged)
  {
    return 0;
  }
  const int error = std::rename(this->Temp.c_str(), this->Target.c_str()) == 0 ? 0 : errno;
  if (error != 0)
  {
    this->Discard();
    return error;
  }
  HavePending = 0;
  this->Staged = false;
  return 0;
}

bool StagedOutput::Discard()
{
  if (!this->Staged)
  {
    return false;
  }
  HavePending = 0;
  ::unlink(this->Temp.c_str());
  this->Staged = false;
  return true;
}

void StagedOutput::HandleSignals()
{
  for (const int signal : { SIGINT, SIGTERM, SIGHUP })
  {
    // A signal the caller ignores (nohup) stays ignored.
    if (std::signal(signal, RemovePendingAndDie) == SIG_IGN)
    {
      std::signal(signal, SIG_IGN);
    }
  }
}
