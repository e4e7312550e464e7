// PYBIND11_MODULE(_mesochain): the native extension behind the Python package mesochain.
#include "python/src/bindings.hpp"

PYBIND11_MODULE(_mesochain, m) {
  m.doc() =
      "Native part of mesochain: objective cells, the DFTB calculator and relaxation, in the "
      "library's atomic units (Bohr, Hartree, radians). See docs/python.md.";
  mesochain::python::bindErrors(m);
  mesochain::python::bindCells(m);
  mesochain::python::bindCalculation(m);
  mesochain::python::bindScan(m);
  mesochain::python::bindBeamFit(m);
  mesochain::python::bindDem(m);
}
