#pragma once
// A request to stop the run, from a signal (SIGINT, SIGTERM, SIGHUP: the program asks for them,
// stopOnSignals) or from a caller: solves stop at their next iteration through their progress
// callback, the run folder is not committed (src/io/run_folder.hpp), and the program exits
// 128 + the signal's number (130, 143, 129) with a message.
// What runs no iteration (reading a scene or a mesh, assembling, factorising, writing) sees the
// request too: a thread of the program waits for the signals and, when the run has not ended within
// kStopGrace of one, removes what the run registered (its temporary folder, its lock: StopCleanup)
// and ends the process with the same status and message. So a run stops at any moment, and leaves
// its output folder as it was.
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace stc {

/// Thrown where a run stops because a stop was requested (src/io/run_folder.hpp before it commits):
/// the program reports it and exits 128 + the signal.
class Interrupted : public std::runtime_error {
 public:
  Interrupted() : std::runtime_error("interrupted") {}
};

/// Throws Interrupted when a stop was requested.
void throwIfInterrupted();

/// Records a request to stop (async-signal-safe); `signal` is 0 for a caller's request.
void requestInterruption(int signal) noexcept;
/// Forgets a request (a caller that handled it and goes on: the next runs are not stopped).
void clearInterruption() noexcept;
/// Whether a stop was requested.
bool interruptionRequested() noexcept;
/// The signal of the request (0: a caller's, or none).
int interruptionSignal() noexcept;

/// A caller's own stop for the phases of a solve that make no iteration record and so never ask its
/// callback (a first relaxation's new directions, solved for minutes at 10⁶ dofs; the sub-grid of
/// nested iteration in time; the incremental solver's Delassus columns): while a StopProbe lives,
/// keepGoing() on the thread that made it asks `keep_going` too. The Python module's probe answers
/// false once Ctrl-C was pressed (python/callback_bridge.hpp). Scopes nest: the previous probe comes
/// back when one ends.
class StopProbe {
 public:
  explicit StopProbe(std::function<bool()> keep_going);
  ~StopProbe();
  StopProbe(const StopProbe&) = delete;
  StopProbe& operator=(const StopProbe&) = delete;

 private:
  std::function<bool()> previous_;
};

/// Whether the run may go on: no stop requested, and the calling thread's StopProbe, if any, agrees.
bool keepGoing();
/// Throws Interrupted unless keepGoing(): where a phase that makes no iteration record may stop,
/// between its parts. The caller catches it (the program: exit 128 + the signal, nothing written;
/// the Python module: KeyboardInterrupt).
void stopPoint();

/// Seconds a run has, after a signal, to stop on its own before the process ends it.
inline constexpr double kStopGrace = 1.0;

/// Takes SIGINT, SIGTERM and SIGHUP for the process: blocked in every thread, and waited for by a
/// thread of their own that requests the stop and, after kStopGrace, ends the process (header).
/// Call first in main, before any other thread starts (they inherit the blocked signals).
void stopOnSignals();

/// The one message and exit status of a run stopped by a signal: prints "stopped by SIG...: nothing
/// written, ..." and returns 128 + the signal. Called by whichever comes first, the run that saw the
/// request or the signals' thread; the other waits for the process to end.
int reportStopAndExitStatus();

/// Paths removed if the process is ended after a signal (StopCleanup's lifetime: registered while
/// the object lives). A run folder registers its temporary folder and its lock.
class StopCleanup {
 public:
  StopCleanup() = default;
  explicit StopCleanup(std::vector<std::filesystem::path> paths);
  ~StopCleanup();
  StopCleanup(const StopCleanup&) = delete;
  StopCleanup& operator=(const StopCleanup&) = delete;

 private:
  long id_ = -1;
};

}  // namespace stc
