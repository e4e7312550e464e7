// `mesochain-bench skgen`: accuracy against time of the table generator's two grids, so a user
// can pick them: the two-centre (prolate spheroidal) quadrature and the atomic log grid. Carbon
// with the pbc-0-3 recipe (Slater basis, PBE); errors against a much finer reference grid.
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/cli/command.hpp"
#include "skgen/element_basis.hpp"
#include "skgen/two_centre.hpp"

namespace mesochain::app {

namespace {
struct BenchSkgenOptions {
  std::vector<int> points = {12, 16, 24, 32, 48, 64, 96};
  int referencePoints = 160;
  std::vector<double> steps = {0.032, 0.016, 0.008, 0.004};
  double referenceStep = 0.002;
  std::vector<double> distances = {1.5, 2.7, 4.0};
};

skgen::ElementBasis carbon(double step) {
  skgen::ElementSettings s;
  s.symbol = "C";
  s.xc = skgen::XcKind::Pbe;
  s.hubbardXc = skgen::XcKind::LdaPw92;
  s.density = skgen::Confinement::powerLaw(7.0, 2.0);
  s.shells = {skgen::Confinement::powerLaw(2.7, 2.0), skgen::Confinement::powerLaw(2.7, 2.0)};
  s.slater = {{0.50, 1.14, 2.62, 6.0}, 3};
  s.h = step;
  return skgen::buildElementBasis(s);
}

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// All integrals at every distance.
std::vector<skgen::SkIntegral> integrals(const skgen::ElementBasis& b, int points,
                                         const std::vector<double>& distances) {
  skgen::TwoCentreQuadrature q;
  q.nXi = q.nEta = points;
  q.rMax = 20.0;
  const skgen::XcFunctional xc(skgen::XcKind::Pbe, false);
  std::vector<skgen::SkIntegral> all;
  for (double d : distances) {
    const auto v = skgen::twoCentreIntegrals(b.orbitals, b.orbitals, &b.atom, &b.atom, &xc, d, q);
    all.insert(all.end(), v.begin(), v.end());
  }
  return all;
}

void maxErrors(const std::vector<skgen::SkIntegral>& a, const std::vector<skgen::SkIntegral>& ref,
               double& ds, double& dh) {
  ds = dh = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ds = std::max(ds, std::abs(a[i].s - ref[i].s));
    dh = std::max(dh, std::abs(a[i].h - ref[i].h));
  }
}
}  // namespace

Command makeBenchSkgenCommand() {
  auto sub = std::make_shared<CLI::App*>(nullptr);
  auto opt = std::make_shared<BenchSkgenOptions>();
  Command c;
  c.attach = [sub, opt](CLI::App& bench) {
    *sub = bench.add_subcommand("skgen", "table generator: integral error against time of the two-centre and atom grids");
    (*sub)->add_option("--points", opt->points, "two-centre Gauss points per coordinate to measure");
    (*sub)->add_option("--reference-points", opt->referencePoints, "reference two-centre points");
    (*sub)->add_option("--steps", opt->steps, "atomic log-grid steps (in ln r) to measure");
    (*sub)->add_option("--reference-step", opt->referenceStep, "reference atomic log-grid step");
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [opt] {
    std::cout << fmt::format("carbon, pbc-0-3 recipe (Slater basis, PBE); S and H (ss, sp, ps, pp σ, pp π) at d = {} bohr\n\n",
                             fmt::join(opt->distances, ", "));
    // two-centre quadrature at the default atom grid
    const skgen::ElementBasis b = carbon(0.008);
    const auto ref = integrals(b, opt->referencePoints, opt->distances);
    std::cout << fmt::format("two-centre grid (atom log step 0.008; reference {0}x{0} points)\n", opt->referencePoints);
    std::cout << "points  ms/distance  max|dS|     max|dH| (Ha)\n";
    for (int n : opt->points) {
      const auto t0 = std::chrono::steady_clock::now();
      int reps = 0;
      std::vector<skgen::SkIntegral> v;
      do {
        v = integrals(b, n, opt->distances);
        ++reps;
      } while (seconds(t0) < 0.3);
      const double ms = 1e3 * seconds(t0) / (reps * opt->distances.size());
      double ds, dh;
      maxErrors(v, ref, ds, dh);
      std::cout << fmt::format("{:6d}  {:11.3f}  {:10.2e}  {:10.2e}\n", n, ms, ds, dh) << std::flush;
    }
    // atomic grid at a converged two-centre grid
    std::cout << fmt::format("\natom grid (two-centre 64x64 points; reference step {})\n", opt->referenceStep);
    const skgen::ElementBasis bref = carbon(opt->referenceStep);
    const auto ref2 = integrals(bref, 64, opt->distances);
    std::cout << "step    s/element  |d onsite| (Ha)  max|dS|     max|dH| (Ha)\n";
    for (double h : opt->steps) {
      const auto t0 = std::chrono::steady_clock::now();
      const skgen::ElementBasis e = carbon(h);
      const double t = seconds(t0);
      double ds, dh;
      maxErrors(integrals(e, 64, opt->distances), ref2, ds, dh);
      const double don = std::max(std::abs(e.data.onsite[0] - bref.data.onsite[0]),
                                  std::abs(e.data.onsite[1] - bref.data.onsite[1]));
      std::cout << fmt::format("{:6.3f}  {:9.3f}  {:15.2e}  {:10.2e}  {:10.2e}\n", h, t, don, ds, dh) << std::flush;
    }
    return 0;
  };
  return c;
}

}  // namespace mesochain::app
