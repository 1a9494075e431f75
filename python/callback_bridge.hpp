#pragma once
// The solvers' per-iteration callback (stc::IterationCallback) during a solve that runs with the
// interpreter's lock released: at each record it takes the lock back briefly, lets Python run its
// signal handlers (PyErr_CheckSignals: Ctrl-C raises KeyboardInterrupt there), then calls the
// user's callback(record), if any. A pending exception, or a callback that returns False, stops
// the solve (Termination::StoppedByCallback); after the solve, with the lock held again,
// rethrowPending() raises the exception (KeyboardInterrupt, or whatever the callback raised).
#include <pybind11/pybind11.h>

#include <functional>
#include <optional>

#include "stcontact/core/interruption.hpp"
#include "stcontact/solver/solve_summary.hpp"

namespace stc::python {

namespace py = pybind11;

class CallbackBridge {
 public:
  /// `callback`: None or a callable taking an IterationRecord; its answer stops the solve when
  /// it is false (None counts as "go on"). Construct with the lock held.
  explicit CallbackBridge(py::object callback = py::none());

  /// Signals, then the user's callback: for the solve the user asked for.
  IterationCallback withUserCallback();
  /// Signals only: for the solves the call makes on the way (the incremental reference).
  IterationCallback signalsOnly();
  /// Signals only, with no record: the StopProbe (src/core/interruption.hpp) a call holds while it
  /// solves, asked between the parts of what makes no record (a first relaxation's directions, a
  /// sub-grid of instants, the Delassus columns), which then throw stc::Interrupted.
  std::function<bool()> stopProbe();

  /// Runs `work` (the lock released by the caller) with stopProbe() held: false when Ctrl-C stopped it
  /// between the parts of a phase without records (stc::Interrupted), its KeyboardInterrupt pending
  /// for rethrowPending(); an Interrupted the bridge did not ask for goes on up.
  template <class Work>
  bool runStoppable(Work&& work) {
    const StopProbe probe(stopProbe());
    try {
      work();
      return true;
    } catch (const Interrupted&) {
      if (!interrupted()) throw;
      return false;
    }
  }

  /// True once an exception is pending (later solves of the same call should not start).
  bool interrupted() const { return pending_.has_value(); }
  /// Raises the pending exception, if any. Call with the lock held.
  void rethrowPending();

 private:
  bool keepGoing(const IterationRecord* record);  // record null: signals only

  py::object callback_;
  std::optional<py::error_already_set> pending_;
};

}  // namespace stc::python
