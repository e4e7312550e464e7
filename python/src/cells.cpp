// mesochain.Cell (objective::ObjectiveCell), mesochain.CellInput (objective::CellInput: a cell
// file read into memory), read_cell, cell_input and the unit constants.
#include <pybind11/stl.h>

#include "common/units.hpp"
#include "dftb/scc_table.hpp"
#include "input/cell_input_file.hpp"
#include "input/cell_document.hpp"
#include "input/cell_file.hpp"
#include "input/gen_file.hpp"
#include "input/text_reader.hpp"
#include "input/xyz_file.hpp"
#include "input/xyz_settings.hpp"
#include "python/src/arrays.hpp"
#include "python/src/bindings.hpp"

namespace mesochain::python {

namespace {

using objective::CellInput;
using objective::ObjectiveCell;
using objective::Symmetry;

const double kMinimumDistance = objective::kMinimumAtomDistanceAngstrom * units::kAngstromInBohr;

ObjectiveCell makeCell(const std::vector<std::string>& symbols, const py::handle& positions,
                       double translation, double twist, int rotationOrder) {
  const std::string& src = kPythonSource;
  if (symbols.empty()) throw InputError(src, "argument symbols", "no atoms", "at least one element symbol");
  const Eigen::Matrix3Xd x = columnsFromRows(positions, static_cast<long>(symbols.size()), src,
                                             "positions (Bohr)");
  ObjectiveCell cell;
  for (std::size_t a = 0; a < symbols.size(); ++a) {
    if (!objective::detail::isElementName(symbols[a]))
      throw InputError(src, "argument symbols[" + std::to_string(a) + "]", "'" + symbols[a] + "'",
                       "an element symbol such as C or Si");
    cell.addAtom(symbols[a], x.col(static_cast<Eigen::Index>(a)));
  }
  requireFinite(translation, src, "argument translation");
  requireFinite(twist, src, "argument twist");
  if (translation < 0)
    throw InputError(src, "argument translation", std::to_string(translation) + " Bohr",
                     "a translation >= 0 (Bohr; 0 closes a ring)");
  if (rotationOrder < 1)
    throw InputError(src, "argument rotation_order", std::to_string(rotationOrder), "an integer >= 1");
  cell.symmetry = Symmetry::fromParameters(translation, twist, rotationOrder, src.c_str());
  cell.validate(src, kMinimumDistance);
  return cell;
}

std::vector<std::string> symbolsOf(const ObjectiveCell& c) {
  std::vector<std::string> s;
  for (int a = 0; a < c.atomCount(); ++a) s.push_back(c.speciesOf(a));
  return s;
}

ObjectiveCell withPositions(const ObjectiveCell& c, const py::handle& positions) {
  ObjectiveCell out = c;
  out.positions = columnsFromRows(positions, c.atomCount(), kPythonSource, "positions (Bohr)");
  out.validate(kPythonSource, kMinimumDistance);
  return out;
}

ObjectiveCell withSymmetry(const ObjectiveCell& c, std::optional<double> translation,
                           std::optional<double> twist) {
  ObjectiveCell out = c;
  const Symmetry& s = c.symmetry;
  const double t = translation.value_or(s.translation());
  const double g = twist.value_or(s.isRing() ? 0.0 : s.twist());
  requireFinite(t, kPythonSource, "argument translation");
  requireFinite(g, kPythonSource, "argument twist");
  if ((t == 0.0) != s.isRing())
    throw InputError(kPythonSource, "argument translation", std::to_string(t) + " Bohr",
                     s.isRing() ? "0 (the cell is a closed ring)" : "a translation > 0 (the cell is a screw)");
  if (s.isRing() && twist)
    throw InputError(kPythonSource, "argument twist", "a twist for a closed ring",
                     "no twist: a ring's rotation is 2 pi / N_a (change rotation_order instead)");
  if (!s.isRing()) out.symmetry = Symmetry::fromParameters(t, g, s.rotationOrder(), kPythonSource.c_str());
  out.validate(kPythonSource, kMinimumDistance);
  return out;
}

// A copy of `in` with another cell: the same atoms (elements) and the same kind of symmetry, so
// the parameter tables and k-points still apply.
CellInput withCell(const CellInput& in, const ObjectiveCell& cell) {
  if (symbolsOf(cell) != symbolsOf(in.cell))
    throw InputError(kPythonSource, "argument cell", "other elements than the cell of " + in.source,
                     "the same elements in the same order");
  if (cell.symmetry.isRing() != in.cell.symmetry.isRing())
    throw InputError(kPythonSource, "argument cell", cell.symmetry.isRing() ? "a ring" : "a screw",
                     in.cell.symmetry.isRing() ? "a ring, as in " + in.source : "a screw, as in " + in.source);
  CellInput out = in;
  out.cell = cell;
  out.cell.validate(kPythonSource, kMinimumDistance);
  return out;
}

// Atomic units (Hartree, Bohr), the keys of the [dispersion] table (dftb/dispersion_table.hpp).
py::dict dispersionDict(const dftb::DispersionTable& d) {
  py::dict out;
  out["model"] = d.model();
  if (d.lj.enabled) {
    out["epsilon"] = d.lj.epsilon;
    out["r0"] = d.lj.r0;
    out["parameters"] = d.ljParameters;
    py::dict elements;
    for (const auto& [el, p] : dftb::ljElements(d.lj)) {
      py::dict e;
      e["epsilon"] = p.epsilon;
      e["r0"] = p.r0;
      elements[py::str(el)] = e;
    }
    out["elements"] = elements;
    out["cutoff"] = d.lj.cutoff;
    out["summation"] = d.lj.ewald ? "ewald" : "cutoff";
    out["ewald_tolerance"] = d.lj.ewaldTolerance;
  }
  if (d.kc.enabled) {  // cutoff 0 and taper_start < 0: the parameter set's
    out["parameters"] = d.kc.parameters;
    out["cutoff"] = d.kc.cutoff;
    out["taper_start"] = d.kc.taperStart;
    out["bond_cutoff"] = d.kc.bondCutoff;
  }
  return out;
}

// The [scc] table as the cell writer writes it (dftb/scc_table.hpp): its keys are listed there.
py::dict sccDict(const dftb::SccSettings& s) {
  py::dict out;
  for (const SettingEntry& e : dftb::sccTableEntries(s)) {
    if (e.value.is_boolean()) out[e.key.c_str()] = e.value.as_boolean();
    else if (e.value.is_integer()) out[e.key.c_str()] = e.value.as_integer();
    else if (e.value.is_floating()) out[e.key.c_str()] = e.value.as_floating();
    else out[e.key.c_str()] = e.value.as_string().str;
  }
  return out;
}

py::dict taskDict(const objective::TaskInput& t) {
  py::dict out;
  out["type"] = t.type;
  out["force_tolerance"] = t.forceTolerance;
  out["max_steps"] = t.maxSteps;
  out["relax_translation"] = t.relaxTranslation;
  return out;
}

void bindUnits(py::module_& m) {
  py::module_ u = m.def_submodule("units", "The CODATA 2018 constants of common/units.hpp.");
  u.attr("BOHR_IN_ANGSTROM") = units::kBohrInAngstrom;
  u.attr("ANGSTROM_IN_BOHR") = units::kAngstromInBohr;
  u.attr("HARTREE_IN_EV") = units::kHartreeInEv;
  u.attr("EV_IN_HARTREE") = units::kEvInHartree;
  u.attr("HARTREE_IN_KCAL_PER_MOL") = units::kHartreeInKcalPerMol;
  u.attr("BOLTZMANN_HARTREE_PER_KELVIN") = units::kBoltzmannHartreePerKelvin;
  u.attr("DEGREE") = units::kDegree;
  u.attr("EV_PER_ANGSTROM_IN_HARTREE_PER_BOHR") = units::kEvInHartree / units::kAngstromInBohr;
}

}  // namespace

void bindCells(py::module_& m) {
  bindUnits(m);
  py::class_<ObjectiveCell>(m, "Cell",
                            "An objective cell: N_o atoms and the symmetry (screw T, twist gamma, "
                            "rotation order N_a) that generates the structure. Atomic units.")
      .def(py::init(&makeCell), py::arg("symbols"), py::arg("positions"), py::arg("translation"),
           py::arg("twist"), py::arg("rotation_order") = 1,
           "symbols: element per atom; positions: (N, 3) Bohr; translation T: Bohr (0 = closed "
           "ring); twist gamma: rad per screw step; checked as the cell file is (atom distances "
           "including images >= 0.5 Å).")
      .def_property_readonly("symbols", &symbolsOf)
      .def_property_readonly("positions", [](const ObjectiveCell& c) { return rowsFromColumns(c.positions); },
                             "(N, 3) Bohr (a copy)")
      .def_property_readonly("translation", [](const ObjectiveCell& c) { return c.symmetry.translation(); },
                             "screw translation T (Bohr; 0 for a ring)")
      .def_property_readonly("twist", [](const ObjectiveCell& c) { return c.symmetry.twist(); },
                             "screw twist gamma (rad per step)")
      .def_property_readonly("rotation_order", [](const ObjectiveCell& c) { return c.symmetry.rotationOrder(); })
      .def_property_readonly("is_ring", [](const ObjectiveCell& c) { return c.symmetry.isRing(); })
      .def("__len__", &ObjectiveCell::atomCount)
      .def("with_positions", &withPositions, py::arg("positions"), "A copy with new (N, 3) positions (Bohr).")
      .def("with_symmetry", &withSymmetry, py::arg("translation") = py::none(), py::arg("twist") = py::none(),
           "A copy with another screw translation (Bohr) and/or twist (rad); the rotation order stays.")
      .def("unrolled", &objective::unroll, py::arg("zeta_min"), py::arg("zeta_max"),
           "The images g(zeta, c) for zeta_min..zeta_max and every c as plain atoms.")
      .def("write_xyz", [](const ObjectiveCell& c, const std::string& path) { objective::writeXyzFile(path, c); },
           py::arg("path"), "Extended XYZ with the symmetry keys (Å).")
      .def("write_gen", [](const ObjectiveCell& c, const std::string& path) { objective::writeGenFile(path, c); },
           py::arg("path"))
      .def("__repr__", [](const ObjectiveCell& c) {
        return "<mesochain.Cell " + std::to_string(c.atomCount()) + " atoms, T = " +
               std::to_string(c.symmetry.translation()) + " Bohr, twist = " +
               std::to_string(c.symmetry.twist()) + " rad, N_a = " +
               std::to_string(c.symmetry.rotationOrder()) + ">";
      });
  m.def("read_structure", [](const std::string& path) {
        const std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
        if (ext == ".gen" || ext == ".GEN") return objective::readGenFile(path).cell;
        if (ext == ".xyz" || ext == ".XYZ") return objective::readXyzFile(path).cell;
        throw InputError(path, "the file name", "'" + path + "'", "a .gen or .xyz file");
      }, py::arg("path"), "The cell of a .gen or extended .xyz file (as [geometry] file = ... reads it).");

  py::class_<CellInput>(m, "CellInput",
                        "A cell file in memory: the cell and its settings (k-points, temperature, "
                        "parameter tables, dispersion, SCC, task). Atomic units.")
      .def_readonly("source", &CellInput::source)
      .def_readonly("cell", &CellInput::cell)
      .def_property_readonly("helical_kpoints", [](const CellInput& in) { return in.band.helicalKPoints; })
      .def_property_readonly("angular_samples", [](const CellInput& in) { return in.band.angular.samples; },
                             "0 = every angular quantum number, M > 0 = M samples")
      .def_property_readonly("electronic_temperature", [](const CellInput& in) { return in.band.electronicTemperature; },
                             "k_B T (Hartree)")
      .def_readonly("parameter_set", &CellInput::parameterSet)
      .def_readonly("parameter_files", &CellInput::parameterFiles)
      .def_readonly("max_angular_momentum", &CellInput::maxAngularMomentum)
      .def_property_readonly("dispersion", [](const CellInput& in) { return dispersionDict(in.dispersion); },
                             "model and (lj) epsilon (Hartree), r0, cutoff (Bohr), summation, parameters (\"uff\" or \"\"), "
                             "elements (per element epsilon, r0)")
      .def_property_readonly("scc", [](const CellInput& in) { return sccDict(in.scc); })
      .def_property_readonly("task", [](const CellInput& in) { return taskDict(in.task); },
                             "type, force_tolerance (Ha/Bohr), max_steps, relax_translation")
      .def("with_cell", &withCell, py::arg("cell"),
           "A copy with another cell of the same elements and kind of symmetry.")
      .def("settings_keys", [](const CellInput& in) { return objective::xyzSettingsKeys(in); },
           "The settings as the extended XYZ keys mesochain:<section>.<key> (one string).")
      .def("write", [](const CellInput& in, const std::string& path) { objective::writeCellFile(path, in); },
           py::arg("path"), "Write a cell file that reads back to this input.")
      .def("write_xyz",
           [](const CellInput& in, const std::string& path, std::optional<double> energy) {
             objective::XyzExtras extras;
             extras.energy = energy;
             extras.settings = &in;
             objective::writeXyzFile(path, in.cell, extras);
           },
           py::arg("path"), py::arg("energy") = py::none(),
           "Extended XYZ of the cell with its symmetry and settings keys (energy in Hartree).");
  m.def("read_cell", &input::readCellInputFile, py::arg("path"),
        "Read a cell file (docs/cell-file.md) or a DFTB+ input (a path ending in .hsd: the subset of "
        "docs/cell-file.md, \"DFTB+ input\"), with the reader of `mesochain run`.");
  m.def(
      "cell_input",
      [](const py::dict& document, const std::string& source) {
        return objective::readCellDocument(tomlFromPython(document, source), source);
      },
      py::arg("document"), py::arg("source") = "<dict>",
      "Read a dict laid out as the cell file (same keys, units and checks; relative paths from the "
      "working folder).");
}

}  // namespace mesochain::python
