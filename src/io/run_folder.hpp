#pragma once
// A run's output folder, written whole or not at all (docs/interface.md, "Output files"). The run
// writes into a temporary sibling ".<name>.run-<pid>" of its target and, once complete, exchanges it
// with the target in one rename (renameat2 RENAME_EXCHANGE), then removes the previous run's files:
// a reader sees the previous complete run or the new one, never a mix, and a re-run leaves nothing of
// the previous one (a VTU series of 41 frames under a .pvd of 11, a finite old solution beside a new
// numerical_issue summary). A run that stops early (bad input found late, an interruption, an
// exception) removes its temporary and leaves the target as it was. While it runs, a lock on
// ".<name>.lock" beside the target (flock) refuses a second writer; a run that is refused removes
// the lock it made. A run replaces only what a run wrote: its marker ".stcontact-run" lists the
// run's files, and the target must be absent, an empty folder, or hold nothing but the files its
// marker lists (and their folders). Anything else, a file of one's own beside them, a nested run's
// folder, a marker without a list (an older version's, one made by hand), is refused, naming the
// first such file, before anything is computed. A symbolic link given as the target is followed;
// a folder without write permission is refused. Temporaries of runs that were killed (SIGKILL:
// their process is gone) are removed by the next run into the target.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "stcontact/core/interruption.hpp"

namespace stc {

class RunFolder {
 public:
  /// Checks the target and its parent (created if missing), takes the lock, creates the temporary.
  /// Throws OutputError naming the target and the reason.
  explicit RunFolder(std::filesystem::path target);
  ~RunFolder();
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;

  /// Where the run writes its files (the temporary folder).
  const std::filesystem::path& path() const { return temporary_; }
  const std::filesystem::path& target() const { return target_; }
  /// `text` with the temporary folder's path written as the target's (messages that name a file).
  std::string named(std::string text) const;
  /// Writes the marker (the list of the files the run wrote), then replaces the target by the
  /// temporary folder as a whole. Throws
  /// Interrupted when a stop was requested (src/core/interruption.hpp), OutputError when the
  /// exchange fails: either way the target is unchanged and the destructor removes the temporary.
  void commit();

 private:
  /// The lock beside the target: closed, and its file removed, when the run ends or is refused.
  struct Lock {
    std::filesystem::path path;
    int fd = -1;
    ~Lock();
  };
  std::filesystem::path target_, temporary_;
  Lock lock_;
  std::optional<StopCleanup> cleanup_;  ///< the temporary and the lock, for a process ended by a signal
  bool committed_ = false;
};

/// The files of a run folder `dir` its marker lists, relative to it (empty: no marker, or one
/// without a list).
std::vector<std::string> listedFiles(const std::filesystem::path& dir);

/// The file every run folder holds, which marks it as one the next run may replace.
inline constexpr const char* kRunMarker = ".stcontact-run";

}  // namespace stc
