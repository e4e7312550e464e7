// Calibration scenes of the tube contacts (docs/mdem-contacts.md, "Calibration"):
//  * `mesochain-bench sliding`: two aligned (10,10) tubes, each a closed chain across a box
//    periodic along x, one driven at a constant velocity v along the other (held): friction force
//    per length of the dashpots and of the van der Waals contact against v and gamma, to choose
//    gamma (F/L = gamma v; the vdW contact adds no friction).
//  * `mesochain-bench zipping`: two tubes crossed at 30, 45, 60 degrees, released, zip into a
//    bundle: times after which they stay aligned (end-to-end angle below 10 and 3 degrees) and at
//    rest (kinetic energy below a threshold) against the crossing angle, with and without dashpots and for a
//    few local damping alphas, to choose alpha; the energy the dashpots dissipate against the rest
//    (local damping), and where the dashpots act: pairs per wall-gap band and relative speeds at
//    the contact points (mdem/contacts/dashpot_probe.hpp), per run and as a time series (--series).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli/command.hpp"
#include "common/atomic_file.hpp"
#include "common/csv.hpp"
#include "mdem/contacts/dashpot_probe.hpp"
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
  double sampleTime = 1e-3;      // ns between samples (1 ps)
  int elements = 8;
  double startGap = 0.5;         // nm, wall gap at the crossing when released (issue 12: 0.5)
  std::string seriesPath;        // CSV time series of every run ("" = none)
};

double crossingAngle(const mdem::Bodies& b, int n) {
  const mdem::Vec3 ta = b.position[n - 1] - b.position[0], tb = b.position[2 * n - 1] - b.position[n];
  return std::acos(std::min(1.0, std::abs(ta.normalized().dot(tb.normalized()))));
}

// Band counts, relative speeds and dashpot rates of the two tubes (elements [0, n) and [n, 2n)),
// the moment about the centroid of all elements (the crossing point), and the reduced moment of
// inertia of the two tubes about their own centroids (ag nm^2, element centres as point masses).
mdem::DashpotProbe probeZipping(const mdem::Simulation& sim, const mdem::Scene& s, int n, double* reducedInertia) {
  const mdem::Bodies& b = sim.bodies();
  std::vector<mdem::ProbeElement> el(b.size());
  mdem::Vec3 centroid[2] = {mdem::Vec3::Zero(), mdem::Vec3::Zero()};
  for (int i = 0; i < b.size(); ++i) {
    el[i].segment = {b.position[i], mdem::rotate(b.orientation[i], mdem::Vec3::UnitZ()), 0.5 * kLength};
    el[i].radius = kRadius, el[i].velocity = b.velocity[i], el[i].angularVelocity = b.angularVelocityWorld(i);
    el[i].filament = i < n ? 0 : 1;
    centroid[el[i].filament] += b.position[i] / n;
  }
  double inertia[2] = {0.0, 0.0};
  for (int i = 0; i < b.size(); ++i) inertia[el[i].filament] += b.mass[i] * (b.position[i] - centroid[el[i].filament]).squaredNorm();
  *reducedInertia = inertia[0] * inertia[1] / (inertia[0] + inertia[1]);
  return mdem::probeDashpots(s.contacts.damping, s.contacts.vdw.cutoffGap, el, 0.5 * (centroid[0] + centroid[1]));
}

struct ZippingResult {
  // Times after which (to the end of the run) the angle stays below 10 and 3 degrees and the
  // kinetic energy below the rest threshold; < 0 = not reached.
  double aligned10 = -1.0, aligned3 = -1.0, rest = -1.0;  // ns
  double finalAngleDeg = 0.0, vdw = 0.0, released = 0.0;
  double timeStep = 0.0;                 // ns
  double dashpotDissipated = 0.0;        // zJ, ledger entry "contact_dissipated"
  // zJ: E(0) - E(end) - dashpotDissipated with E = kinetic + potential: the work of the local
  // damping plus the integrator's energy error (alone in the runs without local damping).
  double residual = 0.0;
  // Means over the samples before aligned10 (the whole run when not reached): pairs in the
  // dashpot's full band, in its ramp, in the vdW-only band; rms relative speed at the contact
  // points of the full band and of the vdW-only band (nm/ns); lambda s weighted rms speed.
  double pairsFull = 0.0, pairsRamp = 0.0, pairsVdwOnly = 0.0, speedFull = 0.0, speedVdwOnly = 0.0,
         speedWeighted = 0.0;
};

// Two tubes of n elements crossed at `angle`, wall gap o.startGap at their middles, released and
// run for o.maxTime. h = 2e-5 ns (as in bench/zipping-2026-11-22.txt) unless 0.7 of the critical
// step is shorter (dashpots with gamma > 2: the estimate takes six neighbours, so it is cautious). `series` (may be null) receives one CSV record per sample.
ZippingResult zip(double angle, double alpha, double gamma, const ZippingOptions& o, std::string* series) {
  std::vector<std::string> effects{"bonds", "vdw_contact"};
  if (gamma > 0) effects.push_back("contact_damping");
  if (alpha > 0) effects.push_back("local_damping");
  mdem::Scene s = tubeScene(effects);
  s.contacts.damping.translational = gamma;
  s.contacts.damping.rotational = gamma > 0 ? o.rotationalGamma : 0.0;
  s.localDampingAlpha = alpha;
  const int n = o.elements;
  const double d = 2 * kRadius + o.startGap, half = 0.5 * (n - 1) * kLength;
  const mdem::Vec3 ta = mdem::Vec3::UnitX(), tb(std::cos(angle), 0.0, std::sin(angle));
  for (const auto& [start, dir] : {std::pair{mdem::Vec3(-half * ta), ta}, std::pair{mdem::Vec3(mdem::Vec3(0, d, 0) - half * tb), tb}}) {
    mdem::FilamentSpec f;
    f.count = n, f.start = start, f.direction = dir;
    mdem::addFilament(s, f);
  }
  s.run.timeStepFraction = 0.5;  // this first simulation only reads the critical step
  const double critical = mdem::Simulation(s).stability().criticalTimeStep;
  s.run.timeStepFraction = 0.0;
  s.run.timeStep = std::min(2e-5, 0.7 * critical);
  mdem::Simulation sim(s);
  ZippingResult r;
  r.timeStep = s.run.timeStep;
  const mdem::EnergyLedger e0 = sim.energies();
  const double vdw0 = e0["vdw"], deg = mdem::units::kPi / 180.0;
  const long every = std::max(1L, std::lround(o.sampleTime / s.run.timeStep));
  double minVdw = vdw0;
  auto track = [&](double& since, bool ok) {
    if (!ok) since = -1.0;
    else if (since < 0) since = sim.time();
  };
  struct Sample { double full = 0, ramp = 0, vdwOnly = 0, v2Full = 0, v2Vdw = 0, lw = 0, rate = 0; };
  std::vector<Sample> samples;
  while (sim.time() < o.maxTime - 0.5 * s.run.timeStep) {
    sim.run(every);
    const mdem::EnergyLedger e = sim.energies();
    minVdw = std::min(minVdw, e["vdw"]);
    const double a = crossingAngle(sim.bodies(), n);
    track(r.aligned10, a < 10 * deg);
    track(r.aligned3, a < 3 * deg);
    track(r.rest, e.kinetic() < o.restKinetic);
    double inertia;
    const mdem::DashpotProbe p = probeZipping(sim, s, n, &inertia);
    samples.push_back({double(p.full.pairs), double(p.ramp.pairs), double(p.vdwOnly.pairs), p.full.sumSpeedSquared,
                         p.vdwOnly.sumSpeedSquared, p.weightedLength, p.translationalRate});
    if (series) {
      const double dash = e["contact_dissipated"];
      *series += csvRecord({fmt::format("{:g}", angle / deg), fmt::format("{:g}", alpha), fmt::format("{:g}", gamma),
                            fmt::format("{:.4f}", sim.time()), fmt::format("{:.3f}", a / deg),
                            fmt::format("{:.4g}", e.kinetic()), fmt::format("{:.2f}", e["vdw"]),
                            fmt::format("{:.3f}", dash), fmt::format("{:.3f}", e0.total() - e.total() - dash),
                            std::to_string(p.full.pairs), std::to_string(p.ramp.pairs), std::to_string(p.vdwOnly.pairs),
                            fmt::format("{:.4f}", p.weightedLength), fmt::format("{:.4g}", p.full.rmsSpeed()),
                            fmt::format("{:.4g}", p.ramp.rmsSpeed()), fmt::format("{:.4g}", p.vdwOnly.rmsSpeed()),
                            fmt::format("{:.4g}", p.weightedRmsSpeed()), fmt::format("{:.4g}", p.power(s.contacts.damping)),
                            fmt::format("{:.4g}", p.weightedLengthMoment), fmt::format("{:.4g}", inertia),
                            gamma > 0 && p.weightedLengthMoment > 0
                                ? fmt::format("{:.4g}", 1e3 * inertia / (gamma * p.weightedLengthMoment))
                                : std::string()});
    }
  }
  const mdem::EnergyLedger e = sim.energies();
  r.finalAngleDeg = crossingAngle(sim.bodies(), n) / deg;
  r.vdw = e["vdw"];
  r.released = vdw0 - minVdw;
  r.dashpotDissipated = e["contact_dissipated"];
  r.residual = e0.total() - e.total() - r.dashpotDissipated;
  // The zipping phase: the samples before the angle stayed below 10 degrees.
  const std::size_t until = r.aligned10 < 0 ? samples.size() : std::size_t(std::lround(r.aligned10 / (every * r.timeStep)));
  Sample z;
  const std::size_t m = std::max<std::size_t>(1, std::min(until, samples.size()));
  for (std::size_t k = 0; k < m && k < samples.size(); ++k) {
    const Sample& x = samples[k];
    z.full += x.full, z.ramp += x.ramp, z.vdwOnly += x.vdwOnly, z.v2Full += x.v2Full, z.v2Vdw += x.v2Vdw;
    z.lw += x.lw, z.rate += x.rate;
  }
  r.pairsFull = z.full / m, r.pairsRamp = z.ramp / m, r.pairsVdwOnly = z.vdwOnly / m;
  r.speedFull = z.full > 0 ? std::sqrt(z.v2Full / z.full) : 0.0;
  r.speedVdwOnly = z.vdwOnly > 0 ? std::sqrt(z.v2Vdw / z.vdwOnly) : 0.0;
  r.speedWeighted = z.lw > 0 ? std::sqrt(z.rate / z.lw) : 0.0;
  return r;
}

const std::vector<std::string> kZippingSeriesColumns{
    "angle_deg", "alpha", "gamma_pN_ns_per_nm2", "time_ns", "end_to_end_angle_deg", "kinetic_zJ", "vdw_zJ",
    "dashpot_dissipated_zJ", "residual_zJ", "pairs_full", "pairs_ramp", "pairs_vdw_only", "weighted_length_nm",
    "rms_speed_full_nm_per_ns", "rms_speed_ramp_nm_per_ns", "rms_speed_vdw_only_nm_per_ns",
    "weighted_rms_speed_nm_per_ns", "dashpot_power_zJ_per_ns", "weighted_length_moment_nm3",
    "reduced_inertia_ag_nm2", "turn_damping_time_ps"};

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
    (*sub)->add_option("--gamma-r", opt->rotationalGamma, "rotational dashpot coefficient with gamma > 0, pN ns");
    (*sub)->add_option("--max-time", opt->maxTime, "longest simulated time, ns");
    (*sub)->add_option("--rest-kinetic", opt->restKinetic, "kinetic energy at rest, zJ");
    (*sub)->add_option("--elements", opt->elements, "elements per tube");
    (*sub)->add_option("--start-gap", opt->startGap, "wall gap at the crossing when released, nm (0.34: the runs before 2026-12-04)")
        ->check(CLI::Range(0.0, 1.0));
    (*sub)->add_option("--series", opt->seriesPath,
                       "CSV file: every run sampled each ps (angle, energies, pairs per contact band, relative speeds)");
  };
  c.selected = [sub] { return *sub && (*sub)->parsed(); };
  c.run = [opt] {
    if (!opt->seriesPath.empty()) requireWritableOutput(opt->seriesPath, "<command line>", "option --series");
    std::cout << fmt::format(
        "Two (10,10) tubes of {} elements (2 nm) crossed with a {} nm wall gap at the crossing, released; h = 2e-5 ns (or 0.7 of the critical step), "
        "gamma_r = {} pN ns with dashpots.\nTimes (ns) after which, to the end of the run ({} ns), the end-to-end "
        "angle stays below 10 and 3 degrees\nand the kinetic energy below {} zJ ('-': not reached); the final angle "
        "and vdW energy at the end; energy\ndissipated by the dashpots and the residual E(0) - E(end) - dashpots "
        "(local damping + integrator error);\nmeans over the zipping phase (until below 10 deg): element pairs with "
        "wall gap < 0.5 nm (dashpot full),\n0.5-1.0 nm (dashpot ramp), 1.0-1.2 nm (vdW only); rms relative speed at "
        "the contact points (nm/ns) of the\nfull and vdW-only bands and lambda*s weighted over the dashpot "
        "contacts.\n",
        opt->elements, opt->startGap, opt->rotationalGamma, opt->maxTime, opt->restKinetic);
    std::cout << "angle  alpha  gamma  h_ns     below_10  below_3  at_rest  final_deg  vdW_zJ   dashpot_zJ  residual_zJ"
                 "  n_full  n_ramp  n_vdw  v_full  v_vdw  v_weighted\n";
    std::string series = opt->seriesPath.empty() ? std::string() : csvRecord(kZippingSeriesColumns);
    for (double a : opt->anglesDeg)
      for (double g : opt->gammas)
        for (double alpha : opt->alphas) {
          const ZippingResult r =
              zip(a * mdem::units::kPi / 180.0, alpha, g, *opt, opt->seriesPath.empty() ? nullptr : &series);
          std::cout << fmt::format(
                           "{:5.0f}  {:5.2f}  {:5.3g}  {:7.2g}  {:>8}  {:>7}  {:>7}  {:9.3f}  {:7.1f}  {:10.1f}  {:11.2f}"
                           "  {:6.2f}  {:6.2f}  {:5.2f}  {:6.3f}  {:5.3f}  {:10.3f}\n",
                           a, alpha, g, r.timeStep, timeOrDash(r.aligned10), timeOrDash(r.aligned3),
                           timeOrDash(r.rest), r.finalAngleDeg, r.vdw, r.dashpotDissipated, r.residual, r.pairsFull,
                           r.pairsRamp, r.pairsVdwOnly, r.speedFull, r.speedVdwOnly, r.speedWeighted)
                    << std::flush;
        }
    if (!opt->seriesPath.empty()) writeFileAtomically(opt->seriesPath, series);
    return 0;
  };
  return c;
}

}  // namespace mesochain::app
