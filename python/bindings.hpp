#pragma once
// The parts of the extension module stcontact._core, each declared on the module by its file;
// python/module.cpp calls them in order. The Python package (python/stcontact/) wraps them
// in its classes; docs/python.md documents the Python side.
#include <pybind11/pybind11.h>

#include <optional>
#include <string>

#include "stcontact/core/threads.hpp"
#include "stcontact/linalg/ranks.hpp"

namespace stc::python {

namespace py = pybind11;

class SceneHandle;

void bindScene(py::module_& module);    ///< scene_binding.cpp: Scene, check, mesh arrays
void bindSolve(py::module_& module);    ///< solve_binding.cpp: solve, IterationRecord, Problem
void bindStudies(py::module_& module);  ///< study_bindings.cpp: svd, compare
void bindRanks(py::module_& module);    ///< ranks_binding.cpp: ranks

/// The MPI ranks of a call (src/linalg/ranks.hpp): started by the first call under a launcher
/// (`mpirun -np N python3 script.py`, a build with PETSc), rank 0 of 1 otherwise. On several ranks
/// each runs one thread, so that the solves of every rank come in one order: `threads` other than 1
/// is refused there (InputError).
Ranks ranksForCall(std::optional<int> threads);
/// InputError on several ranks: `what` runs in one process, as the command line's commands but solve.
void requireOneProcess(const std::string& what);

/// What a pickled scene holds: its text, source and overrides (scene_binding.cpp), from which
/// sceneFromState makes it anew, every check included; the problem is assembled again on first use.
py::tuple sceneState(const SceneHandle& scene);
SceneHandle sceneFromState(const py::tuple& state);

/// The command line's --threads for one call: the STC_THREADS check first (a bad value is refused
/// before anything runs), then `threads` for the call's duration on the calling thread only
/// (stc::ThreadCountScope), which runs the whole call, the lock released or not: concurrent calls
/// from other Python threads keep their own counts, and each summary records its own.
class ThreadsForCall {
 public:
  explicit ThreadsForCall(std::optional<int> threads) {
    threadCount();
    if (threads) scope_.emplace(*threads);
  }

 private:
  std::optional<ThreadCountScope> scope_;
};

}  // namespace stc::python
