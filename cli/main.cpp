// stcontact: the command line (docs/interface.md). Exit status: 0 converged / ok; 1 bad input or usage
// (one "error: ..." line on stderr); 2 ran but did not converge; 3 internal failure; 130 / 143
// stopped by SIGINT / SIGTERM (the output folder as it was before the run).
#include <CLI/CLI.hpp>
#include <malloc.h>

#include <csignal>
#include <iostream>
#include <new>

#include "stcontact/cli/commands.hpp"
#include "stcontact/cli/compare_command.hpp"
#include "stcontact/cli/scaling_command.hpp"
#include "stcontact/cli/stopping_help.hpp"
#include "stcontact/cli/sweep_command.hpp"
#include "stcontact/cli/terminal_progress.hpp"
#include "stcontact/cli/threads_option.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/core/interruption.hpp"
#include "stcontact/core/memory.hpp"
#include "stcontact/io/output_error.hpp"
#include "stcontact/linalg/blas_kernels.hpp"
#include "stcontact/version.hpp"

namespace {

std::string oneLine(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

int fail(int status, const std::string& message) {
  std::cerr << "error: " << oneLine(message) << std::endl;
  return status;
}

/// A run stopped by a signal: whatever it threw on the way out, it wrote nothing (src/io/run_folder.hpp).
int interrupted() {
  const int signal = stc::interruptionSignal();
  std::cerr << "stopped by " << (signal == SIGTERM ? "SIGTERM" : "SIGINT")
            << ": nothing written, the output folder is as it was before the run" << std::endl;
  return 128 + (signal ? signal : SIGINT);
}

// The solvers allocate interface fields (d n_C × m doubles, 0.3 MB on the seed scene) at every stage.
// glibc serves blocks above its mmap threshold (128 kB, raised on the fly up to 32 MB) by mmap and
// returns the heap's free top to the system above its trim threshold, so that each new field costs
// page faults and zeroing: 8 % of a fas-apriori solve of the seed scene (perf), 19 % of its time.
// Fixed thresholds keep freed fields in the heap for the next one (mallopt(3)); results unchanged.
void keepFreedFieldsInTheHeap() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 128 << 20);
}

}  // namespace

int main(int argc, char** argv) {
  keepFreedFieldsInTheHeap();
  stc::stopOnSignals();  // SIGINT, SIGTERM: the solve stops at its next iteration, nothing is written
  stc::linalg::preferFastBlasKernels();
  CLI::App app{"stcontact " STC_VERSION
               ": quasi-static frictional contact over the whole space-time grid (LATIN, FAS, PGD)"};
  app.set_version_flag("--version", std::string("stcontact ") + STC_VERSION);
  app.require_subcommand(1);

  stc::cli::CheckArgs check;
  auto* check_cmd = app.add_subcommand("check", "validate a scene and print the model's sizes");
  check_cmd->add_option("scene", check.scene, "scene file (TOML)")->required();
  check_cmd->add_option("--set", check.overrides, "override a scene value: section.key=value")->take_all();

  stc::cli::SolveArgs solve;
  auto* solve_cmd = app.add_subcommand("solve", "solve a scene and write the results");
  solve_cmd->add_option("scene", solve.scene, "scene file (TOML)")->required();
  solve_cmd->add_option("--solver", solve.solver,
                        "latin | latin-pgd | fas-aposteriori | fas-apriori | incremental (default: the scene's "
                        "[solver] name, else fas-apriori)");
  solve_cmd->add_option("--out", solve.out, "output folder (default results/<scene name>/<solver>)");
  solve_cmd->add_option("--tol", solve.tolerance, stc::cli::toleranceHelp());
  solve_cmd->add_option("--max-iterations", solve.max_iterations, stc::cli::maxIterationsHelp());
  solve_cmd->add_option("--set", solve.overrides, "override a scene value: section.key=value")->take_all();
  solve_cmd->add_flag("--quiet", solve.quiet, "no progress, no final report");
  solve_cmd->add_flag("--no-reference", solve.no_reference,
                      "do not compute the incremental reference (no true error in history.csv)");
  stc::cli::addThreadsOption(*solve_cmd);
  stc::cli::addProgressIntervalOption(*solve_cmd);

  stc::cli::SvdArgs svd;
  auto* svd_cmd = app.add_subcommand("svd", "space-time SVD of the solution in the energy product (verification)");
  svd_cmd->add_option("scene", svd.scene, "scene file (TOML)")->required();
  svd_cmd->add_option("--set", svd.overrides, "override a scene value: section.key=value")->take_all();
  svd_cmd->add_option("--out", svd.out, "output folder (default results/<scene name>/svd)");
  svd_cmd->add_option("--modes", svd.modes, "pairs written to time_functions.csv, modes.vtu, localisation.csv")
      ->capture_default_str();
  svd_cmd->add_option("--solver", svd.solver, "solver of the analysed solution (incremental only)")
      ->capture_default_str();

  stc::cli::CompareArgs compare;
  auto* compare_cmd = stc::cli::addCompareCommand(app, compare);
  stc::cli::addThreadsOption(*compare_cmd);
  stc::cli::addProgressIntervalOption(*compare_cmd);

  stc::cli::SweepArgs sweep;
  auto* sweep_cmd = stc::cli::addSweepCommand(app, sweep);
  stc::cli::addThreadsOption(*sweep_cmd);
  stc::cli::addProgressIntervalOption(*sweep_cmd);
  stc::cli::ScalingArgs scaling;
  auto* scaling_cmd = stc::cli::addScalingCommand(app, scaling);
  stc::cli::addThreadsOption(*scaling_cmd);
  stc::cli::addProgressIntervalOption(*scaling_cmd);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return fail(1, std::string(e.what()) + " (see stcontact --help)");
  } catch (const stc::InputError& e) {  // an option's own check (--threads, --progress-interval)
    return fail(1, e.what());
  }
  try {
    stc::threadCount();  // a bad STC_THREADS is refused before anything is read or written
    if (check_cmd->parsed()) return stc::cli::runCheck(check);
    if (svd_cmd->parsed()) return stc::cli::runSvd(svd);
    if (compare_cmd->parsed()) return stc::cli::runCompare(compare);
    if (sweep_cmd->parsed()) return stc::cli::runSweep(sweep);
    if (scaling_cmd->parsed()) return stc::cli::runScaling(scaling);
    return stc::cli::runSolve(solve);
  } catch (const stc::Interrupted&) {
    return interrupted();
  } catch (const stc::InputError& e) {
    if (stc::interruptionRequested()) return interrupted();
    return fail(1, e.what());
  } catch (const stc::OutputError& e) {
    return fail(1, e.what());
  } catch (const std::bad_alloc&) {
    // The scene's estimate fit (src/problem/size_estimate.hpp), the run needed more: say so, as bad
    // input (its sizes), not as an internal failure.
    return fail(1, "not enough memory: an allocation failed with " + stc::bytesText(stc::availableMemoryBytes()) +
                       " left available; reduce the mesh or the number of instants");
  } catch (const std::exception& e) {
    if (stc::interruptionRequested()) return interrupted();  // e.g. a reference stopped by the signal
    return fail(3, std::string("internal failure: ") + e.what());
  }
}
