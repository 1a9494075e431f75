#include "src/cli/gnuplot_runner.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace stc::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSuffix = ".tmp";  // the script writes NAME.png.tmp, moved into place on success
constexpr const char* kLog = "gnuplot.log";

bool onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':'))
    if (::access(((dir.empty() ? std::string(".") : dir) + "/" + program).c_str(), X_OK) == 0) return true;
  return false;
}

/// Runs gnuplot in `dir`, its output into gnuplot.log; returns its exit status (127: not started).
int runGnuplot(const fs::path& dir, const fs::path& script, const std::string& variables) {
  std::fflush(nullptr);  // no buffered output duplicated by the child
  const pid_t pid = ::fork();
  if (pid < 0) return 127;
  if (pid == 0) {
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    const int log = ::open(kLog, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (log >= 0) {
      ::dup2(log, STDOUT_FILENO);
      ::dup2(log, STDERR_FILENO);
    }
    ::execlp("gnuplot", "gnuplot", "-e", variables.c_str(), script.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool movePlotsIntoPlace(const fs::path& dir, const std::vector<std::string>& outputs, std::string& warning) {
  for (const std::string& name : outputs) {
    std::error_code error;
    fs::rename(dir / (name + kSuffix), dir / name, error);
    if (error) {
      warning = "could not move " + (dir / (name + kSuffix)).string() + " into place: " + error.message();
      return false;
    }
  }
  return true;
}

}  // namespace

std::string gnuplotString(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

fs::path plotScript(const std::string& name) { return fs::path(STC_PLOT_SCRIPTS) / name; }

std::string gnuplotCommand(const fs::path& script, const std::string& variables) {
  return "gnuplot -e \"" + variables + "\" " + script.string();
}

bool drawPlots(const fs::path& dir, const fs::path& script, const std::string& variables,
               const std::vector<std::string>& outputs, std::string& warning) {
  const std::string later = "; draw them later, in " + dir.string() + ", with: " + gnuplotCommand(script, variables);
  if (!onPath("gnuplot")) {
    warning = "gnuplot is not on PATH: no plot drawn" + later;
    return false;
  }
  if (!fs::exists(script)) {
    warning = "the plot script " + script.string() + " is missing: no plot drawn";
    return false;
  }
  const int status = runGnuplot(dir, script, variables + std::string("; suffix='") + kSuffix + "'");
  std::error_code ignored;
  if (status != 0) {
    for (const auto& name : outputs) fs::remove(dir / (name + kSuffix), ignored);
    warning = "gnuplot failed (exit status " + std::to_string(status) + ", see " + (dir / kLog).string() +
              "): no plot replaced" + later;
    return false;
  }
  fs::remove(dir / kLog, ignored);
  return movePlotsIntoPlace(dir, outputs, warning);
}

}  // namespace stc::cli
