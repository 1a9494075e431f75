// The extension module stcontact._core (pybind11). Bad input (stc::InputError) becomes
// stcontact.InputError, a ValueError whose message is the command line's "error:" line without
// its prefix (cli/main.cpp); a scene or mesh file that does not exist (stc::MissingFileError),
// FileNotFoundError(ENOENT, that message, the path) as open() raises it; an output folder that cannot
// be written (stc::OutputError), an OSError with the same message.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cerrno>

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/missing_file_error.hpp"
#include "stcontact/io/output_error.hpp"
#include "stcontact/linalg/blas_kernels.hpp"
#include "stcontact/options/strategy.hpp"
#include "stcontact/python/bindings.hpp"
#include "stcontact/version.hpp"

namespace {

namespace py = pybind11;

/// The message on one line, as cli/main.cpp prints it.
std::string oneLine(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

}  // namespace

PYBIND11_MODULE(_core, module) {
  module.doc() = "stcontact's compiled core; use the package stcontact (docs/python.md).";
  module.attr("__version__") = STC_VERSION;
  // OpenBLAS's kernels for this processor where Debian's falls back to generic ones
  // (src/linalg/blas_kernels.hpp); NumPy shares the process's OpenBLAS when it was built on it.
  module.attr("blas_kernels") = stc::linalg::preferFastBlasKernels();
  static py::exception<stc::InputError> input_error(module, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const stc::MissingFileError& e) {
      const py::object error = py::handle(PyExc_FileNotFoundError)(ENOENT, oneLine(e.what()), e.path());
      PyErr_SetObject(PyExc_FileNotFoundError, error.ptr());
    } catch (const stc::InputError& e) {
      input_error(oneLine(e.what()).c_str());
    } catch (const stc::OutputError& e) {
      PyErr_SetString(PyExc_OSError, oneLine(e.what()).c_str());
    }
  });
  module.def("available_solvers", &stc::strategyNames, "The strategies solve() and compare() accept.");
  stc::python::bindScene(module);
  stc::python::bindSolve(module);
  stc::python::bindStudies(module);
  stc::python::bindRanks(module);
}
