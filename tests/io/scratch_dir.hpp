#pragma once
// Helpers for tests/io: a fresh folder per test in the build tree (removed afterwards), whole-file
// reads, and python3 (when installed) as an independent parser of what the writers produce.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace stc::iotest {

namespace fs = std::filesystem;

/// build/test_io_scratch/<Suite>.<Test>, empty at construction, removed at destruction.
class ScratchDir {
 public:
  ScratchDir() {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::path(STC_BINARY_DIR) / "test_io_scratch" /
            (std::string(test->test_suite_name()) + "." + test->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }

  /// Names of the entries in the folder (hidden ones included), sorted.
  std::vector<std::string> names() const {
    std::vector<std::string> result;
    for (const auto& entry : fs::directory_iterator(path_))
      result.push_back(entry.path().filename().string());
    std::sort(result.begin(), result.end());
    return result;
  }

 private:
  fs::path path_;
};

inline std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void writePlainFile(const fs::path& path, const std::string& content) {
  std::ofstream(path, std::ios::binary) << content;
}

/// Exit status of `python3 -c code args...` (`code` without single quotes); 127 when the shell
/// finds no python3, which tests turn into a skip.
inline int runPython(const std::string& code, const std::vector<fs::path>& args) {
  std::string command = "python3 -c '" + code + "'";
  for (const fs::path& arg : args) command += " '" + arg.string() + "'";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

constexpr int kNoPython = 127;

}  // namespace stc::iotest
