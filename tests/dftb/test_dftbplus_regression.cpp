// Side-by-side regression against DFTB+ 25.1 on the same geometries, tables, temperatures and
// k-point sets (non-SCC, pbc-0-3). Inputs, geometries and DFTB+'s numbers are in
// tests/data/dftbplus/<case>/ (see its README); tolerances per quantity in tolerances.json.
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/units.hpp"
#include "dftb/calculator.hpp"

using namespace mesochain;
using nlohmann::json;

namespace {
json load(const std::string& path) {
  std::ifstream f(path);
  EXPECT_TRUE(f.good()) << path;
  return json::parse(f);
}

const json& tolerances() {
  static const json t = load(std::string(MESOCHAIN_TEST_DATA) + "/dftbplus/tolerances.json");
  return t;
}

struct Case {
  objective::ObjectiveCell cell;
  int nKappa = 1;
  double kT = 0;
  json ref;
};

Case readCase(const std::string& name) {
  Case c;
  c.ref = load(std::string(MESOCHAIN_TEST_DATA) + "/dftbplus/" + name + "/reference.json");
  const json& g = c.ref["geometry"];
  const auto& xyz = g["coords_bohr_as_used"];
  const std::string type = g["gen_type"];
  if (type == "H") {
    c.cell.symmetry = objective::Symmetry::screw(g["helical_translation_bohr"].get<double>(),
                                                 g["helical_twist_rad"].get<double>(),
                                                 g["rotation_order_Cn"].get<int>());
    // HelicalUniform {N 0.5}: k1 = (i + 1/2)/(2N), i < N, for every k2 = j/C_n: our midpoint
    // grid of 2N kappa points reduced by time reversal, with all mu.
    const int n = c.ref["kpoints"]["n"].get<int>() / c.cell.symmetry.rotationOrder();
    c.nKappa = 2 * n;
    EXPECT_NEAR(c.ref["kpoints"]["points"][0][0].get<double>(), 0.5 / c.nKappa, 1e-15);
  } else if (type == "S") {
    const auto& lat = g["lattice_vectors_bohr"];
    c.cell.symmetry = objective::Symmetry::screw(lat[2][2].get<double>(), 0.0, 1);
    // 1x1xN grid with shift 1/2, merged k with -k: N/2 points (m + 1/2)/N.
    c.nKappa = 2 * c.ref["kpoints"]["n"].get<int>();
    EXPECT_NEAR(c.ref["kpoints"]["points"][0][2].get<double>(), 0.5 / c.nKappa, 1e-15);
  } else {
    c.cell.symmetry = objective::Symmetry::ring(1);  // a molecule
  }
  for (size_t a = 0; a < xyz.size(); ++a)
    c.cell.addAtom(g["species"][a].get<std::string>(),
                   {xyz[a][0].get<double>(), xyz[a][1].get<double>(), xyz[a][2].get<double>()});
  c.kT = c.ref["kT_Hartree"].get<double>();
  return c;
}

dftb::Result compute(const Case& c, dftb::EigenvectorPath path) {
  std::map<std::string, std::string> files;
  for (const auto& a : c.cell.speciesNames)
    for (const auto& b : c.cell.speciesNames)
      files[a + "-" + b] = std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/" + a + "-" + b + ".skf";
  auto params = std::make_shared<const dftb::ParameterSet>(
      dftb::ParameterSet::load(c.cell.speciesNames, files, "regression"));
  dftb::CalculatorSettings s;
  s.band.helicalKPoints = c.nKappa;
  s.band.electronicTemperature = c.kT;
  s.band.eigenvectors = path;
  return dftb::Calculator(params, s).evaluate(c.cell, {true, false});
}

void compare(const std::string& name) {
  const Case c = readCase(name);
  // Both eigenvector paths (dftb/eigensolver.hpp), whichever Automatic would pick.
  for (auto path : {dftb::EigenvectorPath::AllVectors, dftb::EigenvectorPath::OccupiedOnly}) {
    SCOPED_TRACE(path == dftb::EigenvectorPath::AllVectors ? "all vectors" : "occupied only");
    const dftb::Result r = compute(c, path);
    const json& ref = c.ref;
    const json& tol = tolerances();
    const json& exact = ref["derived_from_results_tag"];
    EXPECT_NEAR(r.freeEnergy, ref["summary"]["total_mermin_free_energy"].get<double>(),
                tol["mermin_free_energy"].get<double>()) << name;
    EXPECT_NEAR(r.energies.at("band"), exact["band_energy"].get<double>(), tol["band_energy"].get<double>()) << name;
    EXPECT_NEAR(r.energies.at("entropy_term_ts"), exact["TS"].get<double>(), tol["entropy_term"].get<double>()) << name;
    EXPECT_NEAR(r.energies.at("repulsive"), exact["repulsive_energy"].get<double>(),
                tol["repulsive_energy"].get<double>()) << name;
    EXPECT_NEAR(r.extras.at("electrons"), ref["summary"]["number_of_electrons"].get<double>(), 1e-12);
    const json& f = ref["forces_richardson"]["forces"];
    double worst = 0;
    for (int a = 0; a < c.cell.atomCount(); ++a)
      for (int k = 0; k < 3; ++k)
        worst = std::max(worst, std::abs(-r.gradient(k, a) - f[a][k].get<double>()));
    EXPECT_LT(worst, tol["forces"].get<double>()) << name;
    // Metals: the root of N(mu) = N_el; gapped molecules: mid-gap in both codes.
    EXPECT_NEAR(r.extras.at("fermi_level"), ref["summary"]["fermi_level"].get<double>(),
                  tol["fermi_level"].get<double>()) << name;
  }
}
}  // namespace

TEST(DftbPlusRegression, MethaneCluster) { compare("ch4"); }
TEST(DftbPlusRegression, EthyleneCluster) { compare("c2h4_dimer_like"); }
TEST(DftbPlusRegression, Cnt55TranslationalCellOneDimensional) { compare("cnt55_translational"); }
TEST(DftbPlusRegression, Cnt55TranslationalIdeal) { compare("cnt55_translational_ideal"); }
TEST(DftbPlusRegression, Cnt55HelicalCell) { compare("cnt55_helical"); }
TEST(DftbPlusRegression, Cnt55HelicalIdeal) { compare("cnt55_helical_ideal"); }
