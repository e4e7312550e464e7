// `mesochain-bench ewald`: error against time of the helical Ewald sums over a sweep of
// tolerances (1/r with neutral charges, 1/r^6), and for Lennard-Jones dispersion the plain
// cutoff sum against the Ewald-summed tail (what does accuracy cost?).
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli/command.hpp"
#include "common/plot/canvas.hpp"
#include "common/plot/figure.hpp"
#include "common/plot/png_io.hpp"
#include "common/units.hpp"
#include "dftb/dispersion_ewald.hpp"
#include "ewald/helical_lattice_sum.hpp"
#include "objective/core/nanotube_builder.hpp"

namespace mesochain::app {

namespace {

struct BenchOptions {
  double seconds = 0.3;  // minimum time per measurement
  bool splittingScan = false;
  std::string png = "bench-ewald.png";
};

// One curve of the error-against-time plot.
struct Curve {
  std::string name;
  std::vector<double> seconds, error;
  bool dashed = false;
  int color = -1;  // palette index; -1: the next one
};

// Panel of |relative error| against seconds per call (log-log). Exact zeros cannot sit on a log
// axis: they are left out and the legend says how many.
plot::Image panel(const std::string& title, const std::string& xLabel, const std::vector<Curve>& curves,
                  int width = 900) {
  plot::Figure f(title);
  f.x.label = xLabel;
  f.y.label = "relative error";
  f.x.scale = f.y.scale = plot::Scale::Log10;
  const plot::Marker markers[] = {plot::Marker::Circle, plot::Marker::Square, plot::Marker::Triangle,
                                  plot::Marker::Diamond};
  int i = 0;
  for (const Curve& c : curves) {
    std::vector<double> x, y;
    for (size_t k = 0; k < c.error.size(); ++k)
      if (c.error[k] > 0) x.push_back(c.seconds[k]), y.push_back(c.error[k]);
    const size_t zeros = c.error.size() - y.size();
    plot::SeriesStyle style;
    style.marker = markers[i++ % 4];
    style.dashed = c.dashed;
    if (c.color >= 0) style.color = plot::paletteColor(c.color);
    f.add(zeros ? fmt::format("{} ({} exact zeros not shown)", c.name, zeros) : c.name, x, y, style);
  }
  return f.render(width, 600, title);
}

// Seconds per call of f, repeated until `seconds` have passed.
double timePerCall(const std::function<void()>& f, double seconds) {
  long calls = 0;
  const auto t0 = std::chrono::steady_clock::now();
  double elapsed = 0;
  do {
    f();
    ++calls;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  } while (elapsed < seconds);
  return elapsed / calls;
}

struct BenchCell {
  std::string name;
  objective::ObjectiveCell cell;
};

std::vector<BenchCell> cells() {
  const double bond = 1.42 * units::kAngstromInBohr;
  return {{"(8,4) helical", objective::buildNanotubeHelical(8, 4, bond)},
          {"(10,0) C_10", objective::buildNanotubeTranslational(10, 0, bond, true)},
          {"(6,6) translational", objective::buildNanotubeTranslational(6, 6, bond, false)}};
}

// Neutral synthetic charges: alternating +-0.1 e (an odd count leaves the last one balancing).
Eigen::VectorXd charges(int n) {
  Eigen::VectorXd q(n);
  for (int i = 0; i < n; ++i) q(i) = (i % 2 == 0 ? 0.1 : -0.1) * (1.0 + 0.05 * i);
  q(n - 1) -= q.sum();
  return q;
}

void latticeSums(const BenchOptions& opt, std::vector<Curve>& coulombCurves,
                 std::vector<Curve>& sixthCurves) {
  const std::vector<double> tolerances{1e-4, 1e-6, 1e-8, 1e-10, 1e-12};
  for (ewald::Kernel k : {ewald::Kernel::Coulomb, ewald::Kernel::InverseSixth}) {
    const bool coulomb = k == ewald::Kernel::Coulomb;
    std::cout << (coulomb ? "\n1/r (neutral charges, energy per cell)\n"
                          : "\n1/r^6 (matrix: max element error / max element)\n");
    std::cout << "cell                  N_o N_a  tolerance  alpha/Bohr^-1  r_c/Bohr  l_max  "
                 "(l,k) terms  rel. error  time/ms\n";
    for (const auto& bc : cells()) {
      const auto& cell = bc.cell;
      Curve& curve = (coulomb ? coulombCurves : sixthCurves).emplace_back();
      curve.name = fmt::format("{} (N_o = {})", bc.name, cell.atomCount());
      const Eigen::VectorXd q = charges(cell.atomCount());
      ewald::LatticeSumSettings ref;
      ref.tolerance = 1e-13;
      const Eigen::MatrixXd phiRef = ewald::HelicalLatticeSum(k, ref).matrix(cell);
      const double eRef = 0.5 * q.dot(phiRef * q);
      for (double tol : tolerances) {
        ewald::LatticeSumSettings st;
        st.tolerance = tol;
        const ewald::HelicalLatticeSum sum(k, st);
        Eigen::MatrixXd phi;
        const double t = timePerCall([&] { phi = sum.matrix(cell); }, opt.seconds);
        const double err =
            coulomb ? std::abs(0.5 * q.dot(phi * q) - eRef) / std::abs(eRef)
                    : (phi - phiRef).cwiseAbs().maxCoeff() / phiRef.cwiseAbs().maxCoeff();
        const auto plan = sum.plan(cell);
        curve.seconds.push_back(t);
        curve.error.push_back(err);
        std::cout << fmt::format("{:20s} {:4d} {:3d}  {:9.0e}  {:13.3f}  {:8.2f}  {:5d}  {:11d}  "
                                 "{:10.2e}  {:7.3f}\n",
                                 bc.name, cell.atomCount(), cell.symmetry.rotationOrder(), tol,
                                 plan.splitting, plan.realSpaceCutoff, plan.maxAngularOrder,
                                 plan.reciprocalTerms, err, 1e3 * t)
                  << std::flush;
      }
    }
  }
}

// Time and error of the Coulomb energy at tolerance 1e-10 for fixed splitting parameters (the
// cost model's choice is marked).
void splittingScan(const BenchOptions& opt) {
  std::cout << "\n1/r at tolerance 1e-10, splitting parameter scan\n"
               "cell                  alpha/Bohr^-1  rel. error  time/ms\n";
  for (const auto& bc : cells()) {
    const Eigen::VectorXd q = charges(bc.cell.atomCount());
    ewald::LatticeSumSettings ref;
    ref.tolerance = 1e-13;
    const double eRef = ewald::HelicalLatticeSum(ewald::Kernel::Coulomb, ref).energy(bc.cell, q);
    const double chosen = ewald::HelicalLatticeSum(ewald::Kernel::Coulomb, {1e-10, {}}).plan(bc.cell).splitting;
    for (double a : {chosen, 0.03, 0.06, 0.1, 0.2, 0.3, 0.5}) {
      ewald::LatticeSumSettings st{1e-10, a};
      const ewald::HelicalLatticeSum sum(ewald::Kernel::Coulomb, st);
      double e = 0;
      const double t = timePerCall([&] { e = sum.energy(bc.cell, q); }, opt.seconds);
      std::cout << fmt::format("{:20s}  {:13.3f}{}  {:10.2e}  {:7.3f}\n", bc.name, a,
                               a == chosen ? "*" : " ", std::abs(e - eRef) / std::abs(eRef), 1e3 * t)
                << std::flush;
    }
  }
}

double energyOf(const dftb::EnergyTerm& t, const objective::ObjectiveCell& c) {
  dftb::TermOutput out;
  t.evaluate(c, {}, out);
  return out.energies.free();
}

void dispersion(const BenchOptions& opt, std::vector<Curve>& curves) {
  std::cout << "\nLennard-Jones dispersion (carbon UFF-type, eps = 0.069 kcal/mol, r0 = 3.8 A): "
               "energy per cell\n";
  std::cout << "cell                  summation  setting         rel. error  time/ms\n";
  int cellIndex = 0;
  for (const auto& bc : cells()) {
    const auto& cell = bc.cell;
    const auto base = dftb::UffLennardJones::carbonDefaults(60.0 * units::kAngstromInBohr);
    const double eRef = energyOf(dftb::EwaldDispersionTerm(base, 1e-13), cell);
    Curve cut, ew;
    cut.name = bc.name + ", cutoff 10-120 A";
    cut.dashed = true;
    ew.name = bc.name + ", Ewald 1e-4..1e-10";
    cut.color = ew.color = cellIndex++;
    for (double rcA : {10.0, 20.0, 30.0, 60.0, 120.0}) {
      const double rc = rcA * units::kAngstromInBohr;
      auto lj = std::make_shared<dftb::UffLennardJones>(base.epsilon(), base.r0(), rc);
      const dftb::PairPotentialTerm term(
          "lj", [p = lj.get()](int, int) -> const dftb::RadialPotential& { return *p; }, rc);
      double e = 0;
      const double t = timePerCall([&] { e = energyOf(term, cell); }, opt.seconds);
      cut.seconds.push_back(t);
      cut.error.push_back(std::abs(e - eRef) / std::abs(eRef));
      std::cout << fmt::format("{:20s}  cutoff     r_c = {:5.0f} A   {:10.2e}  {:7.3f}\n", bc.name,
                               rcA, std::abs(e - eRef) / std::abs(eRef), 1e3 * t)
                << std::flush;
    }
    for (double tol : {1e-4, 1e-6, 1e-8, 1e-10}) {
      // Short-range part eps (r0/r)^12 cut at the cell-file default 30 A: 1e-11 eps per pair.
      const dftb::EwaldDispersionTerm term(
          dftb::UffLennardJones(base.epsilon(), base.r0(), 30.0 * units::kAngstromInBohr), tol);
      double e = 0;
      const double t = timePerCall([&] { e = energyOf(term, cell); }, opt.seconds);
      ew.seconds.push_back(t);
      ew.error.push_back(std::abs(e - eRef) / std::abs(eRef));
      std::cout << fmt::format("{:20s}  ewald      tol = {:7.0e}   {:10.2e}  {:7.3f}\n", bc.name, tol,
                               std::abs(e - eRef) / std::abs(eRef), 1e3 * t)
                << std::flush;
    }
    curves.push_back(cut);
    curves.push_back(ew);
  }
}

}  // namespace

Command makeBenchEwaldCommand() {
  auto sub = std::make_shared<CLI::App*>(nullptr);
  auto opt = std::make_shared<BenchOptions>();
  Command c;
  c.attach = [sub, opt](CLI::App& bench) {
    *sub = bench.add_subcommand("ewald", "helical Ewald sums: error against time; dispersion "
                                         "cutoff sum vs Ewald");
    (*sub)->add_option("--seconds", opt->seconds, "minimum time per measurement");
    (*sub)->add_flag("--splitting-scan", opt->splittingScan,
                     "only: time and error of 1/r against the splitting parameter");
    (*sub)->add_option("--png", opt->png,
                       "plot error against time (1/r, 1/r^6, dispersion cutoff vs Ewald) here");
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [opt] {
    if (opt->splittingScan) {
      splittingScan(*opt);
      return 0;
    }
    std::vector<Curve> coulomb, sixth, lj;
    latticeSums(*opt, coulomb, sixth);
    dispersion(*opt, lj);
    const plot::Image top =
        plot::besideEachOther(panel("1/r: energy error against time (tolerance 1e-4..1e-12)",
                                    "seconds per matrix()", coulomb),
                              panel("1/r^6: max element error against time (1e-4..1e-12)",
                                    "seconds per matrix()", sixth));
    const plot::Image bottom = panel("Lennard-Jones dispersion: cutoff sum (dashed) vs Ewald",
                                     "seconds per energy", lj, 1800);
    plot::writePng(opt->png, plot::aboveEachOther(top, bottom));
    std::cout << "\nwrote " << opt->png << "\n";
    return 0;
  };
  return c;
}

}  // namespace mesochain::app
