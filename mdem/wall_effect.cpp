#include "mdem/wall_effect.hpp"

#include <algorithm>
#include <cmath>

#include "mdem/binary_io.hpp"
#include "mdem/compression.hpp"
#include "mdem/effect_registry.hpp"
#include "mdem/stability.hpp"

namespace mesochain::mdem {

// Not listed by name: built for a compression stage (run.cpp sets scene.compression).
MESOCHAIN_MDEM_EFFECT(EffectRegistration{
    "walls", 300, "rigid plates normal to z of a compression stage ([stages.compression])", false,
    [](const Scene& s) { return s.compression.enabled; },
    [](EffectBuild& b) -> EffectPtr { return std::make_unique<WallEffect>(b.scene); },
    EffectTable{}, false})

WallEffect::WallEffect(const Scene& scene) : spec_(scene.compression), rule_(gaussLegendre(scene.compression.quadraturePoints)) {
  for (const ElementType& t : scene.elementTypes) radius_.push_back(t.contactRadius()), halfLength_.push_back(0.5 * t.length);
  const int n = scene.bodies.size();
  force_.assign(n, Vec3::Zero()), torque_.assign(n, Vec3::Zero());
  nb_.assign(n, 0.0), nt_.assign(n, 0.0);
  const PlateState p = plateStateAt(spec_, spec_.startTime);
  lastTime_ = spec_.startTime, lastBottom_ = p.bottom, lastTop_ = p.top;
}

WallEffect::ElementWall WallEffect::element(const Bodies& b, int i, double zb, double zt) const {
  ElementWall out;
  const int type = b.type[i];
  const double r = radius_[type], h = halfLength_[type], gw = spec_.wallGap, k = spec_.stiffness;
  const double z = b.position[i].z();
  const Vec3 t = rotate(b.orientation[i], Vec3::UnitZ());
  const double reach = h * std::abs(t.z()) + r + gw;  // beyond: no quadrature point is near a plate
  if (z - reach >= zb && z + reach <= zt) return out;
  double sumF = 0.0, sumM = 0.0;  // sum of w L/2 (e'_b - e'_t), and the same times s
  for (std::size_t q = 0; q < rule_.x.size(); ++q) {
    const double s = rule_.x[q] * h, w = rule_.w[q] * h;
    const double zq = z + s * t.z();
    const double gb = zq - r - zb, gt = zt - zq - r;
    double de = 0.0;
    if (gb < gw) {
      const double d = gw - gb;
      out.energy += w * 0.5 * k * d * d;
      de -= k * d;  // e'(g_b) dg_b/dz, dg_b/dz = 1
      out.loadBottom += w * k * d;  // dE/dz_b = -e'(g_b)
    }
    if (gt < gw) {
      const double d = gw - gt;
      out.energy += w * 0.5 * k * d * d;
      de += k * d;  // e'(g_t) dg_t/dz, dg_t/dz = -1
      out.loadTop += w * k * d;  // -dE/dz_t = -e'(g_t)
    }
    sumF += w * de, sumM += w * s * de;
  }
  // dE/dz = sumF; a rotation dphi changes t_z by (dphi x t) . z^ = dphi . (t x z^).
  out.force = Vec3(0.0, 0.0, -sumF);
  out.torque = -sumM * t.cross(Vec3::UnitZ());
  return out;
}

void WallEffect::computeItems(const State& state, double time, int lo, int hi) {
  const PlateState p = plateStateAt(spec_, time);
  for (int i = lo; i < hi; ++i) {
    const ElementWall w = element(state.bodies, i, p.bottom, p.top);
    force_[i] = w.force, torque_[i] = w.torque, nb_[i] = w.loadBottom, nt_[i] = w.loadTop;
  }
}

void WallEffect::gather(const State&, double, int lo, int hi, Vec3* force, Vec3* torque) const {
  for (int i = lo; i < hi; ++i) force[i] += force_[i], torque[i] += torque_[i];
}

void WallEffect::finish(const State&, double time) {
  double nb = 0.0, nt = 0.0;
  for (std::size_t i = 0; i < nb_.size(); ++i) nb += nb_[i], nt += nt_[i];
  const PlateState p = plateStateAt(spec_, time);
  // Trapezoid rule in the plate displacement: exact where the plates reverse between steps.
  work_ += 0.5 * (loadBottom_ + nb) * (p.bottom - lastBottom_) - 0.5 * (loadTop_ + nt) * (p.top - lastTop_);
  loadBottom_ = nb, loadTop_ = nt;
  lastTime_ = time, lastBottom_ = p.bottom, lastTop_ = p.top;
}

void WallEffect::reportEnergy(const State& state, EnergyLedger& ledger) const {
  const PlateState p = plateStateAt(spec_, state.time);
  double e = 0.0;
  for (int i = 0; i < state.bodies.size(); ++i) e += element(state.bodies, i, p.bottom, p.top).energy;
  ledger.add("walls", EnergyKind::Potential, e);
}

void WallEffect::addElementEnergies(const State& state, std::vector<double>& perElement) const {
  const PlateState p = plateStateAt(spec_, state.time);
  for (int i = 0; i < state.bodies.size(); ++i) perElement[i] += element(state.bodies, i, p.bottom, p.top).energy;
}

void WallEffect::addStabilityTerms(std::vector<ContactStabilityTerms>& terms) const {
  // One element against one plate: E = k L/2 delta^2 (translation), k L^3/12 per rad^2 tilt
  // about an axis normal to the tube.
  for (std::size_t a = 0; a < terms.size() && a < halfLength_.size(); ++a) {
    const double l = 2.0 * halfLength_[a];
    terms[a].stiffness += spec_.stiffness * l;
    terms[a].rotationalStiffness += Vec3(1.0, 1.0, 0.0) * (spec_.stiffness * l * l * l / 12.0);
  }
}

void WallEffect::saveState(BinaryWriter& out) const {
  for (double v : {loadBottom_, loadTop_, work_, lastTime_, lastBottom_, lastTop_}) out.write(v);
}

void WallEffect::loadState(BinaryReader& in) {
  for (double* v : {&loadBottom_, &loadTop_, &work_, &lastTime_, &lastBottom_, &lastTop_}) *v = in.read<double>();
}

}  // namespace mesochain::mdem
