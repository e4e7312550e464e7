// Calibration scenes of the tube contacts (docs/mdem-contacts.md, "Calibration"):
//  * `mesochain bench sliding`: two aligned (10,10) tubes, each a closed chain across a box
//    periodic along x, one driven at a constant velocity v along the other (held): friction force
//    per length of the dashpots and of the van der Waals contact against v and gamma, to choose
//    gamma (F/L = gamma v; the vdW contact adds no friction).
//  * `mesochain bench zipping`: two tubes crossed at 30, 45, 60 degrees, released, zip into a
//    bundle: times after which they stay aligned (end-to-end angle below 10 and 3 degrees) and at
//    rest (kinetic energy below a threshold) against the crossing angle, with and without dashpots and for a
//    few local damping alphas, to choose alpha.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli/command.hpp"
#include "mdem/contacts/tube_potential.hpp"
#include "mdem/simulation.hpp"
#include "mdem/units.hpp"

namespace mesochain::app {

namespace {
constexpr double kRadius = 0.678;   // (10,10) tube, nm
constexpr double kLength = 2.0;     // element length, nm
constexpr double kMass = 325 * 1.9945e-5;

mdem::Scene tubeScene(std::vector<std::string> effects) {
  mdem::Scene s;
  mdem::ElementType t;
  t.name = "cnt1010", t.shape = mdem::Shape::Cylinder, t.radius = kRadius, t.length = kLength, t.mass = kMass;
  s.elementTypes.push_back(t);
  mdem::BondType b;
  b.name = "cnt", b.fromModuli = true, b.youngModulus = 1e6, b.shearModulus = 0.4e6;
  s.bondTypes.push_back(b);
  s.contacts.vdw.lj = {2.84e-3 * mdem::units::kElectronvolt, 0.34, 38.2};
  s.effects = std::move(effects);
  return s;
}

// Sum over elements [first, first + count) of the force of one effect alone, on a copy.
mdem::Vec3 forceOf(const mdem::Simulation& sim, const char* effect, int first, int count) {
  mdem::State st = sim.state();
  std::fill(st.bodies.force.begin(), st.bodies.force.end(), mdem::Vec3::Zero());
  std::fill(st.bodies.torque.begin(), st.bodies.torque.end(), mdem::Vec3::Zero());
  sim.effect(effect)->addForces(st);
  mdem::Vec3 f = mdem::Vec3::Zero();
  for (int i = first; i < first + count; ++i) f += st.bodies.force[i];
  return f;
}

struct SlidingOptions {
  std::vector<double> velocities{1.0, 3.0, 10.0, 30.0, 100.0};  // nm/ns
  std::vector<double> gammas{0.0, 0.5, 2.0};                    // pN ns / nm^2
  int elements = 6;                                             // per tube
};

struct SlidingResult {
  double dashpot = 0.0, vdwMean = 0.0, vdwMax = 0.0, normal = 0.0;  // pN/nm
};

// Drives tube A (elements 0..n-1) at v along x past tube B (held) by one element length.
SlidingResult slide(double v, double gamma, int n) {
  mdem::Scene s = tubeScene({"vdw_contact", "contact_damping"});
  s.contacts.damping.translational = gamma;
  s.periodic.periodic = {true, false, false};
  s.periodic.length = mdem::Vec3(n * kLength, 0, 0);
  s.contacts.closedFilaments = {{0, n}, {n, n}};
  mdem::TubePairSpec ps;
  ps.lj = s.contacts.vdw.lj, ps.radiusA = ps.radiusB = kRadius;
  ps.switchGap = s.contacts.vdw.switchGap, ps.cutoffGap = s.contacts.vdw.cutoffGap;
  static const double d = mdem::TubePairPotential(ps).equilibriumDistance();  // of infinite tubes
  const mdem::Quat alongX = mdem::fromMatrix((mdem::Mat3() << 0, 0, 1, 0, 1, 0, -1, 0, 0).finished());
  for (int k = 0; k < n; ++k) s.bodies.add(0, s.elementTypes[0], mdem::Vec3(k * kLength + 0.3, d, 0), alongX);
  for (int k = 0; k < n; ++k) s.bodies.add(0, s.elementTypes[0], mdem::Vec3(k * kLength, 0, 0), alongX);
  for (int k = 0; k < n; ++k) {
    mdem::Prescribed p;
    p.element = k, p.velocity = mdem::Vec3(v, 0, 0);
    s.boundary.prescribed.push_back(p);
    mdem::FixedDofs f;
    f.element = n + k, f.fixed.fill(true);
    s.boundary.fixed.push_back(f);
  }
  constexpr int kSamples = 40;
  s.run.timeStep = std::min(1e-4, kLength / (v * kSamples * 10));
  mdem::Simulation sim(s);
  const long every = std::max(1L, std::lround(kLength / (v * s.run.timeStep * kSamples)));
  SlidingResult r;
  const double len = n * kLength;
  for (int k = 0; k < kSamples; ++k) {
    sim.run(every);
    const mdem::Vec3 fd = forceOf(sim, "contact_damping", n, n), fv = forceOf(sim, "vdw_contact", n, n);
    r.dashpot += fd.x() / len / kSamples;
    r.vdwMean += fv.x() / len / kSamples;
    r.vdwMax = std::max(r.vdwMax, std::abs(fv.x() / len));
    r.normal += fv.y() / len / kSamples;
  }
  return r;
}

struct ZippingOptions {
  std::vector<double> anglesDeg{30.0, 45.0, 60.0};
  std::vector<double> alphas{0.0, 0.1, 0.3, 0.7};
  std::vector<double> gammas{0.0, 2.0};
  double rotationalGamma = 0.2;  // pN ns, with gamma > 0
  double maxTime = 0.5;          // ns
  double restKinetic = 0.1;      // zJ
  int elements = 8;
};

double crossingAngle(const mdem::Bodies& b, int n) {
  const mdem::Vec3 ta = b.position[n - 1] - b.position[0], tb = b.position[2 * n - 1] - b.position[n];
  return std::acos(std::min(1.0, std::abs(ta.normalized().dot(tb.normalized()))));
}

struct ZippingResult {
  // Times after which (to the end of the run) the angle stays below 10 and 3 degrees and the
  // kinetic energy below the rest threshold; < 0 = not reached.
  double aligned10 = -1.0, aligned3 = -1.0, rest = -1.0;  // ns
  double finalAngleDeg = 0.0, vdw = 0.0, released = 0.0;
};

// Two tubes of n elements crossed at `angle`, wall gap 0.34 nm at their middles, released and
// run for o.maxTime.
ZippingResult zip(double angle, double alpha, double gamma, const ZippingOptions& o) {
  std::vector<std::string> effects{"bonds", "vdw_contact"};
  if (gamma > 0) effects.push_back("contact_damping");
  if (alpha > 0) effects.push_back("local_damping");
  mdem::Scene s = tubeScene(effects);
  s.contacts.damping.translational = gamma;
  s.contacts.damping.rotational = gamma > 0 ? o.rotationalGamma : 0.0;
  s.localDampingAlpha = alpha;
  const int n = o.elements;
  const double d = 2 * kRadius + 0.34, half = 0.5 * (n - 1) * kLength;
  const mdem::Vec3 ta = mdem::Vec3::UnitX(), tb(std::cos(angle), 0.0, std::sin(angle));
  for (const auto& [start, dir] : {std::pair{mdem::Vec3(-half * ta), ta}, std::pair{mdem::Vec3(mdem::Vec3(0, d, 0) - half * tb), tb}}) {
    mdem::FilamentSpec f;
    f.count = n, f.start = start, f.direction = dir;
    mdem::addFilament(s, f);
  }
  s.run.timeStep = 2e-5;  // one step for all runs (below the critical 2.9e-5 ns with dashpots)
  mdem::Simulation sim(s);
  ZippingResult r;
  const double vdw0 = sim.energies()["vdw"], deg = mdem::units::kPi / 180.0;
  const long every = 50;  // 1 ps
  double minVdw = vdw0;
  auto track = [&](double& since, bool ok) {
    if (!ok) since = -1.0;
    else if (since < 0) since = sim.time();
  };
  while (sim.time() < o.maxTime) {
    sim.run(every);
    const mdem::EnergyLedger e = sim.energies();
    minVdw = std::min(minVdw, e["vdw"]);
    const double a = crossingAngle(sim.bodies(), n);
    track(r.aligned10, a < 10 * deg);
    track(r.aligned3, a < 3 * deg);
    track(r.rest, e.kinetic() < o.restKinetic);
  }
  const mdem::EnergyLedger e = sim.energies();
  r.finalAngleDeg = crossingAngle(sim.bodies(), n) / deg;
  r.vdw = e["vdw"];
  r.released = vdw0 - minVdw;
  return r;
}

std::string timeOrDash(double t) { return t < 0 ? std::string("-") : fmt::format("{:.3f}", t); }
}  // namespace

Command makeBenchSlidingCommand() {
  auto sub = std::make_shared<CLI::App*>(nullptr);
  auto opt = std::make_shared<SlidingOptions>();
  Command c;
  c.attach = [sub, opt](CLI::App& bench) {
    *sub = bench.add_subcommand("sliding", "friction per length of two aligned tubes sliding (periodic)");
    (*sub)->add_option("--velocities", opt->velocities, "sliding velocities, nm/ns");
    (*sub)->add_option("--gammas", opt->gammas, "dashpot coefficients, pN ns/nm^2");
    (*sub)->add_option("--elements", opt->elements, "elements per tube (box = elements x 2 nm)");
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [opt] {
    std::cout << "Two (10,10) tubes at their equilibrium distance, one driven along the other by one "
                 "element length;\nforces per length on the held tube (pN/nm), averaged over 40 samples.\n"
              << "gamma_pN_ns/nm2  v_nm/ns   dashpot_F/L  gamma*v  vdW_F/L_mean  vdW_|F/L|_max  vdW_normal_F/L\n";
    for (double g : opt->gammas)
      for (double v : opt->velocities) {
        const SlidingResult r = slide(v, g, opt->elements);
        std::cout << fmt::format("{:15.3g}  {:7.3g}  {:11.5g}  {:7.5g}  {:12.3g}  {:13.3g}  {:14.4g}\n", g, v,
                                 r.dashpot, g * v, r.vdwMean, r.vdwMax, r.normal)
                  << std::flush;
      }
    return 0;
  };
  return c;
}

Command makeBenchZippingCommand() {
  auto sub = std::make_shared<CLI::App*>(nullptr);
  auto opt = std::make_shared<ZippingOptions>();
  Command c;
  c.attach = [sub, opt](CLI::App& bench) {
    *sub = bench.add_subcommand("zipping", "relaxation time of two crossed tubes zipping into a bundle");
    (*sub)->add_option("--angles", opt->anglesDeg, "crossing angles, degrees");
    (*sub)->add_option("--alphas", opt->alphas, "local damping alphas (0 = none)");
    (*sub)->add_option("--gammas", opt->gammas, "dashpot coefficients, pN ns/nm^2 (0 = none)");
    (*sub)->add_option("--max-time", opt->maxTime, "longest simulated time, ns");
    (*sub)->add_option("--rest-kinetic", opt->restKinetic, "kinetic energy at rest, zJ");
    (*sub)->add_option("--elements", opt->elements, "elements per tube");
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [opt] {
    std::cout << fmt::format(
        "Two (10,10) tubes of {} elements (2 nm) crossed, released; h = 2e-5 ns, gamma_r = {} pN ns with "
        "dashpots.\nTimes (ns) after which, to the end of the run ({} ns), the end-to-end angle stays below 10 "
        "and 3 degrees\nand the kinetic energy below {} zJ ('-': not reached); the final angle and vdW energy "
        "at the end.\n",
        opt->elements, opt->rotationalGamma, opt->maxTime, opt->restKinetic);
    std::cout << "angle_deg  alpha  gamma  below_10deg  below_3deg  at_rest  final_angle_deg  vdW_zJ   released_zJ\n";
    for (double a : opt->anglesDeg)
      for (double g : opt->gammas)
        for (double alpha : opt->alphas) {
          const ZippingResult r = zip(a * mdem::units::kPi / 180.0, alpha, g, *opt);
          std::cout << fmt::format("{:9.0f}  {:5.2f}  {:5.2f}  {:>11}  {:>10}  {:>7}  {:15.3f}  {:7.1f}  {:11.1f}\n",
                                   a, alpha, g, timeOrDash(r.aligned10), timeOrDash(r.aligned3), timeOrDash(r.rest),
                                   r.finalAngleDeg, r.vdw, r.released)
                    << std::flush;
        }
    return 0;
  };
  return c;
}

}  // namespace mesochain::app
