// A file written beside its target and renamed over it once complete.
#ifndef osm_StagedOutput_h
#define osm_StagedOutput_h

#include <string>

/// Where osm-mesh writes an output: a hidden temporary file beside the file
/// the path names (through symbolic links), renamed over it once complete, so
/// that a failed or interrupted write leaves the old file as it was (a review:
/// Ctrl-C during a 15 s write left a 0-byte file where a good mesh had been).
/// The write goes to the path itself, as before, where no file can be made
/// beside it (a read-only folder holding a writable file), where the path
/// names no regular file (a link to a device, a link loop), or where a new
/// file would lose what the old one has (another owner or group, hard links,
/// an access control list); and a rename refused (another user's file in a
/// sticky folder) copies the new file over the old one.
class StagedOutput
{
public:
  explicit StagedOutput(const std::string& path);
  ~StagedOutput();
  StagedOutput(const StagedOutput&) = delete;
  StagedOutput& operator=(const StagedOutput&) = delete;

  /// The file to write: the temporary one, or the path itself.
  const std::string& WritePath() const { return this->Staged ? this->Temp : this->Path; }
  /// Whether the write goes to a temporary file.
  bool IsStaged() const { return this->Staged; }
  /// Whether a file the path named before the write is still as it was: the
  /// write was staged, and Commit has not copied over it.
  bool OldFileIntact() const { return this->Existed && this->Intact; }
  /// Whether Commit wrote over the target in place (a rename refused).
  bool CopiedInPlace() const { return this->Copied; }
  /// Renames the temporary file over the target; 0, or the errno of a failure
  /// (the temporary file is then removed).
  int Commit();
  /// Removes the temporary file; whether there was one.
  bool Discard();

  /// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove the
  /// temporary file being written, then end the process as the signal would;
  /// reads the umask. Call it first, while one thread runs.
  static void HandleSignals();

private:
  std::string Path;
  std::string Target;
  std::string Temp;
  bool Staged = false;
  bool Existed = false;
  bool Intact = false;
  bool Copied = false;
};

#endif
