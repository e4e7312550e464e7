#include "input/hsd/dftbplus_units.hpp"

#include <utility>
#include <vector>

#include "input/hsd/hsd_tree.hpp"

namespace mesochain::input::hsd {

namespace {
using Table = std::vector<std::pair<const char*, double>>;

// DFTB+ 25.1 unitconversion.F90 (lengthUnits, energyUnits, forceUnits), same names.
const Table& table(UnitKind kind) {
  constexpr double aa = kDftbPlusAngstromInBohr;
  constexpr double ev = 1.0 / kDftbPlusHartreeInEv;
  constexpr double joule = 1.0 / 4.3597441775e-18;              // Hartree__J of DFTB+
  constexpr double inverseCm = 1.0 / (2.0 * 10973731.568527 / 100.0);  // 1 / Hartree__cm
  static const Table length{{"angstrom", aa}, {"aa", aa},          {"a", aa},
                            {"meter", 1e10 * aa}, {"m", 1e10 * aa}, {"bohr", 1.0},
                            {"pm", 1e-2 * aa},    {"picometer", 1e-2 * aa}, {"au", 1.0}};
  static const Table energy{{"rydberg", 0.5},
                            {"ry", 0.5},
                            {"electronvolt", ev},
                            {"ev", ev},
                            {"kcal/mol", kDftbPlusKcalPerMolInHartree},
                            {"kelvin", kDftbPlusBoltzmannHartreePerKelvin},
                            {"k", kDftbPlusBoltzmannHartreePerKelvin},
                            {"cm^-1", inverseCm},
                            {"hartree", 1.0},
                            {"ha", 1.0},
                            {"joule", joule},
                            {"j", joule},
                            {"au", 1.0}};
  static const Table force{{"ev/angstrom", ev / aa}, {"ev/aa", ev / aa},  {"ev/a", ev / aa},
                           {"ha/bohr", 1.0},         {"hartree/bohr", 1.0},
                           {"j/m", joule / (1e10 * aa)}, {"joule/m", joule / (1e10 * aa)}, {"au", 1.0}};
  switch (kind) {
    case UnitKind::Length: return length;
    case UnitKind::Energy: return energy;
    default: return force;
  }
}
}  // namespace

std::optional<double> unitFactor(UnitKind kind, const std::string& unit) {
  const std::string u = lowerCase(unit);
  for (const auto& [name, factor] : table(kind))
    if (u == name) return factor;
  return std::nullopt;
}

std::string unitNames(UnitKind kind) {
  std::string out;
  for (const auto& [name, factor] : table(kind)) out += (out.empty() ? "" : ", ") + std::string(name);
  return out;
}

}  // namespace mesochain::input::hsd
