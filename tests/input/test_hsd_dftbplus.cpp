// DFTB+'s own inputs (tests/data/dftbplus/<case>/dftb_in.hsd and geo.gen, DFTB+ 25.1) read by
// mesochain's HSD reader give DFTB+'s numbers: the same geometry in Bohr as DFTB+ used, the
// same k T, and the energies, Fermi level, charges and forces of reference.json to the
// tolerances of the side-by-side regressions (tolerances.json, tolerances_scc.json). Then the
// cell file that `convert` writes from the input gives the same numbers again. The polar CH
// chain (ch_chain_1d), which DFTB+ computes in 3-D cells of growing vacuum, gives the
// vacuum-extrapolated DFTB+ numbers from every one of those inputs.
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "hsd_support.hpp"
#include "input/hsd/dftb_input.hpp"
#include "input/cell_file.hpp"
#include "input/cell_calculator.hpp"
#include "tests/support/vacuum_extrapolation.hpp"

using namespace mesochain;
using nlohmann::json;

namespace {
json load(const std::string& path) {
  std::ifstream f(path);
  EXPECT_TRUE(f.good()) << path;
  return json::parse(f);
}

json reference(const std::string& name) {
  return load(std::string(MESOCHAIN_TEST_DATA) + "/dftbplus/" + name + "/reference.json");
}

// The geometry DFTB+ used (Bohr, its 0.529177249 Å) to rounding.
void expectDftbPlusGeometry(const objective::CellInput& in, const json& geometry) {
  const auto& xyz = geometry["coords_bohr_as_used"];
  ASSERT_EQ(static_cast<std::size_t>(in.cell.atomCount()), xyz.size());
  for (int a = 0; a < in.cell.atomCount(); ++a) {
    EXPECT_EQ(in.cell.speciesOf(a), geometry["species"][a].get<std::string>());
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(in.cell.positions(k, a), xyz[a][k].get<double>(), 1e-12);
  }
  if (geometry.contains("helical_translation_bohr")) {
    EXPECT_NEAR(in.cell.symmetry.translation(), geometry["helical_translation_bohr"].get<double>(), 1e-12);
  }
  if (geometry.contains("lattice_vectors_bohr")) {
    EXPECT_NEAR(in.cell.symmetry.translation(), geometry["lattice_vectors_bohr"][2][2].get<double>(), 1e-12);
  }
}

double worstForce(const dftb::Result& r, const json& forces) {
  double worst = 0;
  for (std::size_t a = 0; a < forces.size(); ++a)
    for (int k = 0; k < 3; ++k)
      worst = std::max(worst, std::abs(-r.gradient(k, static_cast<int>(a)) - forces[a][k].get<double>()));
  return worst;
}

// Reading the cell file `convert` writes gives the same energy and forces.
void expectConvertedFileAgrees(const objective::CellInput& in, const dftb::Result& r, const std::string& name) {
  const std::string toml = mesochain::testing::hsdTempDir("converted") + "/" + name + ".toml";
  objective::writeCellFile(toml, in);
  const objective::CellInput back = objective::readCellFile(toml);
  EXPECT_EQ(back.band.helicalKPoints, in.band.helicalKPoints);
  EXPECT_EQ(back.task.type, in.task.type);
  const dftb::Result rb = objective::makeCalculator(back).evaluate(back.cell, {true, false});
  EXPECT_NEAR(rb.freeEnergy, r.freeEnergy, 1e-11) << name;
  EXPECT_LT((rb.gradient - r.gradient).cwiseAbs().maxCoeff(), 1e-10) << name;
}

void compareNonScc(const std::string& name) {
  const json ref = reference(name);
  const json tol = load(std::string(MESOCHAIN_TEST_DATA) + "/dftbplus/tolerances.json");
  const objective::CellInput in = input::hsd::readDftbInput(mesochain::testing::copiedDftbPlusCase(name));
  expectDftbPlusGeometry(in, ref["geometry"]);
  EXPECT_NEAR(in.band.electronicTemperature, ref["kT_Hartree"].get<double>(), 1e-17);
  EXPECT_EQ(in.task.type, "forces");  // Analysis { PrintForces = Yes }, no driver
  EXPECT_FALSE(in.scc.enabled);
  const dftb::Result r = objective::makeCalculator(in).evaluate(in.cell, {true, false});
  const json& exact = ref["derived_from_results_tag"];
  EXPECT_NEAR(r.freeEnergy, ref["summary"]["total_mermin_free_energy"].get<double>(),
              tol["mermin_free_energy"].get<double>());
  EXPECT_NEAR(r.energies.at("band"), exact["band_energy"].get<double>(), tol["band_energy"].get<double>());
  EXPECT_NEAR(r.energies.at("entropy_term_ts"), exact["TS"].get<double>(), tol["entropy_term"].get<double>());
  EXPECT_NEAR(r.energies.at("repulsive"), exact["repulsive_energy"].get<double>(), tol["repulsive_energy"].get<double>());
  EXPECT_NEAR(r.extras.at("electrons"), ref["summary"]["number_of_electrons"].get<double>(), 1e-12);
  EXPECT_NEAR(r.extras.at("fermi_level"), ref["summary"]["fermi_level"].get<double>(), tol["fermi_level"].get<double>());
  EXPECT_LT(worstForce(r, ref["forces_richardson"]["forces"]), tol["forces"].get<double>());
  expectConvertedFileAgrees(in, r, name);
}

void compareScc(const std::string& name) {
  const json ref = reference(name);
  const json tol = load(std::string(MESOCHAIN_TEST_DATA) + "/dftbplus/tolerances_scc.json");
  const objective::CellInput in = input::hsd::readDftbInput(mesochain::testing::copiedDftbPlusCase(name));
  expectDftbPlusGeometry(in, ref["geometry"]);
  EXPECT_TRUE(in.scc.enabled);
  EXPECT_EQ(in.scc.chargeTolerance, 1e-11);  // SCCTolerance = 1.0e-11
  EXPECT_EQ(in.scc.maxIterations, 500);      // MaxSCCIterations = 500
  const dftb::Result r = objective::makeCalculator(in).evaluate(in.cell, {true, false});
  EXPECT_EQ(r.extras.at("scc_converged"), 1.0);
  EXPECT_NEAR(r.freeEnergy, ref["mermin_energy"].get<double>(), tol["mermin_free_energy"].get<double>());
  const auto& e = ref["detailed_out_energies"];
  EXPECT_NEAR(r.energies.at("scc_coulomb"), e["Energy SCC"].get<double>(), tol["scc_energy"].get<double>());
  EXPECT_NEAR(r.energies.at("h0"), e["Energy H0"].get<double>(), tol["h0_energy"].get<double>());
  EXPECT_NEAR(r.energies.at("repulsive"), e["Repulsive energy"].get<double>(), tol["repulsive_energy"].get<double>());
  const auto& q = r.series.at("mulliken_charges");
  ASSERT_EQ(q.size(), ref["gross_atomic_charges"].size());
  for (std::size_t a = 0; a < q.size(); ++a)
    EXPECT_NEAR(q[a], ref["gross_atomic_charges"][a].get<double>(), tol["charges"].get<double>()) << a;
  EXPECT_LT(worstForce(r, ref["forces_richardson"]), tol["forces"].get<double>());
  expectConvertedFileAgrees(in, r, name);
}
}  // namespace

TEST(HsdDftbPlus, MethaneCluster) { compareNonScc("ch4"); }
TEST(HsdDftbPlus, EthyleneCluster) { compareNonScc("c2h4_dimer_like"); }
TEST(HsdDftbPlus, Cnt55SupercellFolding) { compareNonScc("cnt55_translational"); }
TEST(HsdDftbPlus, Cnt55SupercellFoldingIdeal) { compareNonScc("cnt55_translational_ideal"); }
TEST(HsdDftbPlus, Cnt55HelicalUniform) {
  // HelicalUniform { 40 0.5 } is mesochain's helical = 80.
  EXPECT_EQ(input::hsd::readDftbInput(mesochain::testing::copiedDftbPlusCase("cnt55_helical")).band.helicalKPoints, 80);
  compareNonScc("cnt55_helical");
}
TEST(HsdDftbPlus, Cnt55HelicalUniformIdeal) { compareNonScc("cnt55_helical_ideal"); }
TEST(HsdDftbPlus, SccEthylene) { compareScc("c2h4_scc"); }
TEST(HsdDftbPlus, SccBenzene) { compareScc("benzene_c6"); }

// ch_chain_1d/L<n>: DFTB+'s 3-D cells with n Å of lateral vacuum and its EwaldTolerance /
// EwaldParameter keys. mesochain reads each as the 1-D chain (the lateral vectors only set the
// vacuum), so every L gives the same numbers, and those are DFTB+'s extrapolated to infinite
// vacuum (c0 of c0 + c1/L^2 + c2/L^4 over the six runs; tolerances_scc_chain.json), not any one
// run: the largest vacuum is still off by the dipole term c1/L^2 (about 2e-7 Ha at 240 Å).
TEST(HsdDftbPlus, SccPolarChainInVacuumCells) {
  const json ref = reference("ch_chain_1d");
  const json tol = load(std::string(MESOCHAIN_TEST_DATA) + "/dftbplus/tolerances_scc_chain.json");
  std::vector<double> lengths, energies, mesochainEnergies;
  for (const auto& run : ref["runs"]) {
    const int angstrom = static_cast<int>(std::lround(run["vacuum_lattice_A"].get<double>()));
    const std::string name = "ch_chain_1d/L" + std::to_string(angstrom);
    const objective::CellInput in = input::hsd::readDftbInput(mesochain::testing::copiedDftbPlusCase(name));
    EXPECT_TRUE(in.scc.enabled) << name;
    EXPECT_EQ(in.scc.ewaldTolerance, 1e-13) << name;  // EwaldTolerance = 1.0e-13
    EXPECT_EQ(in.band.helicalKPoints, ref["kpoints"]["n"].get<int>()) << name;
    EXPECT_NEAR(in.cell.symmetry.translation(), ref["geometry"]["translation_bohr"].get<double>(), 1e-12);
    const dftb::Result r = objective::makeCalculator(in).evaluate(in.cell, {false, false});
    EXPECT_EQ(r.extras.at("scc_converged"), 1.0) << name;
    lengths.push_back(run["vacuum_lattice_bohr"].get<double>());
    energies.push_back(run["mermin_energy"].get<double>());
    mesochainEnergies.push_back(r.freeEnergy);
  }
  ASSERT_EQ(lengths.size(), 6u);
  const double c0 = mesochain::testing::fitInverseSquare(lengths, energies)[0];
  for (double e : mesochainEnergies) {
    EXPECT_NEAR(e, mesochainEnergies.front(), 1e-12);  // the vacuum is not part of the 1-D cell
    EXPECT_NEAR(e, c0, tol["mermin_free_energy"].get<double>());
  }
  EXPECT_GT(std::abs(energies.back() - c0), 10 * tol["mermin_free_energy"].get<double>());
}
