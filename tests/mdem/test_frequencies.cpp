// Free vibration of a small cantilever (element 0 clamped): the peaks of the FFTW power
// spectrum of the tip motion lie at the chain's eigenfrequencies, computed independently from
// the linearised stiffness and mass matrices with Eigen's generalized eigensolver. Also: the
// critical time step bound is not above the true stability limit 2 / omega_max.
#include <cmath>
#include <complex>
#include <cstdio>
#include <random>
#include <vector>

#include <fftw3.h>
#include <gtest/gtest.h>

#include "chain_fixture.hpp"
#include "mdem/normal_modes.hpp"
#include "mdem/units.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

std::vector<bool> freeDofsOfCantilever(int elements) {
  std::vector<bool> f(6 * elements, true);
  for (int d = 0; d < 6; ++d) f[d] = false;
  return f;
}

// Power spectrum (Hann window) of a real signal, bins 0 .. n/2.
std::vector<double> powerSpectrum(const std::vector<double>& x) {
  const int n = static_cast<int>(x.size());
  std::vector<double> in(n);
  std::vector<std::complex<double>> out(n / 2 + 1);
  for (int i = 0; i < n; ++i) in[i] = x[i] * (0.5 - 0.5 * std::cos(2 * units::kPi * i / n));
  fftw_plan plan = fftw_plan_dft_r2c_1d(n, in.data(), reinterpret_cast<fftw_complex*>(out.data()),
                                        FFTW_ESTIMATE);
  fftw_execute(plan);
  fftw_destroy_plan(plan);
  std::vector<double> p(out.size());
  for (std::size_t k = 0; k < out.size(); ++k) p[k] = std::norm(out[k]);
  return p;
}

TEST(MdemFrequencies, CriticalStepBoundIsSafe) {
  Scene s = cantilever(6);
  s.run.timeStepFraction = 1.0;
  Simulation sim(s);
  const Eigen::VectorXd w = eigenfrequencies(s.bodies, s.bonds, freeDofsOfCantilever(6));
  EXPECT_LE(sim.stability().omegaMax, 3.0 * w.maxCoeff());  // not absurdly conservative
  EXPECT_GE(sim.stability().omegaMax, w.maxCoeff() * (1.0 - 1e-12));
}

TEST(MdemFrequencies, SpectrumPeaksAtEigenfrequencies) {
  constexpr int kElements = 4;
  Scene s = cantilever(kElements);
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 1; i < kElements; ++i) {  // small kicks: linear regime
    s.bodies.velocity[i] = 1e-3 * Vec3(u(gen), u(gen), u(gen));
    s.bodies.setAngularVelocityWorld(i, 1e-3 * Vec3(u(gen), u(gen), u(gen)));
  }
  s.run.timeStepFraction = 0.05;
  Simulation sim(s);
  const double h = sim.timeStep();
  const Eigen::VectorXd omega = eigenfrequencies(s.bodies, s.bonds, freeDofsOfCantilever(kElements));

  constexpr int kSamples = 1 << 17;
  std::vector<std::vector<double>> signals(6, std::vector<double>(kSamples));
  const int tip = kElements - 1;
  for (int k = 0; k < kSamples; ++k) {
    sim.step();
    const Vec3 d = sim.bodies().position[tip] - sim.bodies().initialPosition[tip];
    const Vec3 r = sim.bodies().accumulatedRotation[tip];
    for (int c = 0; c < 3; ++c) signals[c][k] = d[c] / kL, signals[3 + c][k] = r[c];
  }
  // Sum of the normalised spectra of the six tip coordinates.
  std::vector<double> power(kSamples / 2 + 1, 0.0);
  for (const auto& x : signals) {
    const std::vector<double> p = powerSpectrum(x);
    double mx = 0.0;
    for (double v : p) mx = std::max(mx, v);
    for (std::size_t k = 0; k < p.size(); ++k) power[k] += p[k] / mx;
  }
  const double binOmega = 2 * units::kPi / (kSamples * h);  // rad/ns per bin
  int checked = 0;
  double worst = 0.0;
  for (int m = 0; m < omega.size(); ++m) {
    // Verlet's discrete frequency: 2/h asin(omega h/2) (exact for a linear system).
    const double expected = 2.0 / h * std::asin(0.5 * omega[m] * h);
    const double bin = expected / binOmega;
    // Only modes separated from their neighbours by more than 8 bins can be resolved.
    bool isolated = bin > 8;
    for (int o = 0; o < omega.size(); ++o)
      if (o != m && std::abs(omega[o] - omega[m]) < 8 * binOmega) isolated = false;
    if (!isolated) continue;
    const int k0 = static_cast<int>(std::lround(bin));
    int best = k0;
    for (int k = k0 - 3; k <= k0 + 3; ++k)
      if (power[k] > power[best]) best = k;
    if (power[best] < 1e-8) continue;  // mode not excited at the tip
    // Parabolic interpolation of log power around the maximum.
    const double a = std::log(power[best - 1]), b = std::log(power[best]), c = std::log(power[best + 1]);
    const double peak = best + 0.5 * (a - c) / (a - 2 * b + c);
    EXPECT_NEAR(peak, bin, 0.05) << "mode " << m << " omega " << omega[m] << " rad/ns";
    ++checked;
    worst = std::max(worst, std::abs(peak - bin));
  }
  EXPECT_GE(checked, 8) << "too few modes resolved";
  std::printf("modes resolved %d of %d, worst peak offset %.3g bins\n", checked, static_cast<int>(omega.size()), worst);
}

}  // namespace
}  // namespace mesochain::mdem
