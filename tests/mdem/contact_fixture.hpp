#pragma once
// Shared set-up for the contact tests: a (10,10)-like tube (R = 0.678 nm) with the carbon
// Lennard-Jones parameters eps = 2.84 meV, sigma = 0.34 nm, graphene surface density
// 38.2 atoms/nm^2, and an independent reference: the LJ energy of two finite cylindrical
// surfaces by direct quadrature (Gauss-Legendre along the axes, trapezoid around them).
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "mdem/contacts/network_generator.hpp"
#include "mdem/contacts/tube_potential.hpp"
#include "mdem/contacts/vdw_contact.hpp"
#include "mdem/quaternion.hpp"
#include "mdem/units.hpp"

namespace mesochain::mdem::testing {

inline constexpr double kTubeRadius = 0.678;  // nm
inline constexpr double kSegmentLength = 2.0;  // nm

// Forces and torques of one pair result `r` at (a0, b0) against central differences of
// `energy(a, b)` (eps: the displacement in nm and rotation in rad), with the scales of the
// comparison: the force, and for torques the moment of that force at the end of an element of
// half length `half` (parallel pairs have no torque but a force), with the round-off floor of a
// central difference of E (|E| u / eps = 1e-10 |E|, here 1e-9 |E|). Then the total force and the
// total moment about the origin vanish.
template <class Energy>
void expectPairForcesAreMinusGradient(const ContactPairResult& r, const Segment& a0, const Segment& b0,
                                      Energy energy, double eps, double half) {
  const double floor = 1e-3 + 1e-4 * std::abs(r.energy);
  const double fs = r.forceA.norm() + floor, ts = r.torqueA.norm() + r.torqueB.norm() + half * fs;
  for (int k = 0; k < 3; ++k) {
    const Vec3 e = eps * Vec3::Unit(k);
    Segment ap = a0, am = a0, bp = b0, bm = b0;
    ap.centre += e, am.centre -= e, bp.centre += e, bm.centre -= e;
    EXPECT_NEAR(r.forceA[k], -(energy(ap, b0) - energy(am, b0)) / (2 * eps), 1e-5 * fs);
    EXPECT_NEAR(r.forceB[k], -(energy(a0, bp) - energy(a0, bm)) / (2 * eps), 1e-5 * fs);
    // Rotation by phi = +-eps e_k about the element's centre.
    ap = am = a0, bp = bm = b0;
    ap.axis = rotate(expMap(e), a0.axis), am.axis = rotate(expMap(-e), a0.axis);
    bp.axis = rotate(expMap(e), b0.axis), bm.axis = rotate(expMap(-e), b0.axis);
    EXPECT_NEAR(r.torqueA[k], -(energy(ap, b0) - energy(am, b0)) / (2 * eps), 1e-5 * ts);
    EXPECT_NEAR(r.torqueB[k], -(energy(a0, bp) - energy(a0, bm)) / (2 * eps), 1e-5 * ts);
  }
  EXPECT_LT((r.forceA + r.forceB).norm(), 1e-12 * fs);
  const Vec3 moment = a0.centre.cross(r.forceA) + b0.centre.cross(r.forceB) + r.torqueA + r.torqueB;
  EXPECT_LT(moment.norm(), 1e-9 * (fs * (a0.centre.norm() + b0.centre.norm()) + ts));
}

inline LennardJones carbonLj() {
  return {2.84e-3 * units::kElectronvolt, 0.34, 38.2};
}

inline TubePairSpec tubeSpec() {
  TubePairSpec s;
  s.lj = carbonLj();
  s.radiusA = s.radiusB = kTubeRadius;
  s.switchGap = 0.8;
  s.cutoffGap = 1.2;
  return s;
}

// Built once per test binary (about 0.1 s).
inline const TubePairPotential& tubePotential() {
  static const TubePairPotential p(tubeSpec());
  return p;
}

// Direct LJ quadrature over two cylindrical surfaces (no caps): n^2 \int\int phi(|p - q|) dA dA.
inline double surfaceReferenceEnergy(const Segment& a, const Segment& b, double radius,
                                     int axialPanels = 10, int angular = 48) {
  const LennardJones lj = carbonLj();
  const QuadratureRule gl = gaussLegendre(6);
  struct Point { Vec3 x; double w; };
  auto surface = [&](const Segment& s) {
    std::vector<Point> pts;
    const Vec3 e1 = s.axis.unitOrthogonal(), e2 = s.axis.cross(e1);
    const double da = 2.0 * units::kPi / angular;
    for (int p = 0; p < axialPanels; ++p) {
      const double z0 = -s.halfLength + 2.0 * s.halfLength * p / axialPanels;
      const double z1 = z0 + 2.0 * s.halfLength / axialPanels;
      for (std::size_t q = 0; q < gl.x.size(); ++q) {
        const double z = 0.5 * (z0 + z1) + 0.5 * (z1 - z0) * gl.x[q];
        const double wz = 0.5 * (z1 - z0) * gl.w[q];
        for (int k = 0; k < angular; ++k)
          pts.push_back({s.centre + z * s.axis + radius * (std::cos(k * da) * e1 + std::sin(k * da) * e2),
                         wz * radius * da});
      }
    }
    return pts;
  };
  const auto pa = surface(a), pb = surface(b);
  double e = 0.0;
  for (const Point& p : pa) {
    double row = 0.0;
    for (const Point& q : pb) {
      const double r2 = (p.x - q.x).squaredNorm();
      const double s2 = lj.sigma * lj.sigma / r2, s6 = s2 * s2 * s2;
      row += q.w * (s6 * s6 - s6);
    }
    e += p.w * row;
  }
  return 4.0 * lj.epsilon * lj.surfaceDensity * lj.surfaceDensity * e;
}

// The rows of tests/data/mdem/vdw_vs_surface_quadrature.csv (wall-gap change from the
// equilibrium axis distance, crossing angle, offset along a, tolerance in %): `energy(a, b)` of
// segment b crossing a 2-nm segment a is within the row's tolerance of the direct surface
// quadrature, for all 8 rows.
template <class Energy>
void expectSurfaceQuadratureRows(Energy energy) {
  const double dEq = tubePotential().equilibriumDistance();
  std::ifstream in(std::string(MESOCHAIN_TEST_DATA) + "/mdem/vdw_vs_surface_quadrature.csv");
  ASSERT_TRUE(in.good());
  std::string line;
  int cases = 0;
  const Segment a{Vec3::Zero(), Vec3::UnitX(), 0.5 * kSegmentLength};
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    double extra, theta, offset, tolerance;
    char c;
    std::istringstream row(line);
    row >> extra >> c >> theta >> c >> offset >> c >> tolerance;
    const Segment b{Vec3(offset, dEq + extra, 0.0), Vec3(std::cos(theta), 0.0, std::sin(theta)),
                    0.5 * kSegmentLength};
    const double model = energy(a, b), ref = surfaceReferenceEnergy(a, b, kTubeRadius);
    EXPECT_LT(100.0 * std::abs(model - ref) / std::abs(ref), tolerance) << line;
    ++cases;
  }
  EXPECT_EQ(cases, 8);
}

// The (10,10) tube model of the scene-file tests, as TOML: cylinders of 2 nm (325 carbon
// atoms), Y = 1 TPa, G = 0.4 TPa.
inline constexpr const char* kTubeModelToml = R"([[element_types]]
name = "cnt1010"
shape = "cylinder"
radius_nm = 0.678
length_nm = 2.0
mass_ag = 0.0064823
[[bond_types]]
name = "cnt"
young_modulus_MPa = 1.0e6
shear_modulus_MPa = 0.4e6
)";

}  // namespace mesochain::mdem::testing

#include "mdem/scene.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::mdem::testing {

// A scene with one (10,10)-like cylinder element type (325 carbon atoms per 2 nm element), one
// bond type (Y = 1 TPa, G = 0.4 TPa) and the carbon vdW contact parameters; no elements yet.
inline Scene tubeScene(std::vector<std::string> effects) {
  Scene s;
  ElementType t;
  t.name = "cnt1010";
  t.shape = Shape::Cylinder;
  t.radius = kTubeRadius, t.length = kSegmentLength, t.mass = 325 * 1.9945e-5;
  s.elementTypes.push_back(t);
  BondType b;
  b.name = "cnt", b.fromModuli = true, b.youngModulus = 1e6, b.shearModulus = 0.4e6;
  s.bondTypes.push_back(b);
  s.contacts.vdw.lj = carbonLj();
  s.contacts.vdw.switchGap = 0.8, s.contacts.vdw.cutoffGap = 1.2;
  s.effects = std::move(effects);
  return s;
}

// A straight tube of `count` elements from `start` along `direction`; returns the first index.
inline int addTube(Scene& s, int count, const Vec3& start, const Vec3& direction) {
  FilamentSpec f;
  f.count = count, f.start = start, f.direction = direction;
  return addFilament(s, f);
}

// A random network of 60 tubes of 12 elements (720: above the stepper's one-thread threshold)
// with van der Waals contacts, dashpots and local damping, at half the critical step.
inline Scene dampedNetworkScene() {
  Scene s = tubeScene({"bonds", "vdw_contact", "contact_damping", "local_damping"});
  NetworkSpec n;
  n.tubes = 60, n.elementsPerTube = 12;
  n.size = Vec3(80.0, 80.0, 6.0);
  n.waviness = 0.1, n.minimumGap = 0.2, n.seed = 7;
  generateNetwork(s, n);
  s.contacts.damping.translational = 0.5;
  s.localDampingAlpha = 0.2;
  s.run.timeStepFraction = 0.5;
  return s;
}

}  // namespace mesochain::mdem::testing
