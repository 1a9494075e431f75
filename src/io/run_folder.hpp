#pragma once
// A run's output folder, written whole or not at all (docs/interface.md, "Output files"). The run
// writes into a temporary sibling ".<name>.run-<pid>" of its target and, once complete, exchanges it
// with the target in one rename (renameat2 RENAME_EXCHANGE), then removes the previous run's files:
// a reader sees the previous complete run or the new one, never a mix, and a re-run leaves nothing of
// the previous one (a VTU series of 41 frames under a .pvd of 11, a finite old solution beside a new
// numerical_issue summary). A run that stops early (bad input found late, an interruption, an
// exception) removes its temporary and leaves the target as it was. While it runs, a lock on
// ".<name>.lock" beside the target (flock) refuses a second writer. The target must be absent, an
// empty folder or a previous run's (its marker ".stcontact-run", or the summary.json, summary.md
// or svd_summary.json of a version before the marker): anything else is refused rather than replaced. Temporaries of
// runs that were killed (SIGKILL: their process is gone) are removed by the next run into the target.
#include <filesystem>
#include <string>

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
  /// Writes the marker, then replaces the target by the temporary folder as a whole. Throws
  /// Interrupted when a stop was requested (src/core/interruption.hpp), OutputError when the
  /// exchange fails: either way the target is unchanged and the destructor removes the temporary.
  void commit();

 private:
  std::filesystem::path target_, temporary_, lock_path_;
  int lock_fd_ = -1;
  bool committed_ = false;
};

/// The file every run folder holds, which marks it as one the next run may replace.
inline constexpr const char* kRunMarker = ".stcontact-run";

}  // namespace stc
