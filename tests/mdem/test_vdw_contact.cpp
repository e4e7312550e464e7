// The van der Waals contact against independent computations: the closed-form line integral
// against quadrature, the kernel against its defining property (its line integral is the
// parallel-tube potential), the anisotropic and isotropic kernels against direct LJ quadrature
// over two cylindrical surfaces, forces and torques against finite differences of the energy,
// action-reaction and angular momentum balance, no corrugation along a chain, aligning moment.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "contact_fixture.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

TEST(MdemVdwContact, LineIntegralOfLennardJonesIsClosedForm) {
  const LennardJones lj = carbonLj();
  for (double h : {0.3, 0.34, 0.4, 0.7}) {
    // Trapezoid on a fine grid in z over [-20 h, 20 h].
    double sum = 0.0;
    const int n = 400000;
    const double zMax = 20.0 * h, dz = 2.0 * zMax / n;
    for (int k = 0; k <= n; ++k) {
      const double z = -zMax + k * dz, r2 = h * h + z * z;
      const double s6 = std::pow(lj.sigma * lj.sigma / r2, 3);
      sum += (k == 0 || k == n ? 0.5 : 1.0) * 4.0 * lj.epsilon * (s6 * s6 - s6) * dz;
    }
    double dq;
    const double q = ljLineIntegral(lj, h, &dq);
    EXPECT_NEAR(q, sum, 1e-6 * std::abs(sum)) << h;
    const double e = 1e-6;
    EXPECT_NEAR(dq, (ljLineIntegral(lj, h + e) - ljLineIntegral(lj, h - e)) / (2 * e), 1e-6 * std::abs(dq));
  }
}

TEST(MdemVdwContact, ParallelTubePotentialConvergedAndPlausible) {
  const LennardJones lj = carbonLj();
  const double d = 2 * kTubeRadius + 0.32;
  const double coarse = parallelTubeEnergyPerLength(lj, kTubeRadius, kTubeRadius, d, nullptr, 96);
  const double fine = parallelTubeEnergyPerLength(lj, kTubeRadius, kTubeRadius, d, nullptr, 256);
  EXPECT_NEAR(coarse, fine, 1e-8 * std::abs(fine));
  const TubePairPotential& p = tubePotential();
  const double gap = p.equilibriumDistance() - 2 * kTubeRadius;
  const double depthEvPerNm = p.wellDepthPerLength() / units::kElectronvolt;
  std::printf("(10,10) pair: equilibrium gap %.4f nm, depth %.4f eV/nm\n", gap, depthEvPerNm);
  // Graphite-like interlayer gap (LJ 2^(1/6) sigma - small curvature correction) and a depth
  // of the order of the published ~0.9-1.0 eV/nm for (10,10) bundles (Girifalco et al. 2000).
  EXPECT_GT(gap, 0.30);
  EXPECT_LT(gap, 0.34);
  EXPECT_LT(depthEvPerNm, -0.7);
  EXPECT_GT(depthEvPerNm, -1.3);
}

TEST(MdemVdwContact, KernelIntegratesToTheParallelTubePotential) {
  const TubePairPotential& p = tubePotential();
  const QuadratureRule gl = gaussLegendre(32);
  for (double gap : {0.28, 0.32, 0.4, 0.6, 0.9, 1.1}) {
    const double d = 2 * kTubeRadius + gap;
    // 2 \int_0^U w(sqrt(d^2 + u^2)) du with U = sqrt(dc^2 - d^2), composite Gauss.
    const double uMax = std::sqrt(p.cutoffDistance() * p.cutoffDistance() - d * d);
    double sum = 0.0;
    const int panels = 40;
    for (int k = 0; k < panels; ++k) {
      const double u0 = uMax * k / panels, u1 = uMax * (k + 1) / panels;
      for (std::size_t q = 0; q < gl.x.size(); ++q)
        sum += 0.5 * (u1 - u0) * gl.w[q] * 2.0 * p.kernel(std::sqrt(d * d + std::pow(0.5 * (u0 + u1) + 0.5 * (u1 - u0) * gl.x[q], 2)));
    }
    EXPECT_NEAR(sum, p.phi(d), 2e-3 * std::abs(p.wellDepthPerLength())) << gap;
    // The table H reproduces the same integral: H(d, -inf) - H(d, +inf) = Phi(d).
    double a, b, c, e;
    const double tab = p.lineIntegral(d, -uMax - 1.0, &a, &b) - p.lineIntegral(d, uMax + 1.0, &c, &e);
    EXPECT_NEAR(tab, p.phi(d), 2e-3 * std::abs(p.wellDepthPerLength())) << gap;
  }
}

Segment seg(const Vec3& c, const Vec3& axis) { return {c, axis.normalized(), 0.5 * kSegmentLength}; }

// Segment b crossing a at angle theta, axis distance d, offset along a.
Segment crossed(double d, double theta, double offset = 0.0) {
  return seg(Vec3(offset, d, 0.0), Vec3(std::cos(theta), 0.0, std::sin(theta)));
}

TEST(MdemVdwContact, AnisotropicMatchesSurfaceQuadrature) {
  const TubePairPotential& p = tubePotential();
  const QuadratureRule rule = gaussLegendre(12);
  const Segment a = seg(Vec3::Zero(), Vec3::UnitX());
  const double dEq = p.equilibriumDistance();
  std::ifstream in(std::string(MESOCHAIN_TEST_DATA) + "/mdem/vdw_vs_surface_quadrature.csv");
  ASSERT_TRUE(in.good());
  std::string line;
  int cases = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    double extra, theta, offset, tolerance;
    char c;
    std::istringstream row(line);
    row >> extra >> c >> theta >> c >> offset >> c >> tolerance;
    const Segment b = crossed(dEq + extra, theta, offset);
    const double model = anisotropicVdw(p, rule, a, b).energy;
    const double ref = surfaceReferenceEnergy(a, b, kTubeRadius);
    const double err = 100.0 * (model - ref) / std::abs(ref);
    std::printf("d=%.3f theta=%.3f offset=%.2f  model %.3f  reference %.3f zJ  (%+.1f%%)\n",
                dEq + extra, theta, offset, model, ref, err);
    EXPECT_LT(std::abs(err), tolerance) << line;
    ++cases;
  }
  EXPECT_EQ(cases, 8);
}

TEST(MdemVdwContact, SurfaceReferenceIsConverged) {
  const Segment a = seg(Vec3::Zero(), Vec3::UnitX());
  const Segment b = crossed(tubePotential().equilibriumDistance(), 0.7854);
  const double base = surfaceReferenceEnergy(a, b, kTubeRadius);
  const double finer = surfaceReferenceEnergy(a, b, kTubeRadius, 16, 72);
  EXPECT_NEAR(base, finer, 2e-3 * std::abs(finer));
}

// Energy of a pair after moving/rotating element a or b.
struct Config {
  Vec3 xa, xb;
  Quat qa, qb;
  Segment a() const { return {xa, rotate(qa, Vec3::UnitZ()), 0.5 * kSegmentLength}; }
  Segment b() const { return {xb, rotate(qb, Vec3::UnitZ()), 0.5 * kSegmentLength}; }
};

template <class Kernel>
void checkGradients(const Config& c, Kernel kernel, double tolerance) {
  const ContactPairResult r = kernel(c);
  const double eps = 1e-6;
  const double fs = r.forceA.norm() + 1e-3, ts = r.torqueA.norm() + r.torqueB.norm() + 1e-3;
  for (int d = 0; d < 3; ++d) {
    const Vec3 e = eps * Vec3::Unit(d);
    auto energy = [&](Config k) { return kernel(k).energy; };
    Config p = c, m = c;
    p.xa += e, m.xa -= e;
    EXPECT_NEAR(r.forceA[d], -(energy(p) - energy(m)) / (2 * eps), tolerance * fs) << "fa " << d;
    p = c, m = c;
    p.xb += e, m.xb -= e;
    EXPECT_NEAR(r.forceB[d], -(energy(p) - energy(m)) / (2 * eps), tolerance * fs) << "fb " << d;
    p = c, m = c;
    p.qa = expMap(e) * c.qa, m.qa = expMap(-e) * c.qa;
    EXPECT_NEAR(r.torqueA[d], -(energy(p) - energy(m)) / (2 * eps), tolerance * ts) << "ta " << d;
    p = c, m = c;
    p.qb = expMap(e) * c.qb, m.qb = expMap(-e) * c.qb;
    EXPECT_NEAR(r.torqueB[d], -(energy(p) - energy(m)) / (2 * eps), tolerance * ts) << "tb " << d;
  }
  // Action-reaction and the balance of moments about the origin (the energy is invariant under
  // rigid translations and rotations of the pair).
  EXPECT_LT((r.forceA + r.forceB).norm(), 1e-12 * fs);
  const Vec3 moment = c.xa.cross(r.forceA) + c.xb.cross(r.forceB) + r.torqueA + r.torqueB;
  EXPECT_LT(moment.norm(), 1e-9 * (fs * (c.xa.norm() + c.xb.norm()) + ts));
}

std::vector<Config> generalConfigs() {
  const double d = tubePotential().equilibriumDistance();
  std::vector<Config> out;
  // Crossed at 30, 60, 90 degrees near the well, on the wall, in the tail; end-on overlap.
  const Quat base = axisAngle(Vec3(1, 1, 0).normalized(), 1.5708);  // body z -> world-ish x
  for (double theta : {0.5236, 1.0472, 1.5708}) {
    for (double extra : {-0.05, 0.02, 0.5}) {
      Config c;
      c.xa = Vec3(0.3, -0.2, 0.1), c.qa = normalized(axisAngle(Vec3(0, 1, 0), 1.5708) * axisAngle(Vec3(0, 0, 1), 0.3));
      const Vec3 ta = rotate(c.qa, Vec3::UnitZ());
      const Vec3 n = ta.unitOrthogonal();
      c.xb = c.xa + (d + extra) * n + 0.4 * ta;
      c.qb = normalized(axisAngle(n, theta) * c.qa * axisAngle(Vec3::UnitZ(), 0.8));
      out.push_back(c);
    }
  }
  (void)base;
  return out;
}

TEST(MdemVdwContact, AnisotropicForcesAndTorquesAreMinusEnergyGradient) {
  const QuadratureRule rule = gaussLegendre(8);
  auto kernel = [&](const Config& c) { return anisotropicVdw(tubePotential(), rule, c.a(), c.b()); };
  for (const Config& c : generalConfigs()) checkGradients(c, kernel, 1e-5);
}

TEST(MdemVdwContact, IsotropicForcesAreMinusEnergyGradientAndMatchParallelSegments) {
  const IsotropicVdw iso(tubePotential(), 0.5 * kSegmentLength, 0.5 * kSegmentLength);
  auto kernel = [&](const Config& c) { return iso.evaluate(c.xa, c.xb); };
  for (const Config& c : generalConfigs()) checkGradients(c, kernel, 1e-5);
  // U(r) is the anisotropic energy of parallel side-by-side segments (independent evaluation).
  const QuadratureRule rule = gaussLegendre(24);
  for (double r : {1.62, 1.67, 1.8, 2.2}) {
    const double aniso = anisotropicVdw(tubePotential(), rule, seg(Vec3::Zero(), Vec3::UnitX()),
                                        seg(Vec3(0, r, 0), Vec3::UnitX())).energy;
    double du;
    EXPECT_NEAR(iso.energy(r, &du), aniso, 1e-3 * std::abs(aniso) + 1e-3) << r;
  }
}

TEST(MdemVdwContact, NoCorrugationAlongAStraightChain) {
  // Segment a slides parallel to a chain of five collinear segments (a is the quadrature side).
  const QuadratureRule rule = gaussLegendre(8);
  const double d = tubePotential().equilibriumDistance();
  double lo = 1e300, hi = -1e300, fmax = 0.0;
  for (double x = -1.0; x <= 1.0; x += 0.0731) {
    double e = 0.0, fx = 0.0;
    for (int k = -2; k <= 2; ++k) {
      const ContactPairResult r = anisotropicVdw(tubePotential(), rule, seg(Vec3(x, d, 0), Vec3::UnitX()),
                                                 seg(Vec3(k * kSegmentLength, 0, 0), Vec3::UnitX()));
      e += r.energy, fx += r.forceA.x();
    }
    lo = std::min(lo, e), hi = std::max(hi, e), fmax = std::max(fmax, std::abs(fx));
  }
  EXPECT_LT(hi - lo, 1e-9 * std::abs(lo));
  EXPECT_LT(fmax, 1e-9 * std::abs(lo));
  // The isotropic form (central forces between centres) does corrugate on the same path:
  // the test above is not void.
  const IsotropicVdw iso(tubePotential(), 0.5 * kSegmentLength, 0.5 * kSegmentLength);
  double lo2 = 1e300, hi2 = -1e300;
  for (double x = -1.0; x <= 1.0; x += 0.0731) {
    double e = 0.0;
    for (int k = -2; k <= 2; ++k) e += iso.evaluate(Vec3(x, d, 0), Vec3(k * kSegmentLength, 0, 0)).energy;
    lo2 = std::min(lo2, e), hi2 = std::max(hi2, e);
  }
  std::printf("sliding along a chain: anisotropic energy range %.3g zJ, isotropic %.3g zJ\n", hi - lo, hi2 - lo2);
  EXPECT_GT(hi2 - lo2, 0.01 * std::abs(lo2));
}

TEST(MdemVdwContact, CrossedTubesFeelAnAligningMoment) {
  // Segment a (along x) crosses a tube b of five collinear segments turned by theta about the
  // contact normal y through the crossing point: b's axis is (cos theta, 0, sin theta).
  const QuadratureRule rule = gaussLegendre(8);
  const double d = tubePotential().equilibriumDistance();
  double previous = 0.0;
  for (double theta : {0.0, 0.2, 0.4, 0.7, 1.0, 1.3}) {
    const Vec3 tb(std::cos(theta), 0.0, std::sin(theta));
    double e = 0.0, ma = 0.0, mb = 0.0;
    for (int k = -2; k <= 2; ++k) {
      const Vec3 xb = Vec3(0, d, 0) + k * kSegmentLength * tb;
      const ContactPairResult r = anisotropicVdw(tubePotential(), rule, seg(Vec3::Zero(), Vec3::UnitX()), seg(xb, tb));
      e += r.energy;
      ma += r.torqueA.y();
      mb += r.torqueB.y() + (xb - Vec3(0, d, 0)).cross(r.forceB).y();  // about the crossing point
    }
    std::printf("theta %.2f: energy %.3f zJ, moment on a %.3f, on b %.3f zJ\n", theta, e, ma, mb);
    if (theta > 0.0) {
      EXPECT_GT(e, previous) << theta;  // the energy grows with the crossing angle
      EXPECT_LT(ma, 0.0) << theta;      // a turns towards b (about -y) ...
      EXPECT_GT(mb, 0.0) << theta;      // ... and b towards a
    }
    previous = e;
  }
}

}  // namespace
}  // namespace mesochain::mdem
