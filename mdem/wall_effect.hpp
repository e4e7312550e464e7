#pragma once
// "walls": two rigid, frictionless plates normal to z that push the elements of a film (the
// compression stage, mdem/compression.hpp; docs/scene-file.md, [stages.compression]). Built
// whenever the scene has a compression (not listed by name), ledger entry "walls".
//
// Contact law: a point of an element's axis at height z meets the bottom plate (plane z_b) at
// the gap g = z - R - z_b between the tube wall (radius R, ElementType::contactRadius) and the
// plate, the top plate (z_t) at g = z_t - z - R. Each gap below the rest gap g_w stores, per
// unit length of axis,
//     e(g) = k/2 (g_w - g)^2   (g < g_w; 0 beyond: repulsive only, C1 at g_w),
// with k by default the curvature Phi''(d_eq) of the tube-tube van der Waals contact at its
// minimum (tube_potential.hpp, two parallel tubes of the element's kind): a plate resists
// indentation as stiffly as another tube does; g_w defaults to 0.34 nm, the graphite interlayer
// spacing. The energy of an element is the Gauss-Legendre quadrature of e along its axis,
//     E_i = sum_q w_q L/2 [e(g_b(s_q)) + e(g_t(s_q))],  axis point c + s t,  s = s_q L/2,
// and its force and torque are exactly minus the gradient of that sum: F = f z^ with
// f = -sum_q w_q L/2 [e'(g_b) - e'(g_t)], torque (t x z^) sum_q s_q w_q L/2 [-(e'(g_b) - e'(g_t))].
// The plates exert only normal forces: no in-plane force and no moment about z.
//
// The plates move with the compression protocol z_b(t), z_t(t) (compression.hpp). The load of
// the film on a plate is N_b = dE/dz_b >= 0 (pushing the bottom plate down), N_t = -dE/dz_t >= 0;
// the work the plates do on the film, W = \int (N_b dz_b - N_t dz_t), is accumulated per force
// evaluation by the trapezoid rule in the plate displacement (plateWork()), so that
// total(t) - total(0) + dissipated = W (energy balance, tests/mdem/test_compression.cpp).
#include <vector>

#include "mdem/contacts/quadrature.hpp"
#include "mdem/effect.hpp"
#include "mdem/scene.hpp"

namespace mesochain::mdem {

class WallEffect : public Effect {
 public:
  explicit WallEffect(const Scene& scene);
  std::string name() const override { return "walls"; }
  int itemCount() const override { return static_cast<int>(force_.size()); }
  void computeItems(const State& state, double time, int lo, int hi) override;
  int itemElement(int k) const override { return k; }
  void gather(const State& state, double time, int lo, int hi, Vec3* force, Vec3* torque) const override;
  bool hasFinish() const override { return true; }
  void finish(const State& state, double time) override;
  void reportEnergy(const State& state, EnergyLedger& ledger) const override;
  void addElementEnergies(const State& state, std::vector<double>& perElement) const override;
  void addStabilityTerms(std::vector<ContactStabilityTerms>& perType) const override;
  void saveState(BinaryWriter& out) const override;
  void loadState(BinaryReader& in) override;

  // Of the last force evaluation: the film's loads on the plates (pN, >= 0) and the plates' work
  // on the film since the effect was built (zJ).
  double bottomLoad() const { return loadBottom_; }
  double topLoad() const { return loadTop_; }
  double plateWork() const { return work_; }
  double stiffness() const { return spec_.stiffness; }

  // One element's energy, force, torque and its plate loads (dE/dz_b, -dE/dz_t), plates at
  // zb, zt. Public for tests.
  struct ElementWall {
    double energy = 0.0;
    Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
    double loadBottom = 0.0, loadTop = 0.0;
  };
  ElementWall element(const Bodies& b, int i, double zb, double zt) const;

 private:
  CompressionSpec spec_;
  std::vector<double> radius_, halfLength_;  // per type
  QuadratureRule rule_;
  std::vector<Vec3> force_, torque_;
  std::vector<double> nb_, nt_;
  double loadBottom_ = 0.0, loadTop_ = 0.0, work_ = 0.0;
  double lastTime_ = 0.0, lastBottom_ = 0.0, lastTop_ = 0.0;  // plates at the last evaluation
};

}  // namespace mesochain::mdem
