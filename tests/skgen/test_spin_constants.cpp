// Spin constants W_ll' and the spin-polarisation energy of free atoms (skgen/atomic_data.hpp)
// against published values (tests/data/skgen/spin-constants.json), plus the exact properties
// that do not need a reference: W = 0 without exchange-correlation, the symmetry W_sp = W_ps
// (ε_l = ∂E/∂n_l, so ∂ε_l/∂n_l' is a second derivative of E), O(δ²) convergence of the central
// differences, and the charge row reproducing the Hubbard U of the unpolarised atom.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "dftb/skf_file.hpp"
#include "skgen/atomic_data.hpp"
#include "skgen/elements.hpp"

using namespace mesochain;
using namespace mesochain::skgen;

namespace {
nlohmann::json reference() {
  std::ifstream in(std::string(MESOCHAIN_TEST_DATA) + "/skgen/spin-constants.json");
  return nlohmann::json::parse(in);
}

// Free atom of the element table on the numerical grid; the log step 0.032 changes W by
// < 1e-7 against 0.016 and 0.008 (docs/skgen.md).
AtomSettings freeAtom(const std::string& symbol, XcKind xc) {
  const Element& e = findElement(symbol, "test", "element");
  AtomSettings a;
  a.name = symbol;
  a.z = e.z;
  for (const auto& sh : e.shells) a.shells.push_back({sh.n, sh.l, {0.5 * sh.occupation, 0.5 * sh.occupation}});
  a.xc = xc;
  a.h = 0.032;
  a.rMax = 40.0;
  a.tolerance = 1e-10;
  return a;
}

// Carbon's configuration around Z = 8 without exchange-correlation.
AtomSettings bareIon() {
  AtomSettings a = freeAtom("C", XcKind::None);
  a.z = 8.0;
  return a;
}

const std::vector<int>& valence(const std::string& symbol) {
  return findElement(symbol, "test", "element").valence;
}

void expectMatrixNear(const std::vector<std::vector<double>>& w, const nlohmann::json& ref,
                      double tol, const std::string& what) {
  ASSERT_EQ(w.size(), ref.size()) << what;
  for (std::size_t i = 0; i < w.size(); ++i)
    for (std::size_t j = 0; j < w.size(); ++j)
      EXPECT_NEAR(w[i][j], ref[i][j].get<double>(), tol) << what << " W[" << i << "][" << j << "]";
}
}  // namespace

TEST(SpinConstants, PbeMatchThePublishedValues) {
  const nlohmann::json ref = reference();
  const nlohmann::json& manual = ref["dftbplus_manual"];
  const nlohmann::json& auorg = ref["auorg_readme"];
  for (const std::string symbol : {"H", "C", "N"}) {
    const OccupationDerivatives d = occupationDerivatives(freeAtom(symbol, XcKind::Pbe), valence(symbol));
    expectMatrixNear(d.w, auorg["PBE"][symbol], auorg["tolerance_Ha"].get<double>(), symbol + " auorg");
    expectMatrixNear(d.w, manual["PBE"][symbol], manual["tolerance_Ha"].get<double>(), symbol + " manual");
    if (d.w.size() == 2) {
      EXPECT_NEAR(d.w[0][1], d.w[1][0], 1e-6) << symbol;  // symmetric second derivative of E
      EXPECT_NEAR(d.u[0][1], d.u[1][0], 1e-6) << symbol;
    }
  }
}

TEST(SpinConstants, LdaMatchTheManualAndTheChargeRowIsTheHubbardU) {
  const nlohmann::json ref = reference();
  const nlohmann::json& manual = ref["dftbplus_manual"];
  for (const std::string symbol : {"H", "C"}) {
    const AtomSettings a = freeAtom(symbol, XcKind::LdaPw92);
    const OccupationDerivatives d = occupationDerivatives(a, valence(symbol));
    expectMatrixNear(d.w, manual["LDA"][symbol], manual["tolerance_Ha"].get<double>(), symbol + " manual LDA");
    // ½(∂ε↑/∂n↑ + ∂ε↑/∂n↓) of the HOMO is dε/dn of the unpolarised atom: the Hubbard U
    const int homo = static_cast<int>(d.u.size()) - 1;
    const ShellOccupation& sh = findElement(symbol, "test", "element").shells[valence(symbol)[homo]];
    // (the two central differences step differently — one spin by δ against both by δ/2 — and
    // agree to their O(δ²) error, ~5e-6 Ha at δ = 0.01; SpinConstants.ConvergeInTheStep)
    EXPECT_NEAR(d.u[homo][homo], hubbardU(a, sh.n, sh.l), 1e-5) << symbol;
    if (symbol == "C") {
      // the LDA U of the published pbc-0-3 table (Atom.CarbonHubbardUMatchesThePublishedTable)
      const dftb::SkfTable t =
          dftb::readSkfFile(std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/C-C.skf", true);
      EXPECT_NEAR(d.u[1][1], t.hubbard[1], 1e-5);
    }
  }
}

TEST(SpinConstants, VanishWithoutExchangeCorrelation) {
  // Hartree and nuclear potentials see only n↑ + n↓: ∂ε↑/∂n↑ = ∂ε↑/∂n↓ exactly, W = 0 while the
  // charge derivatives (the Hubbard matrix) stay large.
  // (the ion O2+ with carbon's configuration: without exchange the neutral atom's 2s electrons
  // feel their own repulsion and are barely bound)
  const OccupationDerivatives d = occupationDerivatives(bareIon(), valence("C"));
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t j = 0; j < 2; ++j) {
      EXPECT_NEAR(d.w[i][j], 0.0, 1e-10) << i << j;
      EXPECT_GT(d.u[i][j], 0.3) << i << j;
    }
}

TEST(SpinConstants, ConvergeInTheStep) {
  // central differences: the error falls as δ², so halving δ divides the change by ~4; the
  // default δ = 0.01 is converged to ~5e-6 Ha (well inside the published rounding)
  double w[3];
  for (int k = 0; k < 3; ++k)
    w[k] = occupationDerivatives(freeAtom("H", XcKind::Pbe), {0}, 0.02 / (1 << k)).w[0][0];
  const double d1 = w[0] - w[1], d2 = w[1] - w[2];
  EXPECT_NEAR(d1 / d2, 4.0, 0.2);
  EXPECT_LT(std::abs(d2), 1e-5);
  EXPECT_LT(std::abs(d2) / 3.0, 2e-6);  // Richardson estimate of the remaining error at δ = 0.005
}

TEST(SpinConstants, EmptyAndFullShells) {
  // Li 2p is empty: it cannot be discharged, so its row and column are those of 2s (the
  // convention of the published sets); He 1s is full: the steps go just beyond capacity.
  const OccupationDerivatives li = occupationDerivatives(freeAtom("Li", XcKind::Pbe), valence("Li"));
  EXPECT_DOUBLE_EQ(li.w[1][1], li.w[0][0]);
  EXPECT_DOUBLE_EQ(li.w[0][1], li.w[0][0]);
  EXPECT_LT(li.w[0][0], 0.0);
  const AtomSettings he = freeAtom("He", XcKind::Pbe);
  const OccupationDerivatives d = occupationDerivatives(he, valence("He"));
  EXPECT_LT(d.w[0][0], -0.05);
  EXPECT_NEAR(d.u[0][0], hubbardU(he, 1, 0), 1e-5);  // O(δ²) of two difference schemes
}

TEST(SpinPolarisationEnergy, ReproducesThePbc03AtomicLines) {
  // The "SPE" field of the .skf atomic line is E(spin-polarised atom) − E(unpolarised atom)
  // (slakoformat.pdf: "spin polarisation error for calculating formation energies"); the
  // pbc-0-3 set computed carbon with PBE, hydrogen and nitrogen with LDA.
  const nlohmann::json ref = reference()["spin_polarisation_energy"];
  for (const std::string symbol : {"C", "H", "N"}) {
    const dftb::SkfTable t = dftb::readSkfFile(
        std::string(MESOCHAIN_SOURCE_DIR) + "/params/pbc-0-3/" + symbol + "-" + symbol + ".skf", true);
    const XcKind xc = parseXcKind(ref[symbol]["functional"].get<std::string>(), "spin-constants.json");
    EXPECT_NEAR(spinPolarisationEnergy(freeAtom(symbol, xc)), t.spinPolarisationError,
                ref[symbol]["tolerance_Ha"].get<double>())
        << symbol;
  }
  // and it is a property of exchange-correlation: zero without it
  EXPECT_NEAR(spinPolarisationEnergy(bareIon()), 0.0, 1e-9);
}
