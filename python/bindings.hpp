#pragma once
// The parts of the extension module stcontact._core, each declared on the module by its file;
// python/module.cpp calls them in order. The Python package (python/stcontact/) wraps them
// in its classes; docs/python.md documents the Python side.
#include <pybind11/pybind11.h>

#include <optional>

#include "stcontact/core/threads.hpp"

namespace stc::python {

namespace py = pybind11;

class SceneHandle;

void bindScene(py::module_& module);    ///< scene_binding.cpp: Scene, check, mesh arrays
void bindSolve(py::module_& module);    ///< solve_binding.cpp: solve, IterationRecord, Problem
void bindStudies(py::module_& module);  ///< study_bindings.cpp: svd, compare

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
