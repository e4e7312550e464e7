#pragma once
// Fixtures of the SCC tests: C/H parameters (pbc-0-3, a DFTB2 set), SCC calculators, the
// distorted C6H6 ring as one CH unit + C_6 and written out explicitly.
#include <cmath>
#include <memory>
#include <string>

#include "common/units.hpp"
#include "dftb/calculator.hpp"
#include "objective/core/cell.hpp"

namespace mesochain::testing {

inline std::shared_ptr<const dftb::ParameterSet> chParameters() {
  const std::string dir = std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/";
  static auto p = std::make_shared<const dftb::ParameterSet>(dftb::ParameterSet::load(
      {"C", "H"},
      {{"C-C", dir + "C-C.skf"}, {"C-H", dir + "C-H.skf"}, {"H-C", dir + "H-C.skf"},
       {"H-H", dir + "H-H.skf"}},
      "test"));
  return p;
}

inline dftb::CalculatorSettings sccSettings(double kelvin, int nKappa = 1) {
  dftb::CalculatorSettings s;
  s.band.helicalKPoints = nKappa;
  // DFTB+'s Boltzmann constant, so that temperatures match the reference runs.
  s.band.electronicTemperature = kelvin * 3.16681534524639e-6;
  s.scc.enabled = true;
  s.scc.chargeTolerance = 1e-11;
  s.scc.energyTolerance = 1e-11;
  s.scc.maxIterations = 200;
  return s;
}

inline dftb::Calculator sccCalculator(double kelvin, int nKappa = 1) {
  return dftb::Calculator(chParameters(), sccSettings(kelvin, nKappa));
}

// One CH unit of a distorted benzene ring (C at radius 1.397 A, H 1.084 A further out and
// turned by 0.12 rad, both slightly off the plane); the ring is this unit and its C_6 images.
// Same numbers as tests/data/dftbplus/benzene_c6/geo.gen.
inline objective::ObjectiveCell benzeneUnit(double bohrInAngstrom = 0.529177249) {
  const double rc = 1.397 / bohrInAngstrom, rh = (1.397 + 1.084) / bohrInAngstrom;
  objective::ObjectiveCell cell;
  cell.symmetry = objective::Symmetry::ring(6);
  cell.addAtom("C", {rc, 0.0, 0.03 / bohrInAngstrom});
  cell.addAtom("H", {rh * std::cos(0.12), rh * std::sin(0.12), -0.10 / bohrInAngstrom});
  return cell;
}

// The N_a images of every cell atom written out as one molecule (ring(1)), species order kept.
inline objective::ObjectiveCell explicitCopies(const objective::ObjectiveCell& cell) {
  objective::ObjectiveCell out;
  out.symmetry = objective::Symmetry::ring(1);
  for (const auto& s : cell.speciesNames) out.speciesNames.push_back(s);
  for (int c = 0; c < cell.symmetry.rotationOrder(); ++c)
    for (int a = 0; a < cell.atomCount(); ++a) {
      out.species.push_back(cell.species[a]);
      out.positions.conservativeResize(3, out.positions.cols() + 1);
      out.positions.col(out.positions.cols() - 1) =
          cell.symmetry.apply(objective::GroupElement{0, c}, cell.positions.col(a));
    }
  return out;
}

}  // namespace mesochain::testing

namespace mesochain::testing {

// A helical (CH)_x chain: one CH unit, screw T = 1.15 A, gamma = 150 deg (12 units per two
// turns), C at 0.45 A from the axis (C-C 1.44 A, C...C 2.34 A), H 1.09 A further out;
// slightly distorted so that no force vanishes by symmetry.
inline objective::ObjectiveCell helicalChUnit() {
  const double a = 1.0 / 0.529177249;
  objective::ObjectiveCell cell;
  cell.symmetry = objective::Symmetry::screw(1.15 * a, 150.0 * units::kDegree, 1);
  cell.addAtom("C", {0.45 * a, 0.02 * a, 0.0});
  cell.addAtom("H", {1.54 * a, -0.03 * a, 0.04 * a});
  return cell;
}

// The translational supercell of a screw cell whose twist is 2 pi m / M: M units, T' = M T,
// gamma' = 0.
inline objective::ObjectiveCell translationalSupercell(const objective::ObjectiveCell& cell,
                                                        int units) {
  objective::ObjectiveCell out;
  out.symmetry = objective::Symmetry::screw(units * cell.symmetry.translation(), 0.0, 1);
  for (const auto& s : cell.speciesNames) out.speciesNames.push_back(s);
  for (long z = 0; z < units; ++z)
    for (int a = 0; a < cell.atomCount(); ++a) {
      out.species.push_back(cell.species[a]);
      out.positions.conservativeResize(3, out.positions.cols() + 1);
      out.positions.col(out.positions.cols() - 1) =
          cell.symmetry.apply(objective::GroupElement{z, 0}, cell.positions.col(a));
    }
  return out;
}

}  // namespace mesochain::testing
