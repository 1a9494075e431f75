#include "stcontact/io/run_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <string>
#include <system_error>

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

/// A folder the run may replace: empty, or a run's (its marker, or an older version's summary).
bool replaceable(const fs::path& target) {
  std::error_code ec;
  if (fs::is_empty(target, ec)) return true;
  for (const char* mark : {kRunMarker, "summary.json", "summary.md", "svd_summary.json"})
    if (fs::exists(target / mark, ec)) return true;
  return false;
}

/// The first entry of `dir`, for the message that refuses it.
std::string firstEntry(const fs::path& dir) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) return entry.path().filename().string();
  return "?";
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
  const fs::path parent = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
  fs::create_directories(parent, ec);
  if (ec || !fs::is_directory(parent)) cannotCreate(target_, ec ? ec.message() : "its parent is not a folder");
  if (fs::exists(target_, ec) && !fs::is_directory(target_, ec)) fail(target_, "exists and is not a folder");
  const std::string name = target_.filename().string();
  lock_path_ = parent / ("." + name + ".lock");
  lock_fd_ = ::open(lock_path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (lock_fd_ < 0) cannotCreate(target_, reason(errno));
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(lock_fd_);
    lock_fd_ = -1;
    fail(target_, "is being written by another run (its lock " + lock_path_.string() + " is held)");
  }
  if (fs::exists(target_, ec) && !replaceable(target_))
    fail(target_, "holds files that are not a run's ('" + firstEntry(target_) +
                      "'): choose another --out or empty it (a run replaces its folder as a whole)");
  removeStaleTemporaries(parent, name);
  temporary_ = parent / ("." + name + ".run-" + std::to_string(::getpid()));
  fs::remove_all(temporary_, ec);
  if (!fs::create_directory(temporary_, ec) || ec) cannotCreate(target_, ec.message());
}

RunFolder::~RunFolder() {
  std::error_code ec;
  if (!committed_) fs::remove_all(temporary_, ec);
  if (lock_fd_ >= 0) {
    ::unlink(lock_path_.c_str());
    ::close(lock_fd_);
  }
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
    std::ofstream marker(temporary_ / kRunMarker);
    marker << "written by stcontact; the next run into this folder replaces it\n";
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

}  // namespace stc
