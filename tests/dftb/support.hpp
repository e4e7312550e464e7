#pragma once
// Shared fixtures of the dftb tests: hand-built objective cells (independent of the builders)
// and finite-difference helpers.
#include <cmath>
#include <memory>
#include <string>

#include "common/units.hpp"
#include "dftb/calculator.hpp"
#include "dftb/parameters.hpp"
#include "objective/core/cell.hpp"

namespace mesochain::testing {

inline std::shared_ptr<const dftb::ParameterSet> carbonParameters() {
  static auto p = std::make_shared<const dftb::ParameterSet>(dftb::ParameterSet::load(
      {"C"}, {{"C-C", std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/C-C.skf"}}, "test"));
  return p;
}

inline dftb::Calculator carbonCalculator(int nKappa, double kelvin, bool dispersion = false,
                                         double ljCutoff = 20.0) {
  dftb::CalculatorSettings s;
  s.band.helicalKPoints = nKappa;
  s.band.electronicTemperature = kelvin * units::kBoltzmannHartreePerKelvin;
  if (dispersion) {
    s.dispersion.enabled = true;
    s.dispersion.epsilon = 0.069 * units::kKcalPerMolInHartree;
    s.dispersion.r0 = 3.80 * units::kAngstromInBohr;
    s.dispersion.cutoff = ljCutoff;
  }
  return dftb::Calculator(carbonParameters(), s);
}

// Armchair (n,n) tube as 2 atoms + screw (T = a/2, gamma = pi/n) + C_n, built by hand from the
// graphene geometry: the two atoms of a circumferential pair are one bond apart along the arc.
inline objective::ObjectiveCell armchairHelical(int n, double bondAngstrom = 1.42) {
  const double acc = bondAngstrom * units::kAngstromInBohr;
  const double radius = 3.0 * n * acc / (2 * units::kPi);
  objective::ObjectiveCell cell;
  cell.symmetry = objective::Symmetry::screw(std::sqrt(3.0) * acc / 2, units::kPi / n, n);
  cell.addAtom("C", {radius, 0.0, 0.0});
  cell.addAtom("C", {radius * std::cos(acc / radius), radius * std::sin(acc / radius), 0.0});
  return cell;
}

// Zigzag (n,0) tube as 2 atoms + screw (T = 3 a_cc / 2, gamma = pi/n) + C_n.
inline objective::ObjectiveCell zigzagHelical(int n, double bondAngstrom = 1.42) {
  const double acc = bondAngstrom * units::kAngstromInBohr;
  const double radius = std::sqrt(3.0) * n * acc / (2 * units::kPi);
  objective::ObjectiveCell cell;
  cell.symmetry = objective::Symmetry::screw(1.5 * acc, units::kPi / n, n);
  cell.addAtom("C", {radius, 0.0, 0.0});
  cell.addAtom("C", {radius * std::cos(units::kPi / n), radius * std::sin(units::kPi / n),
                     0.5 * acc});
  return cell;
}

// Deterministic small displacements (Bohr) so that forces do not vanish by symmetry.
inline void distort(objective::ObjectiveCell& cell, double amplitude) {
  for (int a = 0; a < cell.atomCount(); ++a)
    for (int k = 0; k < 3; ++k)
      cell.positions(k, a) += amplitude * std::sin(1.7 * a + 2.3 * k + 0.4);
}

// Central finite difference of the free energy with respect to atom a, component k.
inline double fdGradient(const dftb::Calculator& calc, objective::ObjectiveCell cell, int a,
                         int k, double h) {
  cell.positions(k, a) += h;
  const double ep = calc.evaluate(cell, {}).freeEnergy;
  cell.positions(k, a) -= 2 * h;
  const double em = calc.evaluate(cell, {}).freeEnergy;
  return (ep - em) / (2 * h);
}

}  // namespace mesochain::testing
