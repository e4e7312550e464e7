#pragma once
// Eigen 3 x N columns <-> NumPy (N, 3) rows (the layout of ASE and of most Python codes).
#include <string>

#include <Eigen/Dense>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "common/errors.hpp"

namespace mesochain::python {

namespace py = pybind11;

inline py::array_t<double> rowsFromColumns(const Eigen::Matrix3Xd& m) {
  py::array_t<double> out({static_cast<py::ssize_t>(m.cols()), py::ssize_t{3}});
  auto a = out.mutable_unchecked<2>();
  for (Eigen::Index j = 0; j < m.cols(); ++j)
    for (int k = 0; k < 3; ++k) a(j, k) = m(k, j);
  return out;
}

// An (N, 3) array of finite numbers; `rows` = N unless negative (any N). InputError naming
// `argument` otherwise.
inline Eigen::Matrix3Xd columnsFromRows(const py::handle& object, long rows, const std::string& source,
                                        const std::string& argument) {
  py::array_t<double, py::array::c_style | py::array::forcecast> a;
  try {
    a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(object);
  } catch (const py::error_already_set&) {
  }
  const std::string expected =
      rows < 0 ? "an array of shape (N, 3)" : "an array of shape (" + std::to_string(rows) + ", 3)";
  if (!a) throw InputError(source, "argument " + argument, "something that is not a numeric array", expected);
  if (a.ndim() != 2 || a.shape(1) != 3 || (rows >= 0 && a.shape(0) != rows)) {
    std::string shape = "(";
    for (py::ssize_t d = 0; d < a.ndim(); ++d) shape += (d ? ", " : "") + std::to_string(a.shape(d));
    throw InputError(source, "argument " + argument, "an array of shape " + shape + (a.ndim() == 1 ? ",)" : ")"),
                     expected);
  }
  Eigen::Matrix3Xd m(3, a.shape(0));
  auto r = a.unchecked<2>();
  for (py::ssize_t j = 0; j < a.shape(0); ++j)
    for (int k = 0; k < 3; ++k) {
      m(k, j) = r(j, k);
      requireFinite(m(k, j), source, "argument " + argument);
    }
  return m;
}

}  // namespace mesochain::python
