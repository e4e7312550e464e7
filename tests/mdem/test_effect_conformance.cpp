// One conformance suite for every registered mdem effect (in the spirit of LAMMPS's one YAML per
// style and a single runner): each effect has at least one case below (a test fails for a
// registered effect without one), and every case is checked by the same body:
//  * an effect that stores energy: its forces and torques are minus the finite-difference
//    gradient of the energy it reports (translations, and small world rotations with the
//    accumulated rotation advanced alike);
//  * an internal effect (not loads, not numerical damping): total force zero and total moment
//    about the origin zero (linear and angular momentum conserved); the plates ("walls", rigid
//    and frictionless, normal to z): no in-plane force and no moment about z;
//  * a dissipative effect (dashpots, numerical damping): its power on the current velocities is
//    never positive;
//  * every case: a short run of its scene conserves total + dissipated energy when no numerical
//    damping is named, and never raises it otherwise.
#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "chain_fixture.hpp"
#include "contact_fixture.hpp"
#include "mdem/compression.hpp"
#include "mdem/effect_registry.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

struct ConformanceCase {
  std::string effect;  // the effect under test (the scene may name others it needs)
  std::string label;
  std::function<Scene()> scene;
};

// Random velocities and a small random displacement and rotation of every element, so that
// bonds are strained and contacts off their minimum; reproducible.
void shake(Scene& s, unsigned seed, double dx, double dphi, double v) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < s.bodies.size(); ++i) {
    s.bodies.position[i] += dx * Vec3(u(gen), u(gen), u(gen));
    s.bodies.orientation[i] = normalized(expMap(dphi * Vec3(u(gen), u(gen), u(gen))) * s.bodies.orientation[i]);
    s.bodies.velocity[i] = v * Vec3(u(gen), u(gen), u(gen));
    s.bodies.setAngularVelocityWorld(i, v * Vec3(u(gen), u(gen), u(gen)));
  }
  s.run.timeStepFraction = 0.02;
}

// Two crossed tube segments of three elements, 0.45 nm apart (wall to wall) at the crossing.
Scene crossedTubes(std::vector<std::string> effects) {
  Scene s = tubeScene(std::move(effects));
  addTube(s, 3, Vec3(-2.0, 0.0, 0.0), Vec3::UnitX());
  const double d = 2.0 * kTubeRadius + 0.45;
  addTube(s, 3, Vec3(0.3, -2.0, d), Vec3(0.3, 1.0, 0.0).normalized());
  return s;
}

// Two bricks stacked face to face (the collapsed-tube contact).
Scene stackedBricks() {
  Scene s = filament(2);
  Scene other = filament(2, Vec3(kH + 0.36, 0.3, 0.4));
  for (int i = 0; i < other.bodies.size(); ++i)
    s.bodies.add(0, s.elementTypes[0], other.bodies.position[i], other.bodies.orientation[i]);
  s.bonds.clear();
  addBond(s, 0, 1, 0);
  addBond(s, 2, 3, 0);
  s.contacts.vdw.lj = carbonLj();
  s.effects = {"bonds", "vdw_contact"};
  return s;
}

std::vector<ConformanceCase> cases() {
  std::vector<ConformanceCase> c;
  c.push_back({"bonds", "strained brick chain", [] {
                 Scene s = filament(5, Vec3(0.1, 0.2, 0.3), Vec3(0.2, 0.1, 1.0).normalized());
                 shake(s, 1, 0.05, 0.05, 1.0);
                 return s;
               }});
  c.push_back({"vdw_contact", "crossed tubes", [] {
                 Scene s = crossedTubes({"bonds", "vdw_contact"});
                 shake(s, 2, 0.02, 0.02, 0.5);
                 return s;
               }});
  c.push_back({"vdw_contact", "stacked bricks", [] {
                 Scene s = stackedBricks();
                 shake(s, 3, 0.02, 0.02, 0.5);
                 return s;
               }});
  c.push_back({"contact_damping", "crossed tubes", [] {
                 Scene s = crossedTubes({"bonds", "vdw_contact", "contact_damping"});
                 s.contacts.damping.translational = 1.0, s.contacts.damping.rotational = 0.5;
                 shake(s, 4, 0.02, 0.02, 3.0);
                 return s;
               }});
  c.push_back({"loads", "fixed-direction force and moment", [] {
                 Scene s = filament(4);
                 Load l;
                 l.element = 3, l.force = {0.5, -0.2, 0.3}, l.moment = {0.1, 0.2, -0.3};
                 s.boundary.loads.push_back(l);
                 shake(s, 5, 0.03, 0.03, 1.0);
                 return s;
               }});
  c.push_back({"walls", "crossed tubes between plates", [] {
                 // Plates at rest (the protocol starts later), placed 0.12 nm into the lowest and
                 // highest walls so that tilted elements touch them along part of their length.
                 Scene s = crossedTubes({"bonds", "vdw_contact"});
                 shake(s, 8, 0.02, 0.05, 0.5);
                 s.compression.enabled = true;
                 s.compression.maxStrain = 0.5, s.compression.strainRate = 1.0, s.compression.stiffness = 800.0;
                 s.compression.area = 100.0;
                 setUpCompression(s, 1e6);
                 s.compression.bottom0 += s.compression.wallGap + 0.12, s.compression.top0 -= s.compression.wallGap + 0.12;
                 return s;
               }});
  c.push_back({"local_damping", "brick chain", [] {
                 Scene s = filament(5);
                 s.effects = {"bonds", "local_damping"};
                 s.localDampingAlpha = 0.5;
                 shake(s, 6, 0.05, 0.05, 2.0);
                 return s;
               }});
  c.push_back({"viscous_damping", "brick chain", [] {
                 Scene s = filament(5);
                 s.effects = {"bonds", "viscous_damping"};
                 s.viscousRate = 3.0;
                 shake(s, 7, 0.05, 0.05, 2.0);
                 return s;
               }});
  return c;
}

void PrintTo(const ConformanceCase& c, std::ostream* os) { *os << c.effect << " (" << c.label << ")"; }

class EffectConformance : public ::testing::TestWithParam<ConformanceCase> {};

// Force and torque of the effect alone on the current state of `sim`.
std::pair<std::vector<Vec3>, std::vector<Vec3>> alone(const Simulation& sim, Effect& e) {
  State st = sim.state();
  std::fill(st.bodies.force.begin(), st.bodies.force.end(), Vec3::Zero());
  std::fill(st.bodies.torque.begin(), st.bodies.torque.end(), Vec3::Zero());
  e.addForces(st);
  return {st.bodies.force, st.bodies.torque};
}

// The damping effects act on the force of those before them: their share is the difference.
std::pair<std::vector<Vec3>, std::vector<Vec3>> share(const Simulation& sim, const std::string& name) {
  State with = sim.state(), without = sim.state();
  for (State* st : {&with, &without}) {
    std::fill(st->bodies.force.begin(), st->bodies.force.end(), Vec3::Zero());
    std::fill(st->bodies.torque.begin(), st->bodies.torque.end(), Vec3::Zero());
  }
  for (const EffectPtr& e : sim.effects()) {
    e->addForces(with);
    if (e->name() != name) e->addForces(without);
  }
  std::vector<Vec3> f(with.bodies.size()), t(with.bodies.size());
  for (int i = 0; i < with.bodies.size(); ++i) {
    f[i] = with.bodies.force[i] - without.bodies.force[i];
    t[i] = with.bodies.torque[i] - without.bodies.torque[i];
  }
  return {f, t};
}

double storedEnergy(const Effect& e, const State& st) {
  EnergyLedger l;
  e.reportEnergy(st, l);
  return l.potential();
}

TEST_P(EffectConformance, PassesTheSharedChecks) {
  const ConformanceCase& c = GetParam();
  const Scene scene = c.scene();
  Simulation sim(scene);
  Effect* e = sim.effect(c.effect);
  ASSERT_NE(e, nullptr) << c.effect << " not built for its case";
  const Bodies& b = sim.bodies();
  EnergyLedger own;
  e->reportEnergy(sim.state(), own);
  bool stores = false, dissipates = e->role() == EffectRole::NumericalDamping;
  for (const LedgerEntry& x : own.entries())
    (x.kind == EnergyKind::Potential ? stores : dissipates) = true;

  const auto [force, torque] = dissipates ? share(sim, c.effect) : alone(sim, *e);
  double scale = 0.0;
  for (int i = 0; i < b.size(); ++i) scale = std::max({scale, force[i].norm(), torque[i].norm()});
  ASSERT_GT(scale, 0.0) << "the case does not exercise " << c.effect;

  if (stores) {
    // Central differences: translations of element i along d, rotations exp(delta e_d) q_i.
    const double delta = 1e-6;
    for (int i = 0; i < b.size(); ++i)
      for (int d = 0; d < 6; ++d) {
        double ep[2];
        for (int side = 0; side < 2; ++side) {
          State st = sim.state();
          const double h = side == 0 ? delta : -delta;
          if (d < 3) {
            st.bodies.position[i][d] += h;
          } else {
            st.bodies.orientation[i] = expMap(h * Vec3::Unit(d - 3)) * st.bodies.orientation[i];
            st.bodies.accumulatedRotation[i][d - 3] += h;
          }
          ep[side] = storedEnergy(*e, st);
        }
        const double fd = -(ep[0] - ep[1]) / (2.0 * delta);
        const double analytic = d < 3 ? force[i][d] : torque[i][d - 3];
        EXPECT_NEAR(analytic, fd, 1e-5 * scale) << c.effect << " (" << c.label << "), element " << i << ", dof " << d;
      }
  }
  if (c.effect == "walls") {
    Vec3 f = Vec3::Zero(), m = Vec3::Zero();
    double moment = 0.0;
    for (int i = 0; i < b.size(); ++i) {
      f += force[i];
      m += b.position[i].cross(force[i]) + torque[i];
      moment = std::max(moment, b.position[i].norm() * force[i].norm() + torque[i].norm());
    }
    EXPECT_GT(std::abs(f.z()), 0.0) << "the plates push";
    EXPECT_LT(std::hypot(f.x(), f.y()), 1e-12 * scale) << "walls: in-plane force";
    EXPECT_LT(std::abs(m.z()), 1e-12 * moment) << "walls: moment about z";
  } else if (c.effect != "loads" && e->role() == EffectRole::Physical) {
    Vec3 f = Vec3::Zero(), m = Vec3::Zero();
    double moment = 0.0;
    for (int i = 0; i < b.size(); ++i) {
      f += force[i];
      m += b.position[i].cross(force[i]) + torque[i];
      moment = std::max(moment, b.position[i].norm() * force[i].norm() + torque[i].norm());
    }
    EXPECT_LT(f.norm(), 1e-10 * scale) << c.effect << ": total force";
    EXPECT_LT(m.norm(), 1e-10 * moment) << c.effect << ": total moment";
  }
  if (dissipates) {
    double power = 0.0;
    for (int i = 0; i < b.size(); ++i) power += force[i].dot(b.velocity[i]) + torque[i].dot(b.angularVelocityWorld(i));
    EXPECT_LT(power, 0.0) << c.effect << " adds energy";
  }

  // A short run: total + dissipated conserved (no numerical damping), or never raised.
  bool numerical = false;
  for (const EffectPtr& x : sim.effects()) numerical = numerical || x->role() == EffectRole::NumericalDamping;
  const bool loads = !scene.boundary.loads.empty();
  const EnergyLedger e0 = sim.energies();
  double worst = 0.0;
  for (int k = 0; k < 200; ++k) {
    sim.run(5);
    const EnergyLedger ek = sim.energies();
    const double balance = ek.total() + ek.dissipated() - e0.total();
    worst = numerical ? std::max(worst, balance) : std::max(worst, std::abs(balance));
  }
  // Velocity Verlet on a linear system: each mode's energy stays within x / (1 - x) of a
  // conserved shadow energy, x = (h omega_max)^2 / 4 (test_dynamics.cpp); the contacts and
  // moments here are mildly nonlinear, so twice that. Dashpots see the half-step velocities of
  // the scheme, so their work is first order in h: 1 % of the work dissipated on top
  // (test_contact_stability.cpp measures the same).
  const double x = std::pow(sim.timeStep() * sim.stability().omegaMax, 2) / 4.0;
  const double bound = 2.0 * x / (1.0 - x) * std::abs(e0.total()) + 0.01 * sim.energies().dissipated();
  std::printf("%s (%s): worst energy balance %.3g zJ (bound %.3g zJ)\n", c.effect.c_str(), c.label.c_str(), worst,
              bound);
  if (!loads || numerical) {
    EXPECT_LT(worst, bound) << c.effect << " energy balance";
  }
}

std::string caseName(const ::testing::TestParamInfo<ConformanceCase>& p) {
  std::string n = p.param.effect + "_" + p.param.label;
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Mdem, EffectConformance, ::testing::ValuesIn(cases()), caseName);

TEST(MdemEffectConformance, EveryRegisteredEffectHasACase) {
  std::map<std::string, int> covered;
  for (const ConformanceCase& c : cases()) ++covered[c.effect];
  for (const EffectRegistration* r : registeredEffects())
    EXPECT_GT(covered[r->name], 0) << "effect \"" << r->name << "\" is registered but has no conformance case "
                                   << "(tests/mdem/test_effect_conformance.cpp)";
}

}  // namespace
}  // namespace mesochain::mdem
