#pragma once
// Atomic result files (docs/interface.md: "all written atomically: a crashed run never leaves a half
// file"). Content goes to a temporary file in the target's folder, is flushed and closed (no fsync: see commit()), then
// renamed over the target: readers see either the old file or the complete new one, never a part.
#include <filesystem>
#include <memory>
#include <ostream>
#include <string>

namespace stc {

/// Writes `content` to `path`, replacing any existing file, atomically. On any failure throws
/// OutputError naming `path` and the system's reason, and leaves no temporary behind.
void writeFileAtomically(const std::filesystem::path& path, const std::string& content);

/// Creates `dir` and its parents if missing. Throws OutputError naming `dir` if it cannot be
/// created, is not a folder, or a probe file cannot be created (and removed) in it.
void ensureWritableDirectory(const std::filesystem::path& dir);

/// A file written through stream() into a temporary ".<name>.tmp.<pid>.<n>" next to `path` and
/// moved into place by commit(), for large files streamed without building a string. Destroyed
/// without commit() (an exception, an early return), it removes the temporary and `path` keeps
/// its old content.
class AtomicFile {
 public:
  /// Creates the temporary; throws OutputError naming `path` if that fails.
  explicit AtomicFile(std::filesystem::path path);
  ~AtomicFile();
  AtomicFile(AtomicFile&&) noexcept;
  AtomicFile& operator=(AtomicFile&&) noexcept;
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// The stream to write to; usable until commit().
  std::ostream& stream();
  /// Checks every write, flushes and closes the temporary, then renames it over path().
  /// On failure removes the temporary and throws OutputError. Throws std::logic_error if called
  /// twice, or after a failed commit.
  void commit();

  /// The target and the temporary (both undefined on a moved-from AtomicFile).
  const std::filesystem::path& path() const;
  const std::filesystem::path& temporaryPath() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  void discard() noexcept;
  [[noreturn]] void fail(int error);
};

}  // namespace stc
