#pragma once
// The native part of the Python package mesochain (docs/python.md): thin pybind11 bindings over
// the library. One function per area registers its classes and functions on the module.
#include <string>

#include <pybind11/pybind11.h>
#include <toml.hpp>

namespace mesochain::python {

namespace py = pybind11;

// mesochain.InputError / mesochain.NumericalError and the C++ -> Python translation.
void bindErrors(py::module_& m);
// Cell, CellInput, read_cell, cell_input, units.
void bindCells(py::module_& m);
// Calculator, Result, relax.
void bindCalculation(py::module_& m);
// ScanPoint, ScanResult, ScanInput, read_scan, run_scan, scan.
void bindScan(py::module_& m);
// fit_quadratic (the beam fitter).
void bindBeamFit(py::module_& m);
// Scene, load_scene, run_scene (mDEM).
void bindDem(py::module_& m);

// A Python dict (the cell-file layout) as a TOML document; a value of a type TOML cannot hold
// is an InputError naming `source` and the dotted key.
toml::value tomlFromPython(const py::handle& object, const std::string& source,
                           const std::string& key = "");

// The source name used for arguments given from Python ("<python>").
inline const std::string kPythonSource = "<python>";

}  // namespace mesochain::python
