#pragma once
// Fixtures of the SCC tests: C/H parameters (pbc-0-3, a DFTB2 set), SCC calculators, the
// distorted C6H6 ring as one CH unit + C_6 and written out explicitly.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

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

// One translational unit (length 3 a_cc) of an H-terminated armchair graphene nanoribbon with
// `dimerLines` C columns across the width (the N of N-AGNR: 2N C and 4 H per unit), axis z,
// twisted by `twist` (rad) per unit: every atom of the flat ribbon at height z is turned by
// twist z / T about the axis, and the screw (T, twist) repeats the unit. H sits on the missing
// graphene bond of each edge C at 1.09 A. Slightly distorted so no force vanishes by symmetry.
inline objective::ObjectiveCell twistedArmchairRibbonUnit(int dimerLines, double twist) {
  const double b = 1.0 / 0.529177249, acc = 1.42 * b, a = std::sqrt(3.0) * acc;
  const double period = 3 * acc, xMax = (dimerLines - 1) * a / 2, eps = 1e-6;
  const double xMid = xMax / 2;
  auto inWidth = [&](double x) { return x > -eps && x < xMax + eps; };
  objective::ObjectiveCell cell;
  cell.symmetry = objective::Symmetry::screw(period, twist, 1);
  auto place = [&](const std::string& el, double x, double z) {
    // Flat ribbon in the x-z plane, centred on the axis, then twisted.
    const double angle = twist * z / period, u = x - xMid;
    const int k = cell.atomCount();
    cell.addAtom(el, {u * std::cos(angle) + 0.02 * std::sin(1.3 * k),
                      u * std::sin(angle) + 0.03 * std::cos(2.1 * k), z + 0.02 * std::sin(0.7 * k)});
  };
  std::vector<Eigen::Vector2d> carbons;
  for (int i = -2 * dimerLines; i <= 2 * dimerLines; ++i)
    for (int j = -4; j <= 4; ++j) {
      const Eigen::Vector2d base(i * a + j * a / 2, j * 1.5 * acc);  // i a1 + j a2
      for (const Eigen::Vector2d& r : {base, Eigen::Vector2d(base + Eigen::Vector2d(0, acc))})
        if (inWidth(r.x()) && r.y() > -eps && r.y() < period - eps) carbons.push_back(r);
    }
  for (const auto& c : carbons) place("C", c.x(), c.y());
  for (const auto& c : carbons) {
    // Graphene neighbours of c (sublattice A: up, lower-left, lower-right; B: the reverse).
    const bool sublatticeA = [&] {
      const double j = std::round(c.y() / (1.5 * acc));
      return std::abs(c.y() - j * 1.5 * acc) < 1e-6;
    }();
    const double s = sublatticeA ? 1.0 : -1.0;
    for (const Eigen::Vector2d& d : {Eigen::Vector2d(0, s * acc), Eigen::Vector2d(-a / 2, -s * acc / 2),
                                     Eigen::Vector2d(a / 2, -s * acc / 2)})
      if (!inWidth(c.x() + d.x())) {
        const Eigen::Vector2d h = c + (1.09 / 1.42) * d;
        place("H", h.x(), h.y());
      }
  }
  return cell;
}

}  // namespace mesochain::testing
