// mesochain.Calculator (dftb::Calculator as the cell file asks for it: objective::makeCalculator),
// mesochain.Result and mesochain.relax (objective::relax). The GIL is released while the
// library computes (its OpenMP threads run meanwhile).
#include <memory>

#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include "dftb/calculator.hpp"
#include "input/cell_calculator.hpp"
#include "objective/drivers/relax.hpp"
#include "python/src/arrays.hpp"
#include "python/src/bindings.hpp"

namespace mesochain::python {

namespace {

using dftb::Result;
using objective::ObjectiveCell;

py::object gradientOrNone(const Result& r, double sign) {
  if (!r.gradient.size()) return py::none();
  return rowsFromColumns(sign * r.gradient);
}

py::dict seriesDict(const Result& r) {
  py::dict out;
  for (const auto& [k, v] : r.series) out[py::str(k)] = py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
  return out;
}

Result evaluate(const dftb::Calculator& calc, const ObjectiveCell& cell, bool forces, bool strain) {
  py::gil_scoped_release release;
  return calc.evaluate(cell, {forces, strain});
}

void requirePositive(double x, const char* argument, const char* unit) {
  requireFinite(x, kPythonSource, std::string("argument ") + argument);
  if (!(x > 0))
    throw InputError(kPythonSource, std::string("argument ") + argument, std::to_string(x),
                     std::string("a positive number (") + unit + ")");
}

void requireCount(long n, const char* argument, long hi) {
  if (n < 1 || n > hi)
    throw InputError(kPythonSource, std::string("argument ") + argument, std::to_string(n),
                     "an integer from 1 to " + std::to_string(hi));
}

objective::RelaxOutcome relax(const dftb::Calculator& calc, const ObjectiveCell& cell,
                              double forceTolerance, long maxSteps, bool relaxTranslation,
                              std::optional<double> axialTolerance, long maxTranslationSteps,
                              const std::string& algorithm, double maxDisplacement,
                              std::function<void(int, double, double)> progress) {
  objective::RelaxSettings s;
  requirePositive(forceTolerance, "force_tolerance", "Ha/Bohr");
  requireCount(maxSteps, "max_steps", 100000000L);
  requireCount(maxTranslationSteps, "max_translation_steps", 100000L);
  requirePositive(maxDisplacement, "max_displacement", "Bohr");
  if (relaxTranslation && cell.symmetry.isRing())
    throw InputError(kPythonSource, "argument relax_translation", "True for a closed ring (translation 0)",
                     "relax_translation only for a screw with translation > 0");
  if (algorithm != "lbfgs" && algorithm != "fire")
    throw InputError(kPythonSource, "argument algorithm", "'" + algorithm + "'", "'lbfgs' or 'fire'");
  s.algorithm = algorithm == "fire" ? objective::RelaxAlgorithm::Fire : objective::RelaxAlgorithm::Lbfgs;
  s.forceTolerance = forceTolerance;
  // As `mesochain run`: the axial tolerance is the force tolerance unless given.
  s.axialTolerance = axialTolerance.value_or(forceTolerance);
  requirePositive(s.axialTolerance, "axial_tolerance", "Ha/Bohr");
  s.maxSteps = static_cast<int>(maxSteps);
  s.relaxTranslation = relaxTranslation;
  s.maxTranslationSteps = static_cast<int>(maxTranslationSteps);
  s.maxDisplacement = maxDisplacement;
  if (progress)
    s.progress = [progress](int step, double f, double fmax) {
      py::gil_scoped_acquire acquire;
      progress(step, f, fmax);  // a Python exception propagates and ends the relaxation
    };
  py::gil_scoped_release release;
  return objective::relax(calc, cell, s);
}

}  // namespace

void bindCalculation(py::module_& m) {
  py::class_<Result>(m, "Result", "Energies per cell (Hartree) and derivatives (atomic units).")
      .def_readonly("free_energy", &Result::freeEnergy, "Mermin free energy F = E - TS; forces are -dF/dx")
      .def_readonly("total_energy", &Result::totalEnergy)
      .def_readonly("extrapolated_energy", &Result::extrapolatedEnergy, "E - TS/2, the T -> 0 estimate")
      .def_property_readonly("energies", [](const Result& r) {
            py::dict d;
            for (const auto& e : r.energies.entries()) d[py::str(e.name)] = e.value;
            return d;
          }, "the energy ledger: every built term's entry (Hartree per cell), as energies_hartree in the results JSON")
      .def_property_readonly("band_energy", [](const Result& r) { return r.energies["band"]; })
      .def_property_readonly("entropy_term", [](const Result& r) { return r.energies.entropy(); }, "T S")
      .def_property_readonly("repulsive", [](const Result& r) { return r.energies["repulsive"]; })
      .def_property_readonly("dispersion", [](const Result& r) { return r.energies["dispersion"]; },
                             "0 when the cell has no dispersion")
      .def_property_readonly("scc", [](const Result& r) { return r.energies["scc"]; }, "0 without SCC")
      .def_readonly("dF_dtranslation", &Result::dFdTranslation, "dF/dT (Hartree/Bohr)")
      .def_readonly("dF_dtwist", &Result::dFdTwist, "dF/dgamma (Hartree/rad)")
      .def_readonly("atoms", &Result::atoms)
      .def_property_readonly("gradient", [](const Result& r) { return gradientOrNone(r, 1.0); },
                             "(N, 3) dF/dx (Hartree/Bohr) or None when not requested")
      .def_property_readonly("forces", [](const Result& r) { return gradientOrNone(r, -1.0); },
                             "(N, 3) -dF/dx (Hartree/Bohr) or None")
      .def_readonly("extras", &Result::extras, "fermi_level, homo, lumo, electrons, kpoints, timings, ...")
      .def_property_readonly("series", &seriesDict, "mulliken_charges, SCC history, ... (NumPy arrays)")
      .def_property_readonly("charges", [](const Result& r) -> py::object {
            auto it = r.series.find("mulliken_charges");
            if (it == r.series.end()) return py::none();
            return py::array_t<double>(static_cast<py::ssize_t>(it->second.size()), it->second.data());
          }, "Mulliken charges per atom (e, positive = electron deficit) with SCC; None without")
      .def_property_readonly("eigenvalues", [](const Result& r) -> py::object {
            auto it = r.series.find("eigenvalues");
            auto w = r.series.find("kpoint_weight");
            if (it == r.series.end() || w == r.series.end() || w->second.empty()) return py::none();
            const auto nk = static_cast<py::ssize_t>(w->second.size());
            const auto norb = static_cast<py::ssize_t>(it->second.size()) / nk;
            py::array_t<double> out({nk, norb});
            std::copy(it->second.begin(), it->second.end(), out.mutable_data());
            return out;
          }, "(k-points, orbitals) levels in Hartree, ascending per k-point; the points are "
             "kpoint_kappa (rad per screw step), kpoint_mu, kpoint_weight in `series`")
      .def("__repr__", [](const Result& r) {
        return "<mesochain.Result F = " + std::to_string(r.freeEnergy) + " Ha, " + std::to_string(r.atoms) + " atoms>";
      });

  py::class_<dftb::Calculator, std::shared_ptr<dftb::Calculator>>(
      m, "Calculator", "The DFTB calculator a cell input asks for (tables, k-points, temperature, dispersion, SCC).")
      .def(py::init([](const objective::CellInput& in) {
             // One rank, also in a process where something else started MPI (mpi4py).
             return std::make_shared<dftb::Calculator>(
                 objective::makeCalculator(in, parallel::Communicator::serial()));
           }),
           py::arg("input"))
      .def("evaluate", &evaluate, py::arg("cell"), py::arg("forces") = true, py::arg("strain") = true,
           "Energy of the cell; forces: the gradient; strain: dF/dT and dF/dgamma.")
      .def_property_readonly("terms", &dftb::Calculator::termNames)
      .def("clear_charges", [](const dftb::Calculator& c) { c.chargeCache().clear(); },
           "Forget the SCC charges kept for the warm start.");

  py::class_<objective::RelaxStep>(m, "RelaxStep")
      .def_readonly("translation", &objective::RelaxStep::translation, "Bohr")
      .def_readonly("free_energy", &objective::RelaxStep::freeEnergy, "Hartree")
      .def_readonly("max_force", &objective::RelaxStep::maxForce, "Hartree/Bohr")
      .def_readonly("axial_force", &objective::RelaxStep::axialForce, "-dF/dT, Hartree/Bohr");
  py::class_<objective::RelaxOutcome>(m, "RelaxOutcome")
      .def_readonly("cell", &objective::RelaxOutcome::cell)
      .def_readonly("result", &objective::RelaxOutcome::result)
      .def_readonly("converged", &objective::RelaxOutcome::converged)
      .def_readonly("evaluations", &objective::RelaxOutcome::evaluations)
      .def_readonly("history", &objective::RelaxOutcome::history, "one RelaxStep per fixed-T relaxation");
  m.def("relax", &relax, py::arg("calculator"), py::arg("cell"), py::kw_only(),
        py::arg("force_tolerance") = 1e-4, py::arg("max_steps") = 500, py::arg("relax_translation") = false,
        py::arg("axial_tolerance") = py::none(), py::arg("max_translation_steps") = 30,
        py::arg("algorithm") = "lbfgs", py::arg("max_displacement") = 0.2, py::arg("progress") = nullptr,
        "Relax the atoms at fixed symmetry (and T with relax_translation); tolerances in Ha/Bohr. "
        "progress(evaluation, F, max_force) is called after every energy evaluation.");
}

}  // namespace mesochain::python
