// A file written beside its target and renamed over it once complete.
#ifndef osm_StagedOutput_h
#define osm_StagedOutput_h

#include "OutputFile.h"

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
  /// Whether a file the path named before the write is still as it was: the
  /// write was staged, and Commit has not copied over it.
  bool OldFileIntact() const { return this->Existed && this->Intact; }
  /// Renames the temporary file over the target; 0, or the errno of a failure.
  int Commit();
  /// After a failed write or Commit: removes what the write made, the
  /// temporary file or a file it made or changed in place (a file it did not
  /// touch, and a link's own entry, stay); whether it removed one.
  bool RemoveWritten();

  /// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove the
  /// temporary file being written, then end the process as the signal would;
  /// reads the umask. Call it first, while one thread runs.
  static void HandleSignals();

private:
  bool Discard();

  std::string Path;
  std::string Target;
  std::string Temp;
  bool Staged = false;
  bool Existed = false;
  bool Intact = false;
  osm::OutputFile Before; ///< the target as it was, for a write in place
};

#endif
