#pragma once
// Results handed to NumPy without a second copy: the array takes ownership of the C++ storage (a
// capsule deletes it with the array), so a d n_C × m force history or an n × m displacement history
// exists once. Eigen matrices keep their column-major layout (NumPy order 'F'): column k is instant
// t_k, contiguous, and rows 0::2 / 1::2 are strided views, not copies.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <utility>
#include <vector>

namespace stc::python {

namespace py = pybind11;

/// The matrix moved into a NumPy array (pybind11's Eigen caster moves an rvalue into a capsule).
inline py::array movedToNumpy(Eigen::MatrixXd&& matrix) {
  return py::reinterpret_steal<py::array>(py::cast(std::move(matrix)).release());
}
inline py::array movedToNumpy(Eigen::MatrixXi&& matrix) {
  return py::reinterpret_steal<py::array>(py::cast(std::move(matrix)).release());
}
inline py::array movedToNumpy(Eigen::VectorXd&& vector) {
  return py::reinterpret_steal<py::array>(py::cast(std::move(vector)).release());
}

/// The vector moved into a one-dimensional NumPy array.
template <class T>
py::array_t<T> movedToNumpy(std::vector<T>&& values) {
  if (values.empty()) return py::array_t<T>(0);
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(static_cast<py::ssize_t>(owned->size()), owned->data(), owner);
}

}  // namespace stc::python
