// One conformance suite for every registered dftb energy term (in the spirit of LAMMPS's one
// YAML per style and a single runner): each registered term has at least one case below (a
// test fails for a registered term without one), and every case is checked by the same body,
// on the term alone (built by its registration's factory; a charge interaction through the band
// term it makes self-consistent):
//  * gradient: dF/dx of every cell atom against central finite differences of the term's
//    free energy (ledger Energy entries minus TS);
//  * strain: dF/dT and dF/dgamma against central finite differences of the screw parameters;
//  * objective cell = supercell: M screw steps written out as one cell of screw (M T, M gamma)
//    (the translational supercell when M gamma is a multiple of 2 pi / N_a, as for the tubes
//    below) have M times the energy, and the copies' gradients are the cell's rotated;
//  * invariance: a rotation of all atoms about the screw axis and a shift along it change no
//    energy and rotate the gradient (the only rigid motions an objective cell allows).
// Also here: the calculator sums every built term into its ledger (a term the calculator has
// never heard of included), so a new term cannot have forces and no energy.
#include <cmath>
#include <functional>
#include <memory>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <omp.h>

#include "dftb/charge_cache.hpp"
#include "dftb/dispersion_lj.hpp"
#include "dftb/pair_potential_term.hpp"
#include "dftb/term_registry.hpp"
#include "objective/core/graphene_builder.hpp"
#include "scc_support.hpp"
#include "support.hpp"

namespace mesochain::dftb {
namespace {

using objective::ObjectiveCell;
using objective::Symmetry;

// A term only this test binary registers: a soft pair repulsion V = eps (1 - r/r_c)^3 between
// every two atoms closer than r_c, built when `softPairWanted` is set. Stands for a new term:
// the calculator has no line about it.
bool softPairWanted = false;

class SoftCube final : public RadialPotential {
 public:
  double cutoff() const override { return kCutoff; }
  void evaluate(double r, double& v, double& dv) const override {
    v = dv = 0.0;
    if (r >= kCutoff) return;
    const double x = 1.0 - r / kCutoff;
    v = kEps * x * x * x;
    dv = -3.0 * kEps * x * x / kCutoff;
  }
  static constexpr double kEps = 0.01, kCutoff = 6.0;  // Hartree, Bohr
};

MESOCHAIN_DFTB_TERM(TermRegistration{
    "test_soft_pair", 900, "test only: soft cubic pair repulsion", false,
    [](const CalculatorSettings&) { return softPairWanted; },
    [](const TermBuild&) -> std::unique_ptr<EnergyTerm> {
      return std::make_unique<PairTerm<SamePotentialEvaluator<SoftCube>>>(
          "test_soft_pair", SamePotentialEvaluator<SoftCube>{SoftCube()});
    },
    nullptr})

struct TermCase {
  std::string term;  // registration name
  std::string label;
  std::shared_ptr<const ParameterSet> params;
  CalculatorSettings settings;
  ObjectiveCell cell;  // a screw cell
  double tolerance;    // on every derivative (Hartree / Bohr or rad)
  int supercellSteps;  // M; the supercell's helical k-points are settings' / M
};

void PrintTo(const TermCase& c, std::ostream* os) { *os << c.term << ": " << c.label; }

CalculatorSettings carbonSettings(int nKappa, double kelvin) {
  CalculatorSettings s;
  s.band.helicalKPoints = nKappa;
  s.band.electronicTemperature = kelvin * units::kBoltzmannHartreePerKelvin;
  return s;
}

CalculatorSettings withDispersion(CalculatorSettings s, bool ewald) {
  s.dispersion.enabled = true;
  s.dispersion.epsilon = 0.069 * units::kKcalPerMolInHartree;
  s.dispersion.r0 = 3.80 * units::kAngstromInBohr;
  s.dispersion.cutoff = 16.0;
  s.dispersion.ewald = ewald;
  s.dispersion.ewaldTolerance = 1e-12;
  return s;
}

// Kolmogorov-Crespi instead of Lennard-Jones; cutoff and taper start in Angstrom (0 and -1: the
// parameter set's own).
CalculatorSettings withKc(CalculatorSettings s, const std::string& set, double cutoff,
                          double taperStart) {
  s.kc.enabled = true;
  s.kc.parameters = set;
  s.kc.cutoff = cutoff * units::kAngstromInBohr;
  s.kc.taperStart = taperStart < 0 ? -1.0 : taperStart * units::kAngstromInBohr;
  s.kc.bondCutoff = 1.7 * units::kAngstromInBohr;
  return s;
}

ObjectiveCell distorted(ObjectiveCell c, double amplitude) {
  testing::distort(c, amplitude);
  return c;
}

std::vector<TermCase> cases() {
  const auto carbon = testing::carbonParameters();
  const ObjectiveCell zigzag = distorted(testing::zigzagHelical(5), 0.05);
  const ObjectiveCell armchair = distorted(testing::armchairHelical(4), 0.06);
  std::vector<TermCase> c;
  // Midpoint k-grids fold exactly onto the 2-step supercell's when N_kappa is divisible by 4.
  c.push_back({"band", "distorted (5,0) tube, 8 kappa, 800 K", carbon, carbonSettings(8, 800.0),
               zigzag, 2e-7, 2});
  auto scc = testing::sccSettings(2000.0, 16);
  // A charge interaction is checked through the band term it makes self-consistent.
  c.push_back({"scc", "helical CH chain, 16 kappa, 2000 K", testing::chParameters(), scc,
               testing::helicalChUnit(), 5e-8, 2});
  c.push_back({"repulsive", "distorted (5,0) tube", carbon, carbonSettings(1, 800.0), zigzag,
               1e-8, 3});
  c.push_back({"dispersion", "cutoff sum, distorted (4,4) tube", carbon,
               withDispersion(carbonSettings(1, 800.0), false), armchair, 1e-8, 2});
  c.push_back({"dispersion", "helical Ewald sum, distorted (4,4) tube", carbon,
               withDispersion(carbonSettings(1, 800.0), true), armchair, 1e-8, 2});
  // Per-element parameters (UFF C and H, DFTB+'s geometric-mean combination) on a C-H chain.
  CalculatorSettings ch = withDispersion(carbonSettings(1, 800.0), true);
  ch.dispersion.elements = {"C", "H"};
  ch.dispersion.elementEpsilon = {0.105 * units::kKcalPerMolInHartree, 0.044 * units::kKcalPerMolInHartree};
  ch.dispersion.elementR0 = {3.851 * units::kAngstromInBohr, 2.886 * units::kAngstromInBohr};
  c.push_back({"dispersion", "per-element UFF C/H, helical Ewald sum, helical CH chain",
               testing::chParameters(), ch, testing::helicalChUnit(), 1e-8, 2});
  c.push_back({"test_soft_pair", "distorted (4,4) tube", carbon, carbonSettings(1, 800.0),
               armchair, 1e-8, 3});
  // Kolmogorov-Crespi: across a small tube (normals of a curved, distorted sheet), and between
  // the two layers of a bent AB bilayer (40 sectors, R ~ 16 Angstrom), a screw cell of 8 atoms.
  c.push_back({"kolmogorov_crespi", "2005 set, taper [8, 12] A, distorted (4,4) tube", carbon,
               withKc(carbonSettings(1, 800.0), "kc2005", 12.0, 8.0), armchair, 1e-8, 2});
  c.push_back({"kolmogorov_crespi", "2018 set, its taper (16 A), distorted (5,0) tube", carbon,
               withKc(carbonSettings(1, 800.0), "ouyang2018", 0.0, -1.0), zigzag, 1e-8, 3});
  c.push_back({"kolmogorov_crespi", "2005 set, taper [8, 12] A, distorted bent AB bilayer",
               carbon, withKc(carbonSettings(1, 800.0), "kc2005", 12.0, 8.0),
               distorted(objective::buildGrapheneRingSector(
                             2, objective::Direction::Zigzag, 40, 1,
                             3.4 * units::kAngstromInBohr, 1.42 * units::kAngstromInBohr),
                         0.05),
               1e-8, 2});
  return c;
}

std::unique_ptr<EnergyTerm> build(const TermCase& tc, const CalculatorSettings& settings) {
  const TermRegistration* r = findTerm(tc.term);
  if (!r) throw std::logic_error("no registered term " + tc.term);
  TermBuild b{tc.params, settings, std::make_shared<ChargeCache>(), {}};
  if (!r->needsCharges) return r->make(b);
  b.chargeInteractions.push_back(r->makeInteraction(b));
  return findTerm("band")->make(b);
}

TermOutput evaluate(const EnergyTerm& term, const ObjectiveCell& cell, bool derivatives) {
  TermOutput out;
  term.evaluate(cell, {derivatives, derivatives}, out);
  return out;
}

double freeEnergy(const EnergyTerm& term, const ObjectiveCell& cell) {
  return evaluate(term, cell, false).energies.free();
}

// The cell of M screw steps: atoms S^zeta(x), zeta = 0..M-1, with screw (M T, M gamma) (the
// same group of images; kept as M gamma, not reduced mod 2 pi / N_a, so that the helical
// k-grid of the supercell folds onto the cell's).
ObjectiveCell screwSupercell(const ObjectiveCell& c, int m) {
  ObjectiveCell s;
  s.symmetry = Symmetry::screw(m * c.symmetry.translation(), m * c.symmetry.twist(),
                               c.symmetry.rotationOrder());
  for (int z = 0; z < m; ++z)
    for (int a = 0; a < c.atomCount(); ++a)
      s.addAtom(c.speciesOf(a), c.symmetry.apply({z, 0}, c.positions.col(a)));
  return s;
}

class TermConformance : public ::testing::TestWithParam<TermCase> {};

TEST_P(TermConformance, GradientMatchesFiniteDifferences) {
  const TermCase& tc = GetParam();
  const auto term = build(tc, tc.settings);
  const TermOutput out = evaluate(*term, tc.cell, true);
  ASSERT_EQ(out.gradient.cols(), tc.cell.atomCount());
  ASSERT_FALSE(out.energies.empty()) << "the term reported no energy";
  EXPECT_GT(out.gradient.cwiseAbs().maxCoeff(), 10 * tc.tolerance) << "a vanishing gradient";
  const double h = 1e-4;
  for (int a = 0; a < tc.cell.atomCount(); ++a)
    for (int k = 0; k < 3; ++k) {
      ObjectiveCell p = tc.cell, m = tc.cell;
      p.positions(k, a) += h;
      m.positions(k, a) -= h;
      EXPECT_NEAR(out.gradient(k, a), (freeEnergy(*term, p) - freeEnergy(*term, m)) / (2 * h),
                  tc.tolerance)
          << "atom " << a << " component " << k;
    }
}

TEST_P(TermConformance, StrainDerivativesMatchFiniteDifferences) {
  const TermCase& tc = GetParam();
  const auto term = build(tc, tc.settings);
  const TermOutput out = evaluate(*term, tc.cell, true);
  const Symmetry& s = tc.cell.symmetry;
  const double h = 1e-4;
  auto at = [&](Symmetry sym) {
    ObjectiveCell c = tc.cell;
    c.symmetry = sym;
    return freeEnergy(*term, c);
  };
  EXPECT_NEAR(out.dEdTranslation,
              (at(s.withTranslation(s.translation() + h)) -
               at(s.withTranslation(s.translation() - h))) / (2 * h),
              tc.tolerance);
  EXPECT_NEAR(out.dEdTwist,
              (at(s.withTwist(s.twist() + h)) - at(s.withTwist(s.twist() - h))) / (2 * h),
              tc.tolerance);
}

TEST_P(TermConformance, ObjectiveCellEqualsItsSupercell) {
  const TermCase& tc = GetParam();
  const int m = tc.supercellSteps;
  CalculatorSettings superSettings = tc.settings;  // k-points matter to the band terms only
  if (tc.settings.band.helicalKPoints % m == 0)
    superSettings.band.helicalKPoints = tc.settings.band.helicalKPoints / m;
  const ObjectiveCell super = screwSupercell(tc.cell, m);
  const TermOutput unit = evaluate(*build(tc, tc.settings), tc.cell, true);
  const TermOutput big = evaluate(*build(tc, superSettings), super, true);
  const double e = unit.energies.free();
  EXPECT_NEAR(big.energies.free(), m * e, 1e-9 * std::max(1.0, std::abs(m * e)));
  for (int z = 0; z < m; ++z) {
    const Eigen::Matrix3d rot = tc.cell.symmetry.rotation({z, 0});
    for (int a = 0; a < tc.cell.atomCount(); ++a)
      EXPECT_LT((big.gradient.col(z * tc.cell.atomCount() + a) - rot * unit.gradient.col(a))
                    .cwiseAbs()
                    .maxCoeff(),
                tc.tolerance)
          << "copy " << z << " atom " << a;
  }
}

TEST_P(TermConformance, RotationAboutAndShiftAlongTheAxisChangeNothing) {
  const TermCase& tc = GetParam();
  const auto term = build(tc, tc.settings);
  const TermOutput ref = evaluate(*term, tc.cell, true);
  const Eigen::Matrix3d rot = objective::rotationZ(0.731);
  ObjectiveCell moved = tc.cell;
  for (int a = 0; a < moved.atomCount(); ++a)
    moved.positions.col(a) = rot * tc.cell.positions.col(a) + Eigen::Vector3d(0, 0, 0.37);
  const TermOutput out = evaluate(*term, moved, true);
  const double e = ref.energies.free();
  EXPECT_NEAR(out.energies.free(), e, 1e-10 * std::max(1.0, std::abs(e)));
  EXPECT_LT((out.gradient - rot * ref.gradient).cwiseAbs().maxCoeff(), tc.tolerance);
  EXPECT_NEAR(out.dEdTranslation, ref.dEdTranslation, tc.tolerance);
  EXPECT_NEAR(out.dEdTwist, ref.dEdTwist, tc.tolerance);
}

INSTANTIATE_TEST_SUITE_P(EveryRegisteredTerm, TermConformance, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<TermCase>& info) {
                           return info.param.term + "_" + std::to_string(info.index);
                         });

TEST(DftbTermConformance, EveryRegisteredTermHasACase) {
  std::set<std::string> covered;
  for (const TermCase& c : cases()) {
    EXPECT_NE(findTerm(c.term), nullptr) << "a case for an unregistered term " << c.term;
    covered.insert(c.term);
  }
  for (const TermRegistration* r : registeredTerms())
    EXPECT_TRUE(covered.count(r->name))
        << "registered dftb term '" << r->name
        << "' has no case in tests/dftb/test_term_conformance.cpp";
}

// The calculator builds exactly the terms the settings want, in registration order.
TEST(DftbTermRegistry, CalculatorBuildsTheWantedTermsInOrder) {
  const auto carbon = testing::carbonParameters();
  using Names = std::vector<std::string>;
  EXPECT_EQ(Calculator(carbon, carbonSettings(1, 800.0)).termNames(), (Names{"band", "repulsive"}));
  EXPECT_EQ(Calculator(carbon, withDispersion(carbonSettings(1, 800.0), true)).termNames(),
            (Names{"band", "repulsive", "dispersion"}));
  EXPECT_EQ(Calculator(testing::chParameters(), testing::sccSettings(300.0)).termNames(),
            (Names{"band", "scc", "repulsive"}));
  for (const TermRegistration* r : registeredTerms())
    EXPECT_EQ(r->needsCharges, r->name == "scc") << r->name;
}

// A term the calculator has never heard of: its energy is in the total and the free energy,
// under its own ledger entry, beside its forces.
TEST(DftbTermRegistry, CalculatorSumsTheEnergyOfEveryBuiltTerm) {
  const auto carbon = testing::carbonParameters();
  const ObjectiveCell cell = distorted(testing::armchairHelical(4), 0.06);
  const CalculatorSettings s = carbonSettings(4, 800.0);
  const Result plain = Calculator(carbon, s).evaluate(cell, {true, true});
  softPairWanted = true;
  const Calculator withTerm(carbon, s);
  softPairWanted = false;
  const Result r = withTerm.evaluate(cell, {true, true});
  TermOutput alone;
  findTerm("test_soft_pair")->make(TermBuild{carbon, s, nullptr, {}})->evaluate(cell, {true, true}, alone);
  const double e = alone.energies.at("test_soft_pair");
  ASSERT_GT(e, 1e-3);
  EXPECT_EQ(r.energies.at("test_soft_pair"), e);
  EXPECT_NEAR(r.totalEnergy, plain.totalEnergy + e, 1e-12);
  EXPECT_NEAR(r.freeEnergy, plain.freeEnergy + e, 1e-12);
  EXPECT_LT((r.gradient - plain.gradient - alone.gradient).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(r.dFdTranslation, plain.dFdTranslation + alone.dEdTranslation, 1e-12);
  // Every Energy entry is in the total, whatever its name.
  double sum = 0.0;
  for (const LedgerEntry& entry : r.energies.entries())
    if (entry.kind == EnergyKind::Energy) sum += entry.value;
  EXPECT_EQ(r.totalEnergy, sum);
  EXPECT_EQ(r.freeEnergy, sum - r.energies.at("entropy_term_ts"));
}

// The pair kernel's threaded path (above kParallelPairs pairs) sums the same pairs as the
// serial one: equal to rounding, whatever the thread count.
TEST(DftbPairKernel, ThreadedSumEqualsTheSerialSum) {
  const ObjectiveCell cell = distorted(testing::armchairHelical(4), 0.06);
  const UffLennardJones lj(0.069 * units::kKcalPerMolInHartree, 3.80 * units::kAngstromInBohr, 800.0);
  ASSERT_GT(objective::ImageList(cell, lj.cutoff()).pairs().size(), 2 * kParallelPairs);
  const PairTerm<SamePotentialEvaluator<UffLennardJones>> term("lj", {lj});
  const int before = omp_get_max_threads();
  omp_set_num_threads(1);
  const TermOutput serial = evaluate(term, cell, true);
  omp_set_num_threads(3);
  const TermOutput threaded = evaluate(term, cell, true);
  omp_set_num_threads(before);
  const double e = serial.energies.at("lj");
  EXPECT_NEAR(threaded.energies.at("lj"), e, 1e-13 * std::abs(e));
  EXPECT_LT((threaded.gradient - serial.gradient).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_NEAR(threaded.dEdTranslation, serial.dEdTranslation, 1e-13);
  EXPECT_NEAR(threaded.dEdTwist, serial.dEdTwist, 1e-13);
  EXPECT_GT(serial.gradient.cwiseAbs().maxCoeff(), 1e-6);
}

}  // namespace
}  // namespace mesochain::dftb
