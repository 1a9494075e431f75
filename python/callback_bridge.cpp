#include "stcontact/python/callback_bridge.hpp"

#include <cmath>
#include <string>

#include <utility>

namespace stc::python {

CallbackBridge::CallbackBridge(py::object callback) : callback_(std::move(callback)) {
  if (!callback_.is_none() && !PyCallable_Check(callback_.ptr()))
    throw py::type_error("callback must be callable (record) -> bool, or None");
}

IterationCallback CallbackBridge::withUserCallback() {
  return [this](const IterationRecord& record) { return keepGoing(&record); };
}

IterationCallback CallbackBridge::signalsOnly() {
  return [this](const IterationRecord&) { return keepGoing(nullptr); };
}

std::function<bool()> CallbackBridge::stopProbe() {
  return [this] { return keepGoing(nullptr); };
}

bool CallbackBridge::keepGoing(const IterationRecord* record) {
  py::gil_scoped_acquire lock;
  if (pending_) return false;
  try {
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (!record || callback_.is_none()) return true;
    const py::object answer = callback_(*record);
    if (answer.is_none()) return true;
    // NaN is true to Python: a callback whose test went NaN would go on silently.
    if (PyFloat_Check(answer.ptr()) && !std::isfinite(PyFloat_AsDouble(answer.ptr()))) {
      const std::string message = "callback returned " + std::string(py::str(answer)) +
                                  ": return True to go on, False to stop (or None)";
      PyErr_SetString(PyExc_ValueError, message.c_str());
      throw py::error_already_set();
    }
    const int truth = PyObject_IsTrue(answer.ptr());
    if (truth < 0) throw py::error_already_set();
    return truth == 1;
  } catch (py::error_already_set& error) {
    pending_.emplace(std::move(error));
    return false;
  }
}

void CallbackBridge::rethrowPending() {
  if (!pending_) return;
  py::error_already_set error = std::move(*pending_);
  pending_.reset();
  throw error;
}

}  // namespace stc::python
