#include "stcontact/studies/gnuplot_runner.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <utility>

namespace stc {
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

/// Runs gnuplot in `dir` (its output into gnuplot.log when `log`); returns its exit status
/// (127: not started, −1: killed).
int runGnuplot(const fs::path& dir, const fs::path& script, const std::string& variables, bool log) {
  std::fflush(nullptr);  // no buffered output duplicated by the child
  const pid_t pid = ::fork();
  if (pid < 0) return 127;
  if (pid == 0) {
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    const int file = log ? ::open(kLog, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644) : -1;
    if (file >= 0) {
      ::dup2(file, STDOUT_FILENO);
      ::dup2(file, STDERR_FILENO);
    }
    ::execlp("gnuplot", "gnuplot", "-e", variables.c_str(), script.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string withSuffix(const std::string& variables) {
  const std::string suffix = std::string("suffix='") + kSuffix + "'";
  return variables.empty() ? suffix : variables + "; " + suffix;
}

}  // namespace

std::string gnuplotString(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string plotCommand(const PlotJob& job) {
  if (job.variables.empty()) return "gnuplot " + job.script.string();
  return "gnuplot -e \"" + job.variables + "\" " + job.script.string();
}

PlotOutcome runPlots(const fs::path& dir, const PlotJob& job) {
  if (!onPath("gnuplot")) return {PlotStatus::GnuplotMissing, 0, ""};
  if (!fs::exists(job.script.is_absolute() ? job.script : dir / job.script)) return {PlotStatus::ScriptMissing, 0, ""};
  const int status = runGnuplot(dir, job.script, withSuffix(job.variables), job.log);
  std::error_code ignored;
  if (status != 0) {
    for (const auto& name : job.outputs) fs::remove(dir / (name + kSuffix), ignored);
    return {PlotStatus::GnuplotFailed, status, ""};
  }
  if (job.log) fs::remove(dir / kLog, ignored);
  for (const std::string& name : job.outputs) {
    std::error_code error;
    fs::rename(dir / (name + kSuffix), dir / name, error);
    if (error)
      return {PlotStatus::NotMoved, 0,
              "could not move " + (dir / (name + kSuffix)).string() + " into place: " + error.message()};
  }
  return {};
}

bool drawPlots(const fs::path& dir, const PlotJob& job, std::string& warning) {
  const std::string later = "; draw them later, in " + dir.string() + ", with: " + plotCommand(job);
  const PlotOutcome outcome = runPlots(dir, job);
  switch (outcome.status) {
    case PlotStatus::Drawn: return true;
    case PlotStatus::GnuplotMissing: warning = "gnuplot is not on PATH: no plot drawn" + later; break;
    case PlotStatus::ScriptMissing:
      warning = "the plot script " + job.script.string() + " is missing: no plot drawn";
      break;
    case PlotStatus::GnuplotFailed:
      warning = "gnuplot failed (exit status " + std::to_string(outcome.exit_status) + ", see " +
                (dir / kLog).string() + "): no plot replaced" + later;
      break;
    case PlotStatus::NotMoved: warning = outcome.detail; break;
  }
  return false;
}

PlotJob reportPlotJob(const std::string& script, std::string variables, std::vector<std::string> outputs) {
  return {std::filesystem::path(STC_PLOT_SCRIPTS) / script, std::move(variables), std::move(outputs)};
}

}  // namespace stc
