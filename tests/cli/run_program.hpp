#pragma once
// How the end-to-end tests run the program: `stcontact SUBCOMMAND` on the seed scene at small
// settings (arc_nodes 21, 21 instants), its report into DIR/report and its stderr into
// DIR/stderr.txt.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace stc::test {

/// A scratch folder of this process (ctest runs each test in its own process, possibly in parallel).
inline std::filesystem::path scratchFolder(const std::string& name) {
  return std::filesystem::path(STC_BINARY_DIR) / "test_report_scratch" / (name + "_" + std::to_string(::getpid()));
}

/// Empties `dir`, runs `stcontact SUBCOMMAND SEED --set ... OPTIONS --quiet --out DIR/report`;
/// returns its exit status (-1: it did not exit).
inline int runOnSmallSeed(const std::string& subcommand, const std::string& options, const std::filesystem::path& dir) {
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string command = "'" STC_BINARY_DIR "/bin/stcontact' " + subcommand + " '" STC_SOURCE_DIR
                              "/examples/scenes/hemicylinder.toml' --set mesh.arc_nodes=21 --set time.steps=21 " +
                              options + " --quiet --out '" + (dir / "report").string() + "' 2> '" +
                              (dir / "stderr.txt").string() + "'";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace stc::test
