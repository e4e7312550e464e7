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
#include "dftb/dispersion_table.hpp"
#include "dftb/scc_table.hpp"
#include "dftb/band_table.hpp"
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
  requireElectronicTemperature(in.band.electronicTemperature, path, "key electrons.temperature");
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
  const dftb::BandSettings& band = in.band;
  out << "[kpoints]\n" << tomlTableText(dftb::kpointsTableEntries(band, s.isRing()));
  out << "\n[electrons]\n" << tomlTableText(dftb::electronsTableEntries(band)) << "\n[parameters]\n";
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
  out << "\n[dispersion]\n" << tomlTableText(dftb::dispersionTableEntries(in.dispersion));
  if (in.scc.enabled) out << "\n[scc]\n" << tomlTableText(dftb::sccTableEntries(in.scc));
  const TaskInput& t = in.task;
  out << "\n[task]\ntype = " << quoted(t.type) << "\n";
  if (t.type == "relax")
    out << fmt::format("force_tolerance = {}  # Ha/Bohr\nmax_steps = {}\nrelax_translation = {}\n",
                       real(t.forceTolerance), t.maxSteps, t.relaxTranslation);
  file.commit();
}

}  // namespace mesochain::objective
