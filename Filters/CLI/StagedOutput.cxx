#include "StagedOutput.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/xattr.h>
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
/// Read once, by HandleSignals at the start, while one thread runs: reading
/// the umask sets it.
mode_t NewFileMode = 0644;

/// Whether a file replaced by a new one would lose something that writing it
/// in place keeps: its owner or group (a file another user lets us write),
/// its other hard links, its access control list.
bool KeepsOnlyInPlace(const std::string& path, const struct stat& info)
{
  return info.st_uid != ::geteuid() || info.st_gid != ::getegid() || info.st_nlink > 1 ||
    ::getxattr(path.c_str(), "system.posix_acl_access", nullptr, 0) >= 0;
}

/// Copies file from over file to, truncating it: the write in place, where
/// the rename is refused (a file another user owns in a sticky folder).
int CopyInPlace(const std::string& from, const std::string& to)
{
  errno = 0;
  std::ifstream in(from, std::ios::binary);
  std::ofstream out(to, std::ios::binary | std::ios::trunc);
  if (in && out)
  {
    out << in.rdbuf();
    out.close();
  }
  return in && out ? 0 : (errno != 0 ? errno : EIO);
}

} // namespace

StagedOutput::StagedOutput(const std::string& path)
  : Path(path)
  , Target(osm::linkTarget(path).string())
  , Before(path)
{
  struct stat info;
  const bool exists = ::stat(this->Target.c_str(), &info) == 0;
  this->Existed = exists;
  // Only a regular file, or none (not a link loop, which stat refuses).
  if (exists ? !S_ISREG(info.st_mode) || KeepsOnlyInPlace(this->Target, info) : errno != ENOENT)
  {
    return;
  }
  const std::filesystem::path target(this->Target);
  std::string pattern =
    (target.parent_path() / ("." + target.filename().string() + ".osm-XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  // No signal between making the file and noting it for the handler.
  sigset_t all, before;
  sigfillset(&all);
  ::sigprocmask(SIG_BLOCK, &all, &before);
  const int fd = ::mkstemp(name.data());
  if (fd >= 0)
  {
    SetPending(name.data());
  }
  ::sigprocmask(SIG_SETMASK, &before, nullptr);
  if (fd < 0)
  {
    return;
  }
  // The old file's permissions, or a new file's.
  ::fchmod(fd, exists ? (info.st_mode & 07777) : NewFileMode);
  ::close(fd);
  this->Temp = name.data();
  this->Staged = true;
  this->Intact = true;
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
  if (error == EPERM || error == EACCES)
  {
    // Written in place after all: a failure leaves the target changed.
    this->Intact = false;
    const int copied = CopyInPlace(this->Temp, this->Target);
    this->Discard();
    return copied;
  }
  if (error == 0)
  {
    HavePending = 0;
    this->Staged = false;
  }
  return error;
}

bool StagedOutput::RemoveWritten()
{
  return this->Staged ? this->Discard() : this->Before.removeIfWritten();
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
  const mode_t mask = ::umask(0);
  ::umask(mask);
  NewFileMode = 0666 & ~mask;
  for (const int signal : { SIGINT, SIGTERM, SIGHUP })
  {
    // A signal the caller ignores (nohup) stays ignored.
    if (std::signal(signal, RemovePendingAndDie) == SIG_IGN)
    {
      std::signal(signal, SIG_IGN);
    }
  }
}
