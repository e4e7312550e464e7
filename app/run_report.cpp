#include "app/run_report.hpp"

#include <cmath>
#include <ostream>

#include <fmt/format.h>

#include "common/build_info.hpp"
#include "common/units.hpp"

namespace mesochain::app {

using nlohmann::json;
using units::kBohrInAngstrom;

namespace {
// A per-cell value beside its per-atom value.
json perCellAndAtom(double value, int atoms) {
  return json{{"per_cell", value}, {"per_atom", value / atoms}};
}

json matrixRows(const Eigen::Matrix3Xd& m) {
  json rows = json::array();
  for (Eigen::Index a = 0; a < m.cols(); ++a) rows.push_back({m(0, a), m(1, a), m(2, a)});
  return rows;
}

double extra(const dftb::Result& r, const char* key) {
  auto it = r.extras.find(key);
  return it == r.extras.end() ? 0.0 : it->second;
}
}  // namespace

json resultJson(const objective::CellInput& input, const objective::ObjectiveCell& cell,
                const dftb::Result& r, const objective::RelaxOutcome* relax) {
  const int n = cell.atomCount();
  const auto& sym = cell.symmetry;
  json j;
  j["format"] = 1;
  j["program"] = buildInfoJson();  // name, version, git commit
  j["input"] = input.source;
  // The tables used (where the set was found: MESOCHAIN_PARAMS_PATH, installed, or the source).
  j["parameters"] = {{"set", input.parameterSet}, {"files", input.parameterFiles}};
  j["task"] = input.task.type;
  json species = json::array();
  for (int a = 0; a < n; ++a) species.push_back(cell.speciesOf(a));
  j["cell"] = {{"atoms", n},
               {"species", species},
               {"positions_angstrom", matrixRows(cell.positions * kBohrInAngstrom)},
               {"translation_angstrom", sym.translation() * kBohrInAngstrom},
               {"twist_degrees", sym.isRing() ? 360.0 / sym.rotationOrder()
                                              : sym.twist() / units::kDegree},
               {"rotation_order", sym.rotationOrder()},
               {"closed_ring", sym.isRing()}};
  j["kpoints"] = {{"helical", sym.isRing() ? 0 : input.band.helicalKPoints},
                  {"angular", input.band.angular.samples == 0 ? json("all") : json(input.band.angular.samples)},
                  {"reduced_points", static_cast<int>(extra(r, "kpoints"))}};
  j["electronic_temperature_kelvin"] =
      input.band.electronicTemperature / units::kBoltzmannHartreePerKelvin;
  // Every entry the terms reported (dftb/energy_ledger.hpp), then the totals.
  json energies;
  for (const dftb::LedgerEntry& e : r.energies.entries()) energies[e.name] = perCellAndAtom(e.value, n);
  energies["total"] = perCellAndAtom(r.totalEnergy, n);
  energies["mermin_free"] = perCellAndAtom(r.freeEnergy, n);
  energies["extrapolated_zero_temperature"] = perCellAndAtom(r.extrapolatedEnergy, n);
  j["energies_hartree"] = energies;
  j["electrons_per_cell"] = extra(r, "electrons");
  j["fermi_level_hartree"] = extra(r, "fermi_level");
  const double homo = extra(r, "homo"), lumo = extra(r, "lumo");
  j["homo_hartree"] = std::isfinite(homo) ? json(homo) : json(nullptr);
  j["lumo_hartree"] = std::isfinite(lumo) ? json(lumo) : json(nullptr);
  j["gap_hartree"] = std::isfinite(homo) && std::isfinite(lumo) ? json(lumo - homo) : json(nullptr);
  if (input.scc.enabled) {
    json history = json::array();
    const auto& he = r.series.at("scc_history_energy");
    const auto& hr = r.series.at("scc_history_residual");
    for (size_t m = 0; m < he.size(); ++m)
      history.push_back({{"mermin_free_hartree", he[m]}, {"max_charge_change_e", hr[m]}});
    j["scc"] = {{"converged", extra(r, "scc_converged") == 1.0},
                {"iterations", static_cast<int>(extra(r, "scc_iterations"))},
                {"charge_tolerance_e", input.scc.chargeTolerance},
                {"energy_tolerance_hartree", input.scc.energyTolerance},
                {"mixer", input.scc.mixer},
                {"mixing", input.scc.mixing},
                {"mulliken_charges_e", r.series.at("mulliken_charges")},
                {"mulliken_populations_e", r.series.at("mulliken_populations")},
                {"history", history}};
  }
  if (r.gradient.size()) {
    j["forces_hartree_per_bohr"] = matrixRows(-r.gradient);
    j["max_force_hartree_per_bohr"] = objective::maxForce(r.gradient);
  }
  if (!sym.isRing()) {
    j["axial_force_hartree_per_bohr"] = -r.dFdTranslation;
    j["torque_hartree_per_radian"] = -r.dFdTwist;
  }
  if (relax) {
    json hist = json::array();
    for (const auto& h : relax->history)
      hist.push_back({{"translation_angstrom", h.translation * kBohrInAngstrom},
                      {"mermin_free_hartree", h.freeEnergy},
                      {"max_force_hartree_per_bohr", h.maxForce},
                      {"axial_force_hartree_per_bohr", h.axialForce}});
    j["relaxation"] = {{"converged", relax->converged},
                       {"evaluations", relax->evaluations},
                       {"force_tolerance_hartree_per_bohr", input.task.forceTolerance},
                       {"relax_translation", input.task.relaxTranslation},
                       {"history", hist}};
  }
  json t;
  for (const auto& [k, v] : r.extras)
    if (k.rfind("time_", 0) == 0) t[k.substr(5)] = v;
  j["timings_seconds"] = t;
  return j;
}

void printSummary(std::ostream& out, const objective::CellInput& input,
                  const objective::ObjectiveCell& cell, const dftb::Result& r,
                  const objective::RelaxOutcome* relax) {
  const int n = cell.atomCount();
  const auto& sym = cell.symmetry;
  out << fmt::format("cell: {} atoms, ", n);
  if (sym.isRing())
    out << fmt::format("closed ring of N_a = {}\n", sym.rotationOrder());
  else
    out << fmt::format("screw T = {:.6f} Å, twist = {:.6f}°, rotation order {}\n",
                       sym.translation() * kBohrInAngstrom, sym.twist() / units::kDegree,
                       sym.rotationOrder());
  out << fmt::format("k-points: {} reduced, kT = {:.1f} K\n", static_cast<int>(extra(r, "kpoints")),
                     input.band.electronicTemperature / units::kBoltzmannHartreePerKelvin);
  if (relax)
    out << fmt::format("relaxation: {} after {} evaluations\n",
                       relax->converged ? "converged" : "NOT converged", relax->evaluations);
  // Hartree (the code's unit) and eV (units::kHartreeInEv, CODATA 2018) side by side.
  out << fmt::format("{:<34}{:>20}{:>20}{:>20}{:>18}\n", "energy", "per cell (Ha)", "per atom (Ha)",
                     "per cell (eV)", "per atom (eV)");
  auto row = [&](const char* name, double v) {
    const double ev = v * units::kHartreeInEv;
    out << fmt::format("{:<34}{:>20.10f}{:>20.10f}{:>20.8f}{:>18.8f}\n", name, v, v / n, ev, ev / n);
  };
  // The ledger's Energy entries in the terms' order, then -TS.
  for (const dftb::LedgerEntry& e : r.energies.entries())
    if (e.kind == dftb::EnergyKind::Energy) row(e.label.c_str(), e.value);
  row("-TS", -r.energies.entropy());
  row("total", r.totalEnergy);
  row("Mermin free energy", r.freeEnergy);
  row("extrapolated to T = 0", r.extrapolatedEnergy);
  out << fmt::format("Fermi level: {:.8f} Ha ({:.6f} eV)\n", extra(r, "fermi_level"),
                     extra(r, "fermi_level") * units::kHartreeInEv);
  if (input.scc.enabled) {
    const bool ok = extra(r, "scc_converged") == 1.0;
    out << fmt::format("SCC: {} after {} iterations (last max charge change {:.2e} e)\n",
                       ok ? "converged" : "NOT CONVERGED (result flagged)",
                       static_cast<int>(extra(r, "scc_iterations")), extra(r, "scc_residual"));
    out << "Mulliken charges (e):";
    for (double q : r.series.at("mulliken_charges")) out << fmt::format(" {:+.5f}", q);
    out << "\n";
  }
  if (r.gradient.size())
    out << fmt::format("largest force: {:.3e} Ha/Bohr\n", objective::maxForce(r.gradient));
  if (!sym.isRing() && r.gradient.size())
    out << fmt::format("axial force -dF/dT: {:.3e} Ha/Bohr\n", -r.dFdTranslation);
}

}  // namespace mesochain::app
