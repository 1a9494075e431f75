#include "stcontact/io/run_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include "stcontact/core/interruption.hpp"
#include "stcontact/io/output_error.hpp"

namespace stc {
namespace {

namespace fs = std::filesystem;

std::string reason(int error) { return std::generic_category().message(error); }

[[noreturn]] void fail(const fs::path& target, const std::string& why) {
  throw OutputError("output folder '" + target.string() + "' " + why);
}

[[noreturn]] void cannotCreate(const fs::path& target, const std::string& why) {
  throw OutputError("cannot create output folder '" + target.string() + "': " + why);
}

/// The marker's first line, then "files:" and one path a line.
constexpr const char* kMarkerHeader = "written by stcontact; the next run into this folder replaces the files listed below";
constexpr const char* kFilesLine = "files:";

/// The entry of `target` that a run may not replace ("" when every entry is the marker, a file it
/// lists or a folder of those): the first in the order of a recursive walk, sorted, relative.
std::string firstForeignEntry(const fs::path& target, const std::vector<std::string>& listed) {
  std::vector<std::string> entries;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(target, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec))
    entries.push_back(fs::relative(it->path(), target, ec).generic_string());
  std::sort(entries.begin(), entries.end());
  for (const std::string& entry : entries) {
    if (entry == kRunMarker || std::binary_search(listed.begin(), listed.end(), entry)) continue;
    const std::string folder = entry + "/";  // a folder that holds a listed file
    const auto next = std::lower_bound(listed.begin(), listed.end(), folder);
    const bool holds_listed = next != listed.end() && next->compare(0, folder.size(), folder) == 0;
    std::error_code type;
    if (holds_listed && fs::is_directory(fs::symlink_status(target / entry, type))) continue;
    return entry;
  }
  return "";
}

/// Throws OutputError unless `target` may be replaced: empty, or holding nothing but what its
/// marker lists.
void requireReplaceable(const fs::path& target) {
  std::error_code ec;
  if (fs::is_empty(target, ec)) return;
  const bool marked = fs::exists(target / kRunMarker, ec);
  const std::vector<std::string> listed = listedFiles(target);
  if (marked && listed.empty())
    fail(target, "holds a run marker without the list of the run's files (an older version's, or one "
                 "made by hand): empty the folder or choose another --out");
  const std::string foreign = firstForeignEntry(target, listed);
  if (foreign.empty()) return;
  if (!marked)
    fail(target, "holds files that are not a run's ('" + foreign +
                     "'): choose another --out or empty it (a run replaces its folder as a whole)");
  fail(target, "holds '" + foreign + "', which its run did not write: move it or choose another --out (a run "
               "replaces only the files its marker lists)");
}

/// Every file below `dir`, relative, sorted.
std::vector<std::string> filesBelow(const fs::path& dir) {
  std::vector<std::string> files;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec))
    if (!it->is_directory(ec)) files.push_back(fs::relative(it->path(), dir, ec).generic_string());
  std::sort(files.begin(), files.end());
  return files;
}

/// Removes ".<name>.run-<pid>" siblings whose process is gone (a run killed before its cleanup).
void removeStaleTemporaries(const fs::path& parent, const std::string& name) {
  const std::string prefix = "." + name + ".run-";
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(parent, ec)) {
    const std::string file = entry.path().filename().string();
    if (file.rfind(prefix, 0) != 0) continue;
    const long pid = std::strtol(file.c_str() + prefix.size(), nullptr, 10);
    if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) fs::remove_all(entry.path(), ec);
  }
}

}  // namespace

RunFolder::RunFolder(fs::path target) : target_(std::move(target)) {
  std::error_code ec;
  if (target_.filename().empty()) target_ = target_.parent_path();  // "out/" names "out"
  const std::string given = target_.filename().string();
  if (given.empty() || given == "." || given == "..")
    fail(target_, "cannot be replaced as a whole: give the folder's own name (e.g. results/run1)");
  if (fs::is_symlink(target_, ec)) {  // followed: the folder it names is replaced, never the link
    const fs::path resolved = fs::canonical(target_, ec);
    if (ec) fail(target_, "is a symbolic link to nothing (" + ec.message() + ")");
    target_ = resolved;
  }
  const fs::path parent = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
  fs::create_directories(parent, ec);
  if (ec || !fs::is_directory(parent)) cannotCreate(target_, ec ? ec.message() : "its parent is not a folder");
  if (fs::exists(target_, ec) && !fs::is_directory(target_, ec)) fail(target_, "exists and is not a folder");
  if (fs::exists(target_, ec) && ::access(target_.c_str(), W_OK) != 0)
    fail(target_, "is not writable: a run would replace a folder its owner protected");
  const std::string name = target_.filename().string();
  const fs::path lock_path = parent / ("." + name + ".lock");
  const int fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (fd < 0) cannotCreate(target_, reason(errno));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {  // another run's lock: leave its file alone
    ::close(fd);
    fail(target_, "is being written by another run (its lock " + lock_path.string() + " is held)");
  }
  lock_.path = lock_path;  // from here on, a refusal removes the lock (Lock::~Lock)
  lock_.fd = fd;
  if (fs::exists(target_, ec)) requireReplaceable(target_);
  removeStaleTemporaries(parent, name);
  temporary_ = parent / ("." + name + ".run-" + std::to_string(::getpid()));
  fs::remove_all(temporary_, ec);
  if (!fs::create_directory(temporary_, ec) || ec) cannotCreate(target_, ec.message());
  cleanup_.emplace(std::vector<fs::path>{temporary_, lock_.path});
}

RunFolder::Lock::~Lock() {
  if (fd < 0) return;
  ::unlink(path.c_str());
  ::close(fd);
}

RunFolder::~RunFolder() {
  std::error_code ec;
  if (!committed_ && !temporary_.empty()) fs::remove_all(temporary_, ec);
}

std::string RunFolder::named(std::string text) const {
  const std::string from = temporary_.string(), to = target_.string();
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

void RunFolder::commit() {
  std::error_code ec;
  throwIfInterrupted();  // the destructor discards the temporary
  {
    const std::vector<std::string> files = filesBelow(temporary_);
    std::ofstream marker(temporary_ / kRunMarker);
    marker << kMarkerHeader << '\n' << kFilesLine << '\n';
    for (const std::string& file : files) marker << file << '\n';
    if (!marker) fail(target_, "cannot be written: the marker " + std::string(kRunMarker));
  }
  if (fs::exists(target_, ec)) {
    // One rename swaps the complete new folder in and the previous one out.
    if (::renameat2(AT_FDCWD, temporary_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) != 0)
      fail(target_, "cannot be replaced: " + reason(errno));
    committed_ = true;
    fs::remove_all(temporary_, ec);  // now the previous run
  } else {
    if (::rename(temporary_.c_str(), target_.c_str()) != 0) fail(target_, "cannot be written: " + reason(errno));
    committed_ = true;
  }
}

std::vector<std::string> listedFiles(const fs::path& dir) {
  std::ifstream marker(dir / kRunMarker);
  std::string line;
  if (!std::getline(marker, line) || line != kMarkerHeader) return {};
  if (!std::getline(marker, line) || line != kFilesLine) return {};
  std::vector<std::string> files;
  while (std::getline(marker, line))
    if (!line.empty()) files.push_back(line);
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace stc
