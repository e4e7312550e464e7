// writeCellFile: a cell file (docs/cell-file.md) that reads back to the same CellInput.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "common/atomic_file.hpp"
#include "common/errors.hpp"
#include "common/electronic_temperature.hpp"
#include "common/setting_entries.hpp"
#include "common/units.hpp"
#include "dftb/scc_table.hpp"
#include "input/cell_file.hpp"

namespace mesochain::objective {

namespace {

// The TOML literals of common/setting_entries.hpp under short names.
std::string quoted(const std::string& s) { return tomlStringText(s); }
std::string real(double x) { return tomlRealText(x); }

}  // namespace

void writeCellFile(const std::string& path, const CellInput& in) {
  const ObjectiveCell& cell = in.cell;
  const Symmetry& s = cell.symmetry;
  if (cell.atomCount() == 0) throw InputError(path, "geometry", "no atoms", "at least one atom");
  requireElectronicTemperature(in.electronicTemperature, path, "key electrons.temperature");
  AtomicOutputFile file(path);
  std::ofstream& out = file.stream();
  out << "# mesochain objective-cell input; keys and units: docs/cell-file.md\n";
  out << "format = 1\n\n[geometry]\nunit = \"angstrom\"\natoms = [\n";
  for (int a = 0; a < cell.atomCount(); ++a) {
    const Eigen::Vector3d x = cell.positions.col(a) * units::kBohrInAngstrom;
    out << fmt::format("  [{}, {}, {}, {}],\n", quoted(cell.speciesOf(a)), real(x.x()), real(x.y()),
                       real(x.z()));
  }
  out << "]\n\n[symmetry]\n";
  const double twist = s.isRing() ? 360.0 / s.rotationOrder() : s.twist() / units::kDegree;
  out << fmt::format("translation = {}  # Å\ntwist = {}  # degrees\nrotation_order = {}\n\n",
                     real(s.translation() * units::kBohrInAngstrom), real(twist),
                     s.rotationOrder());
  out << "[kpoints]\n";
  if (!s.isRing()) out << fmt::format("helical = {}\n", in.helicalKPoints);
  if (in.angular.samples > 0)
    out << fmt::format("angular = {}\n", in.angular.samples);
  else
    out << "angular = \"all\"\n";
  out << fmt::format("\n[electrons]\ntemperature = {}  # K\n\n[parameters]\n",
                     real(in.electronicTemperature / units::kBoltzmannHartreePerKelvin));
  std::map<std::string, std::string> fromSet;
  if (!in.parameterSet.empty()) {
    out << "set = " << quoted(in.parameterSet) << "\n";
    fromSet = parameterSetFiles(in.parameterSet, cell.speciesNames, path, "[parameters] set");
  }
  for (const auto& [pair, file] : in.parameterFiles) {
    auto it = fromSet.find(pair);
    if (it != fromSet.end() && it->second == file) continue;
    out << quoted(pair) << " = "
        << quoted(std::filesystem::absolute(file).lexically_normal().string()) << "\n";
  }
  if (!in.maxAngularMomentum.empty()) {
    out << "max_angular_momentum = {";
    bool first = true;
    for (const auto& [el, l] : in.maxAngularMomentum) {
      if (l < 0 || l > 3)
        throw InputError(path, "max_angular_momentum." + el, std::to_string(l), "0..3 (s..f)");
      out << (first ? " " : ", ") << el << " = \""
          << "spdf"[l] << "\"";
      first = false;
    }
    out << " }\n";
  }
  const DispersionInput& d = in.dispersion;
  out << "\n[dispersion]\nmodel = " << quoted(d.model) << "\n";
  if (d.model == "lj" && d.parameters == "uff") {
    out << "parameters = \"uff\"\n";
  } else if (d.model == "lj" && !d.elements.empty()) {
    out << "elements = {";
    bool first = true;
    for (const auto& [el, p] : d.elements) {
      out << (first ? " " : ", ")
          << fmt::format("{} = {{ epsilon = {}, r0 = {} }}", el, real(p.epsilon * units::kHartreeInKcalPerMol),
                         real(p.r0 * units::kBohrInAngstrom));
      first = false;
    }
    out << " }  # kcal/mol, Å\n";
  } else if (d.model == "lj") {
    out << fmt::format("epsilon = {}  # kcal/mol\nr0 = {}  # Å\n", real(d.epsilon * units::kHartreeInKcalPerMol),
                       real(d.r0 * units::kBohrInAngstrom));
  }
  if (d.model == "lj") out << fmt::format("cutoff = {}  # Å\n", real(d.cutoff * units::kBohrInAngstrom));
  if (d.model == "kc") {
    out << "parameters = " << quoted(d.kcParameters) << "\n";
    if (d.cutoff > 0.0)
      out << fmt::format("cutoff = {}  # Å\ntaper_start = {}  # Å\n",
                         real(d.cutoff * units::kBohrInAngstrom),
                         real(d.kcTaperStart * units::kBohrInAngstrom));
    out << fmt::format("bond_cutoff = {}  # Å\n", real(d.kcBondCutoff * units::kBohrInAngstrom));
  }
  if (d.model == "lj" && d.summation == "ewald")
    out << fmt::format("summation = \"ewald\"\newald_tolerance = {}\n", real(d.ewaldTolerance));
  if (in.scc.enabled) out << "\n[scc]\n" << tomlTableText(dftb::sccTableEntries(in.scc));
  const TaskInput& t = in.task;
  out << "\n[task]\ntype = " << quoted(t.type) << "\n";
  if (t.type == "relax")
    out << fmt::format("force_tolerance = {}  # Ha/Bohr\nmax_steps = {}\nrelax_translation = {}\n",
                       real(t.forceTolerance), t.maxSteps, t.relaxTranslation);
  file.commit();
}

}  // namespace mesochain::objective
