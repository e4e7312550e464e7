// Radial Kohn-Sham solver: hydrogen-like levels (closed form) and the free carbon atom against
// the NIST atomic reference data (tests/data/skgen/nist-carbon.json).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "dftb/skf_file.hpp"
#include "skgen/atom.hpp"
#include "skgen/atomic_data.hpp"
#include "skgen/radial_schrodinger.hpp"

using namespace mesochain;
using namespace mesochain::skgen;

namespace {
std::vector<double> coulomb(const LogGrid& g, double z) {
  std::vector<double> v(g.size());
  for (int i = 0; i < g.size(); ++i) v[i] = -z / g.r[i];
  return v;
}

nlohmann::json nist() {
  std::ifstream in(std::string(MESOCHAIN_TEST_DATA) + "/skgen/nist-carbon.json");
  return nlohmann::json::parse(in);
}

AtomSettings carbon(XcKind xc) {
  AtomSettings s;
  s.name = "C";
  s.z = 6;
  s.shells = {{1, 0, {1.0, 1.0}}, {2, 0, {1.0, 1.0}}, {2, 1, {1.0, 1.0}}};
  s.xc = xc;
  s.h = 0.008;  // converged to ~1e-8 Ha (Atom.TotalEnergyConvergesWithTheGrid)
  return s;
}
}  // namespace

TEST(RadialSchrodinger, HydrogenLikeLevelsAreExact) {
  for (double z : {1.0, 6.0}) {
    const LogGrid g = LogGrid::make(1e-7 / z, 80.0 / z, 0.002);
    const std::vector<double> v = coulomb(g, z);
    for (int n = 1; n <= 3; ++n) {
      for (int l = 0; l < n; ++l) {
        const RadialState st = solveRadial(g, v, z, n, l, std::nan(""));
        EXPECT_NEAR(st.energy, -z * z / (2.0 * n * n), 1e-10 * z * z)
            << "Z=" << z << " n=" << n << " l=" << l;
      }
    }
  }
}

TEST(RadialSchrodinger, HydrogenGroundStateIsTwoExpMinusR) {
  const LogGrid g = LogGrid::make(1e-7, 60.0, 0.002);
  const RadialState st = solveRadial(g, coulomb(g, 1.0), 1.0, 1, 0, -0.4);
  double worst = 0.0;
  for (int i = 0; i < g.size(); i += 50) {
    const double r = g.r[i];
    worst = std::max(worst, std::abs(st.u[i] - 2.0 * r * std::exp(-r)));
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(RadialSchrodinger, ErrorsShrinkAsTheFourthPowerOfTheStep) {
  // Numerov: halving h divides the eigenvalue error by ~16.
  double err[2];
  for (int k = 0; k < 2; ++k) {
    const LogGrid g = LogGrid::make(1e-7, 60.0, 0.04 / (1 << k));
    err[k] = std::abs(solveRadial(g, coulomb(g, 1.0), 1.0, 2, 1, std::nan("")).energy + 0.125);
  }
  EXPECT_GT(err[0] / err[1], 12.0);
  EXPECT_LT(err[0] / err[1], 20.0);
}

TEST(Atom, CarbonLdaMatchesNist) {
  const nlohmann::json ref = nist();
  const double tol = ref["tolerance_Ha"];
  const AtomSolution a = solveAtom(carbon(XcKind::LdaVwn));
  EXPECT_NEAR(a.energies.total, ref["LDA"]["Etot"].get<double>(), tol);
  EXPECT_NEAR(a.shell(1, 0).energy[0], ref["LDA"]["1s"].get<double>(), tol);
  EXPECT_NEAR(a.shell(2, 0).energy[0], ref["LDA"]["2s"].get<double>(), tol);
  EXPECT_NEAR(a.shell(2, 1).energy[0], ref["LDA"]["2p"].get<double>(), tol);
}

TEST(Atom, CarbonSpinPolarisedLdaMatchesNist) {
  const nlohmann::json ref = nist();
  const double tol = ref["tolerance_Ha"];
  AtomSettings s = carbon(XcKind::LdaVwn);
  s.polarised = true;
  s.shells[2].occupation = {2.0, 0.0};  // 2p: both electrons in the majority spin
  const AtomSolution a = solveAtom(s);
  EXPECT_NEAR(a.energies.total, ref["LSD"]["Etot"].get<double>(), tol);
  const char* names[] = {"1s", "2s", "2p"};
  for (int k = 0; k < 3; ++k) {
    for (int sp = 0; sp < 2; ++sp) {
      EXPECT_NEAR(a.shells[k].energy[sp], ref["LSD"][names[k]][sp].get<double>(), tol)
          << names[k] << " spin " << sp;
    }
  }
}

TEST(Atom, TotalEnergyConvergesWithTheGrid) {
  // Halving the step of the logarithmic grid: the change shrinks ~16x (Numerov O(h^4)).
  double e[3];
  for (int k = 0; k < 3; ++k) {
    AtomSettings s = carbon(XcKind::LdaVwn);
    s.h = 0.016 / (1 << k);
    e[k] = solveAtom(s).energies.total;
  }
  const double d1 = std::abs(e[1] - e[0]), d2 = std::abs(e[2] - e[1]);
  EXPECT_GT(d1 / d2, 10.0);
  EXPECT_LT(d2, 1e-6);
}

TEST(Atom, PbeCarbonLevelsMatchThePublishedOnSiteEnergies) {
  // The pbc-0-3 C-C table (PBE, free spherical atom on-site energies; its documentation block
  // names the functional) is an independent reference for the GGA potential, including the
  // divergence term; the issue asks for 1e-5 Ha.
  const dftb::SkfTable t =
      dftb::readSkfFile(std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/C-C.skf", true);
  const AtomSolution a = solveAtom(carbon(XcKind::Pbe));
  EXPECT_NEAR(a.shell(2, 0).energy[0], t.onsite[0], 1e-5);
  EXPECT_NEAR(a.shell(2, 1).energy[0], t.onsite[1], 1e-5);
  EXPECT_LT(a.energies.total, -37.6);  // GGA lies well below LDA (-37.43 Ha)
}

TEST(Atom, NonConvergenceIsAClearError) {
  AtomSettings s = carbon(XcKind::LdaVwn);
  s.maxIterations = 3;
  try {
    solveAtom(s);
    FAIL() << "expected NumericalError";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("did not converge in 3 iterations"), std::string::npos)
        << e.what();
  }
}

TEST(Atom, ConfinementRadiusTooSmallForABoundStateIsAnInputError) {
  AtomSettings s = carbon(XcKind::LdaVwn);
  s.confinement = Confinement::powerLaw(0.8, 2.0);
  const AtomSolution a = solveAtom(s);
  EXPECT_THROW(requireBound(a, 2, 1, "elements.toml", "C.confinement.p"), InputError);
  const AtomSolution free = solveAtom(carbon(XcKind::LdaVwn));
  EXPECT_NO_THROW(requireBound(free, 2, 1, "elements.toml", "C.confinement.p"));
}

TEST(Atom, CarbonHubbardUMatchesThePublishedTable) {
  // The pbc-0-3 U (0.364302) is reproduced by the LDA (PW92) derivative of the 2p level, not by
  // PBE (0.36468): the published set took its Hubbard U from an LDA atom although its integrals
  // are PBE. The tolerance is 1e-4; the agreement is ~1e-6.
  const dftb::SkfTable t =
      dftb::readSkfFile(std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/C-C.skf", true);
  AtomSettings s = carbon(XcKind::LdaPw92);
  s.h = 0.008;
  s.tolerance = 1e-10;
  const double u = hubbardU(s, 2, 1);
  EXPECT_NEAR(u, t.hubbard[1], 1e-4);
  // the central difference is converged in δ: halving it changes U by far less than 1e-4
  EXPECT_NEAR(hubbardU(s, 2, 1, 0.005), u, 1e-6);
}
