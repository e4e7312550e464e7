// mesochain.read_scan / run_scan / scan: deformation scans (objective::runScan) from a scan file
// (objective::readScanFile, docs/scan-file.md) or from a cell input and a list of deformations,
// and their curve (objective::scanCurveJson) as a dict or files.
#include <pybind11/stl.h>

#include "common/errors.hpp"
#include "input/cell_calculator.hpp"
#include "objective/drivers/scan.hpp"
#include "input/scan_file.hpp"
#include "input/scan_output.hpp"
#include "python/src/bindings.hpp"

namespace mesochain::python {

namespace {

using objective::ScanResult;

ScanResult runScanInput(const objective::ScanInput& in, bool resume, int stopAfter) {
  objective::ScanSettings s = in.settings;
  s.resume = resume;
  s.stopAfter = stopAfter;
  s.progressBar = false;
  py::gil_scoped_release release;
  return objective::runScan(in.cell.cell, objective::loadParameters(in.cell),
                            objective::calculatorSettings(in.cell), s,
                            parallel::Communicator::serial());  // Python: one rank
}

ScanResult scanCell(const objective::CellInput& in, const std::string& kind, std::vector<double> values,
                    std::vector<int> rotationOrders, const std::string& direction, double forceTolerance,
                    long maxSteps, bool relaxTranslation, std::optional<int> ringAngular) {
  const std::string& src = kPythonSource;
  objective::ScanSettings s;
  if (kind == "stretch") s.kind = objective::ScanKind::Stretch;
  else if (kind == "twist") s.kind = objective::ScanKind::Twist;
  else if (kind == "bend") s.kind = objective::ScanKind::Bend;
  else throw InputError(src, "argument kind", "'" + kind + "'", "'stretch', 'twist' or 'bend'");
  const bool bend = s.kind == objective::ScanKind::Bend;
  if (bend ? !values.empty() : !rotationOrders.empty())
    throw InputError(src, bend ? "argument values" : "argument rotation_orders",
                     "a list for kind '" + kind + "'",
                     bend ? "rotation_orders only (the ring sizes N_a)" : "values only (strains or rad per cell)");
  if (!bend && direction != "soft")
    throw InputError(src, "argument direction", "'" + direction + "' with kind '" + kind + "'", "direction only with kind 'bend'");
  if (direction != "soft" && direction != "hard")
    throw InputError(src, "argument direction", "'" + direction + "'", "'soft' or 'hard'");
  s.direction = direction == "hard" ? objective::BendDirection::Hard : objective::BendDirection::Soft;
  s.values = std::move(values);
  s.rotationOrders = std::move(rotationOrders);
  if (!(forceTolerance > 0))
    throw InputError(src, "argument force_tolerance", std::to_string(forceTolerance), "a positive force (Ha/Bohr)");
  if (maxSteps < 1 || maxSteps > 100000000L)
    throw InputError(src, "argument max_steps", std::to_string(maxSteps), "an integer from 1 to 100000000");
  s.relax.forceTolerance = forceTolerance;
  s.relax.axialTolerance = forceTolerance;  // as the scan file
  s.relax.maxSteps = static_cast<int>(maxSteps);
  s.relax.relaxTranslation = relaxTranslation;
  if (ringAngular) {
    if (!bend) throw InputError(src, "argument ring_angular", "a value with kind '" + kind + "'", "ring_angular only with kind 'bend'");
    if (*ringAngular < 0) throw InputError(src, "argument ring_angular", std::to_string(*ringAngular), "0 (all) or a number of samples >= 1");
    s.ringAngular.samples = *ringAngular;
  }
  s.progressBar = false;
  py::gil_scoped_release release;
  return objective::runScan(in.cell, objective::loadParameters(in), objective::calculatorSettings(in), s,
                            parallel::Communicator::serial());  // Python: one rank
}

py::object curveDict(const ScanResult& r) {
  return py::module_::import("json").attr("loads")(objective::scanCurveJson(r).dump());
}

}  // namespace

void bindScan(py::module_& m) {
  py::class_<objective::ScanPoint>(m, "ScanPoint")
      .def_readonly("deformation", &objective::ScanPoint::deformation, "strain, rad per cell or 1/Bohr")
      .def_readonly("rotation_order", &objective::ScanPoint::rotationOrder)
      .def_readonly("energy", &objective::ScanPoint::energy, "Mermin free energy per objective cell (Hartree)")
      .def_readonly("converged", &objective::ScanPoint::converged)
      .def_readonly("max_force", &objective::ScanPoint::maxForce)
      .def_readonly("evaluations", &objective::ScanPoint::evaluations)
      .def_readonly("measured_curvature", &objective::ScanPoint::measuredCurvature)
      .def_readonly("cell", &objective::ScanPoint::cell);
  py::class_<ScanResult>(m, "ScanResult")
      .def_property_readonly("kind", [](const ScanResult& r) { return std::string(objective::scanKindName(r.kind)); })
      .def_readonly("translation0", &ScanResult::translation0, "T0 (Bohr)")
      .def_readonly("twist0", &ScanResult::twist0, "rad per cell")
      .def_readonly("atoms_per_cell", &ScanResult::atomsPerCell)
      .def_readonly("cells_per_slice", &ScanResult::cellsPerSlice)
      .def_readonly("points", &ScanResult::points)
      .def_readonly("complete", &ScanResult::complete)
      .def("curve", &curveDict, "The curve as the scan's JSON (docs/scan-file.md; per slice of length T0).")
      .def("write", &objective::writeScanCurve, py::arg("json_path"), py::arg("csv_path") = "",
           "Write the curve JSON (and CSV) as `mesochain scan` does.");
  py::class_<objective::ScanInput>(m, "ScanInput")
      .def_readonly("source", &objective::ScanInput::source)
      .def_readonly("cell", &objective::ScanInput::cell)
      .def_readonly("json_path", &objective::ScanInput::jsonPath)
      .def_readonly("csv_path", &objective::ScanInput::csvPath);
  m.def("read_scan", &objective::readScanFile, py::arg("path"), py::arg("output_dir") = "",
        "Read a scan file (docs/scan-file.md); its [output] paths are relative to output_dir (default the working "
        "folder, as `mesochain scan -o`).");
  m.def("run_scan", &runScanInput, py::arg("scan"), py::kw_only(), py::arg("resume") = false,
        py::arg("stop_after") = -1, "Run a scan file's scan (with its checkpoint).");
  m.def("scan", &scanCell, py::arg("input"), py::kw_only(), py::arg("kind"),
        py::arg("values") = std::vector<double>{}, py::arg("rotation_orders") = std::vector<int>{},
        py::arg("direction") = "soft", py::arg("force_tolerance") = 1e-4, py::arg("max_steps") = 500,
        py::arg("relax_translation") = true, py::arg("ring_angular") = py::none(),
        "A scan of a cell input without a checkpoint: kind 'stretch' (values = strains), 'twist' "
        "(values = rad per cell) or 'bend' (rotation_orders = ring sizes N_a).");
}

}  // namespace mesochain::python
