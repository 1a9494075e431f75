// stcontact: the command line (docs/interface.md). Exit status: 0 converged / ok; 1 bad input or usage
// (one "error: ..." line on stderr); 2 ran but did not converge; 3 internal failure; 130 / 143 / 129
// stopped by SIGINT / SIGTERM / SIGHUP (the output folder as it was before the run).
#include <CLI/CLI.hpp>
#include <malloc.h>

#include <csignal>
#include <functional>
#include <iostream>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "stcontact/cli/commands.hpp"
#include "stcontact/cli/compare_command.hpp"
#include "stcontact/cli/scaling_command.hpp"
#include "stcontact/cli/sweep_command.hpp"
#include "stcontact/cli/true_error_command.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/core/interruption.hpp"
#include "stcontact/core/memory.hpp"
#include "stcontact/core/threads.hpp"
#include "stcontact/io/output_error.hpp"
#include "stcontact/linalg/blas_kernels.hpp"
#include "stcontact/linalg/ranks.hpp"
#include "stcontact/linalg/spd_solver.hpp"
#include "stcontact/version.hpp"

namespace {

std::string oneLine(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

// On several ranks, rank 0 alone says it (every rank meets the same error).
int fail(int status, const std::string& message) {
  if (stc::currentRanks().writes()) std::cerr << "error: " << oneLine(message) << std::endl;
  return status;
}

/// A run stopped by a signal: whatever it threw on the way out, it wrote nothing (src/io/run_folder.hpp).
int interrupted() { return stc::reportStopAndExitStatus(); }

// The solvers allocate interface fields (d n_C × m doubles, 0.3 MB on the seed scene) at every stage.
// glibc serves blocks above its mmap threshold (128 kB, raised on the fly up to 32 MB) by mmap and
// returns the heap's free top to the system above its trim threshold, so that each new field costs
// page faults and zeroing: 8 % of a fas-apriori solve of the seed scene (perf), 19 % of its time.
// Fixed thresholds keep freed fields in the heap for the next one (mallopt(3)); results unchanged.
// The trim threshold bounds the free top the heap keeps: on long histories a field is tens of MB
// (591 rows × 10 001 instants, 47 MB, on the fretting history at divisions 16), and at 128 MiB a
// fas-apriori solve there gave 7 GB back to the system and faulted it in again (2.1 million page
// faults, 3 s of system time); at 512 MiB it keeps them (0.95 million, the solve 7 % faster). The
// free top kept can raise a run's peak: the incremental solver's by 112 MB at 2001 instants there,
// none at 10 001 (docs/threads.md, "Memory of long histories").
void keepFreedFieldsInTheHeap() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
}

}  // namespace

int main(int argc, char** argv) {
  keepFreedFieldsInTheHeap();
  stc::stopOnSignals();  // SIGINT, SIGTERM, SIGHUP: the run stops, nothing is written (first: no thread yet)
  stc::linalg::preferFastBlasKernels();
  CLI::App app{"stcontact " STC_VERSION
               ": quasi-static frictional contact over the whole space-time grid (LATIN, FAS, PGD)"};
  app.set_version_flag("--version", std::string("stcontact ") + STC_VERSION);
  app.require_subcommand(1);

  // Every sub-command, declared by its addXCommand and run by its runX (cli/commands.hpp).
  stc::cli::CheckArgs check;
  stc::cli::SolveArgs solve;
  stc::cli::SvdArgs svd;
  stc::cli::CompareArgs compare;
  stc::cli::SweepArgs sweep;
  stc::cli::ScalingArgs scaling;
  stc::cli::TrueErrorArgs true_error;
  const std::vector<std::pair<CLI::App*, std::function<int()>>> commands = {
      {stc::cli::addCheckCommand(app, check), [&] { return stc::cli::runCheck(check); }},
      {stc::cli::addSolveCommand(app, solve), [&] { return stc::cli::runSolve(solve); }},
      {stc::cli::addSvdCommand(app, svd), [&] { return stc::cli::runSvd(svd); }},
      {stc::cli::addCompareCommand(app, compare), [&] { return stc::cli::runCompare(compare); }},
      {stc::cli::addSweepCommand(app, sweep), [&] { return stc::cli::runSweep(sweep); }},
      {stc::cli::addScalingCommand(app, scaling), [&] { return stc::cli::runScaling(scaling); }},
      {stc::cli::addTrueErrorCommand(app, true_error), [&] { return stc::cli::runTrueError(true_error); }},
  };

  // CLI11 says only "A subcommand is required" for a word it does not know: name it and the commands.
  if (argc > 1 && argv[1][0] != '-') {
    std::string known;
    bool found = false;
    for (const auto& [command, run] : commands) {
      known += (known.empty() ? "" : ", ") + command->get_name();
      found = found || command->get_name() == argv[1];
    }
    if (!found)
      return fail(1, "unknown command '" + std::string(argv[1]) + "' (the commands: " + known + "; see stcontact --help)");
  }
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
    const stc::Ranks ranks = stc::startRanks();  // under an MPI launcher: one of its ranks
    if (ranks.size > 1 && !app.got_subcommand("solve"))
      return fail(1, "only 'solve' runs on several MPI ranks (started as " + std::to_string(ranks.size) + ")");
    for (const auto& [command, run] : commands)
      if (command->parsed()) return run();
    return fail(3, "internal failure: no sub-command parsed");  // require_subcommand(1) rules it out
  } catch (const stc::Interrupted&) {
    return interrupted();
  } catch (const stc::InputError& e) {
    if (stc::interruptionRequested()) return interrupted();
    return fail(1, e.what());
  } catch (const stc::OutputError& e) {
    return fail(1, e.what());
  } catch (const stc::LinearSolveFailure& e) {
    // An iterative backend's solve outside a strategy (the frames of the writer): no output.
    return fail(2, std::string("numerical issue: ") + e.what());
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
