#include "src/cli/compare_plots.hpp"

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

fs::path scriptPath() { return fs::path(STC_PLOT_SCRIPTS) / "work_precision.gp"; }

/// A gnuplot single-quoted string ('' stands for a quote inside).
std::string gnuplotString(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

/// The -e argument: which strategies are curves (with the repeat drawn), which one is the point.
std::string scriptVariables(const Comparison& c, bool with_suffix) {
  std::string curves, repeats, reference;
  for (const StrategyMeasurement& m : c.strategies) {
    if (m.reference_point) {
      reference = m.solver;
      continue;
    }
    if (!curves.empty()) {
      curves += ' ';
      repeats += ' ';
    }
    curves += m.solver;
    repeats += std::to_string(summarize(m).median_repeat);
  }
  std::string vars = "curves=" + gnuplotString(curves) + "; repeats=" + gnuplotString(repeats) +
                     "; reference=" + gnuplotString(reference) + "; scene=" + gnuplotString(c.scene_name);
  if (with_suffix) vars += std::string("; suffix='") + kSuffix + "'";
  return vars;
}

bool onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':'))
    if (::access(((dir.empty() ? std::string(".") : dir) + "/" + program).c_str(), X_OK) == 0) return true;
  return false;
}

/// Runs gnuplot in `dir`, its output into gnuplot.log; returns its exit status (127: not started).
int runGnuplot(const fs::path& dir, const std::string& variables) {
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
    ::execlp("gnuplot", "gnuplot", "-e", variables.c_str(), scriptPath().c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool movePlotsIntoPlace(const fs::path& dir, std::string& warning) {
  for (const std::string& name : workPrecisionPlotNames()) {
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

const std::vector<std::string>& workPrecisionPlotNames() {
  static const std::vector<std::string> names = {"error_vs_time.png", "error_vs_relaxations.png",
                                                 "error_vs_sparse_solves.png"};
  return names;
}

std::string workPrecisionPlotCommand(const Comparison& c) {
  return "gnuplot -e \"" + scriptVariables(c, false) + "\" " + scriptPath().string();
}

bool drawWorkPrecisionPlots(const fs::path& dir, const Comparison& c, std::string& warning) {
  const std::string later = "; draw them later, in " + dir.string() + ", with: " + workPrecisionPlotCommand(c);
  if (!onPath("gnuplot")) {
    warning = "gnuplot is not on PATH: no plot drawn" + later;
    return false;
  }
  if (!fs::exists(scriptPath())) {
    warning = "the plot script " + scriptPath().string() + " is missing: no plot drawn";
    return false;
  }
  const int status = runGnuplot(dir, scriptVariables(c, true));
  std::error_code ignored;
  if (status != 0) {
    for (const auto& name : workPrecisionPlotNames()) fs::remove(dir / (name + kSuffix), ignored);
    warning = "gnuplot failed (exit status " + std::to_string(status) + ", see " + (dir / kLog).string() +
              "): no plot replaced" + later;
    return false;
  }
  fs::remove(dir / kLog, ignored);
  return movePlotsIntoPlace(dir, warning);
}

}  // namespace stc::cli
