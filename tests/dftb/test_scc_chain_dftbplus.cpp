// SCC energy, charges and forces of a translational (1D-periodic) cell against DFTB+ 25.1.
// DFTB+ has no 1D Ewald sum: it ran the polar CH chain of tests/data/dftbplus/ch_chain_1d as a
// 3D-periodic cell with vacuum lattice vectors L x-hat, L y-hat (one run per L). With tin-foil
// boundary conditions the 3D sum of neutral wires differs from the isolated wire by the missing
// G = 0 term of the in-plane reciprocal sum (the 2D analogue of the 3D dipole term,
// 2 pi |M|^2 / (d V) with d = 2, V = L^2 T):
//   E_3D(L) = E_1D - pi |P_perp|^2 / (L^2 T) + O(L^-4),
// P_perp the dipole per cell across the axis; the k_z != 0 terms (inter-wire interaction of the
// axially modulated charge) die like exp(-2 pi L / T). Charges and forces inherit the 1/L^2
// term through the uniform depolarising field. The test fits every DFTB+ quantity to
// c0 + c1/L^2 + c2/L^4 and compares c0 with mesochain's 1D sum, and c1 for the energy with the
// dipole prediction from mesochain's charges. Tolerances per quantity: tolerances_scc_chain.json.
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/units.hpp"
#include "scc_support.hpp"
#include "tests/support/vacuum_extrapolation.hpp"

using namespace mesochain;
using namespace mesochain::objective;
using nlohmann::json;
using mesochain::testing::fitInverseSquare;

namespace {
json load(const std::string& path) {
  std::ifstream f(std::string(MESOCHAIN_TEST_DATA) + "/dftbplus/" + path);
  EXPECT_TRUE(f.good()) << path;
  return json::parse(f);
}
}  // namespace

TEST(SccChainDftbplus, TranslationalCellMatchesVacuumExtrapolatedDftbplus) {
  const json ref = load("ch_chain_1d/reference.json");
  const json tol = load("tolerances_scc_chain.json");
  const auto& g = ref["geometry"];
  ObjectiveCell cell;
  const double t = g["translation_bohr"].get<double>();
  cell.symmetry = Symmetry::screw(t, 0.0, 1);
  for (size_t a = 0; a < g["species"].size(); ++a) {
    const auto& x = g["coords_bohr_as_used"][a];
    cell.addAtom(g["species"][a].get<std::string>(),
                 Eigen::Vector3d(x[0].get<double>(), x[1].get<double>(), x[2].get<double>()));
  }
  const auto calc = mesochain::testing::sccCalculator(ref["temperature_K"].get<double>(),
                                                      ref["kpoints"]["n"].get<int>());
  const dftb::Result r = calc.evaluate(cell, {true, false});
  const auto& q = r.series.at("mulliken_charges");
  const int n = cell.atomCount();
  ASSERT_EQ(static_cast<int>(q.size()), n);
  EXPECT_GT(std::abs(q[3]), 0.1);  // real charge transfer

  std::vector<double> lengths, energies;
  for (const auto& run : ref["runs"]) {
    lengths.push_back(run["vacuum_lattice_bohr"].get<double>());
    energies.push_back(run["mermin_energy"].get<double>());
  }
  const Eigen::Vector3d e = fitInverseSquare(lengths, energies);
  EXPECT_NEAR(r.freeEnergy, e[0], tol["mermin_free_energy"].get<double>());
  // The 1/L^2 coefficient is the dipole term -pi |P_perp|^2 / T of the 1D charges.
  Eigen::Vector2d dipole = Eigen::Vector2d::Zero();
  for (int a = 0; a < n; ++a) dipole += q[a] * cell.positions.col(a).head<2>();
  const double predicted = -units::kPi * dipole.squaredNorm() / t;
  EXPECT_LT(predicted, -1e-3);  // a genuinely polar chain: the vacuum correction is not small
  EXPECT_NEAR(e[1] / predicted, 1.0, tol["dipole_coefficient_relative"].get<double>());
  // The largest vacuum alone is off by about the dipole term (documents the residual).
  const double largest = lengths.back();
  EXPECT_NEAR(energies.back() - r.freeEnergy, predicted / (largest * largest),
              0.05 * std::abs(predicted) / (largest * largest));

  for (int a = 0; a < n; ++a) {
    std::vector<double> qa;
    for (const auto& run : ref["runs"]) qa.push_back(run["gross_atomic_charges"][a].get<double>());
    EXPECT_NEAR(q[a], fitInverseSquare(lengths, qa)[0], tol["charges"].get<double>()) << a;
    for (int k = 0; k < 3; ++k) {
      std::vector<double> fa;
      for (const auto& run : ref["runs"])
        fa.push_back(run["forces_richardson"][a][k].get<double>());
      EXPECT_NEAR(-r.gradient(k, a), fitInverseSquare(lengths, fa)[0], tol["forces"].get<double>())
          << "atom " << a << " component " << k;
    }
  }
}
