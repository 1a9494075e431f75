#pragma once
// A request to stop the run, from a signal (SIGINT, SIGTERM: the program installs the handlers,
// cli/main.cpp) or from a caller: solves stop at their next iteration through their progress
// callback, the run folder is not committed (src/io/run_folder.hpp), and the program exits
// 128 + the signal's number (130, 143) with a message. A flag set from a signal handler: lock-free.
#include <stdexcept>
#include <string>

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

/// Installs requestInterruption as the handler of SIGINT and SIGTERM.
void stopOnSignals();

}  // namespace stc
