// Lennard-Jones dispersion with the r^-6 tail by the helical Ewald sum: against the plain
// cutoff sum with a very long cutoff, finite-difference gradients, and the cell-file switch.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "dftb/dispersion_ewald.hpp"
#include "input/cell_file.hpp"

using namespace mesochain;
using dftb::EwaldDispersionTerm;
using dftb::UffLennardJones;

namespace {

objective::ObjectiveCell twoAtomHelix(double T, double gamma, int na) {
  objective::ObjectiveCell c;
  c.symmetry = objective::Symmetry::screw(T, gamma, na);
  c.addAtom("C", {6.2, 0.3, 0.1});
  c.addAtom("C", {5.1, 3.6, 1.4});
  return c;
}

double energyOf(const dftb::EnergyTerm& t, const objective::ObjectiveCell& c) {
  dftb::TermOutput out;
  t.evaluate(c, {}, out);
  return out.energies.free();
}

}  // namespace

TEST(DispersionEwald, EqualsCutoffSumWithAVeryLongCutoff) {
  const auto cell = twoAtomHelix(4.6, 0.52, 5);
  // Short-range part V_LJ + C6/r^6 = eps (r0/r)^12 cut at 60 Bohr: < 1e-14 Ha left out.
  const auto lj = UffLennardJones::carbonDefaults(60.0);
  const EwaldDispersionTerm ewaldTerm(lj, 1e-12);
  // The plain sum to 3000 Bohr leaves out -(2/5) N_o lambda eps r0^6 / r_c^5 ~ 1e-16 Ha.
  const auto longLj = std::make_shared<UffLennardJones>(lj.epsilon(), lj.r0(), 3000.0);
  const dftb::PairPotentialTerm plain(
      "plain", [p = longLj.get()](int, int) -> const dftb::RadialPotential& { return *p; }, 3000.0);
  const double e = energyOf(ewaldTerm, cell), ref = energyOf(plain, cell);
  EXPECT_NEAR(e, ref, 1e-10 * std::abs(ref));
  // ... while a plain 60 Bohr cutoff misses a visible part of the tail.
  const dftb::PairPotentialTerm cut(
      "cut", [p = &lj](int, int) -> const dftb::RadialPotential& { return *p; }, 60.0);
  EXPECT_GT(std::abs(energyOf(cut, cell) - ref), 1e-6 * std::abs(ref));
}

TEST(DispersionEwald, GradientsMatchFiniteDifferences) {
  const auto cell = twoAtomHelix(4.6, 0.52, 5);
  const EwaldDispersionTerm term(UffLennardJones::carbonDefaults(30.0), 1e-12);
  dftb::TermOutput out;
  term.evaluate(cell, {true, true}, out);
  const double h = 1e-4;
  for (int i = 0; i < 2; ++i)
    for (int a = 0; a < 3; ++a) {
      auto p = cell, m = cell;
      p.positions(a, i) += h;
      m.positions(a, i) -= h;
      EXPECT_NEAR(out.gradient(a, i), (energyOf(term, p) - energyOf(term, m)) / (2 * h), 1e-9);
    }
  auto tp = cell, tm = cell, gp = cell, gm = cell;
  tp.symmetry = cell.symmetry.withTranslation(4.6 + h);
  tm.symmetry = cell.symmetry.withTranslation(4.6 - h);
  gp.symmetry = cell.symmetry.withTwist(0.52 + h);
  gm.symmetry = cell.symmetry.withTwist(0.52 - h);
  EXPECT_NEAR(out.dEdTranslation, (energyOf(term, tp) - energyOf(term, tm)) / (2 * h), 1e-9);
  EXPECT_NEAR(out.dEdTwist, (energyOf(term, gp) - energyOf(term, gm)) / (2 * h), 1e-9);
}

TEST(DispersionEwald, CellFileSelectsTheSummation) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("mesochain_dispewald_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string head = R"(format = 1
[symmetry]
translation = 2.46
twist = 0.0
rotation_order = 5
[geometry]
unit = "angstrom"
atoms = [ ["C", 3.4, 0.0, 0.0], ["C", 3.3, 0.7, 1.23] ]
[kpoints]
helical = 4
[electrons]
temperature = 300
[parameters]
set = "pbc-0-3"
[dispersion]
model = "lj"
)";
  auto write = [&](const std::string& name, const std::string& extra) {
    std::ofstream(dir / name) << head << extra;
    return (dir / name).string();
  };
  const auto in = objective::readCellFile(write("a.toml", "summation = \"ewald\"\newald_tolerance = 1e-9\n"));
  EXPECT_TRUE(in.dispersion.lj.ewald);
  EXPECT_DOUBLE_EQ(in.dispersion.lj.ewaldTolerance, 1e-9);
  EXPECT_FALSE(objective::readCellFile(write("b.toml", "")).dispersion.lj.ewald);
  EXPECT_THROW(objective::readCellFile(write("c.toml", "summation = \"fast\"\n")), InputError);
  EXPECT_THROW(objective::readCellFile(write("d.toml", "summation = \"ewald\"\newald_tolerance = 1e-16\n")),
               InputError);
  EXPECT_THROW(objective::readCellFile(write("e.toml", "ewald_tolerance = 1e-9\n")), InputError);
  fs::remove_all(dir);
}

TEST(DispersionEwald, ReportsTheSplittingOfThePlan) {
  // The term reports the splitting its lattice sum ran with (taken from the sum, not planned
  // again): equal to a separate plan of the same cell, with and without gradients; none on a ring.
  const double tol = 1e-9;
  const EwaldDispersionTerm term(UffLennardJones::carbonDefaults(30.0), tol);
  ewald::LatticeSumSettings st;
  st.tolerance = tol;
  const ewald::HelicalLatticeSum sum(ewald::Kernel::InverseSixth, st);
  for (const auto& cell : {twoAtomHelix(4.6, 0.52, 5), twoAtomHelix(7.9, 0.0, 1)}) {
    const double expected = sum.plan(cell).splitting;
    EXPECT_GT(expected, 0);
    for (const dftb::EvaluationRequest request : {dftb::EvaluationRequest{false, false},
                                                  dftb::EvaluationRequest{true, true}}) {
      dftb::TermOutput out;
      if (request.gradient) out.gradient = Eigen::Matrix3Xd::Zero(3, cell.atomCount());
      term.evaluate(cell, request, out);
      ASSERT_EQ(out.extras.count("dispersion_ewald_splitting"), 1u);
      EXPECT_EQ(out.extras.at("dispersion_ewald_splitting"), expected);
    }
  }
  objective::ObjectiveCell ring;
  ring.symmetry = objective::Symmetry::ring(60);
  ring.addAtom("C", {40.0, 0.3, 0.1});
  ring.addAtom("C", {41.5, 2.6, 1.4});
  dftb::TermOutput out;
  term.evaluate(ring, {}, out);
  EXPECT_EQ(out.extras.at("dispersion_ewald_splitting"), 0.0);
}
