#include "mdem/contacts/contact_effects.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "mdem/binary_io.hpp"
#include "mdem/contacts/contact_file.hpp"
#include "mdem/effect_registry.hpp"

namespace mesochain::mdem {

namespace {
std::shared_ptr<ContactNeighbourhood> sharedNeighbourhood(EffectBuild& b, bool* owner);
}  // namespace

MESOCHAIN_MDEM_EFFECT(EffectRegistration{
    "vdw_contact", 200, "van der Waals contacts between tubes or bricks ([vdw_contact], docs/mdem-contacts.md)", true,
    nullptr, [](EffectBuild& b) -> EffectPtr {
      bool owner;
      auto nb = sharedNeighbourhood(b, &owner);
      return std::make_unique<VdwContactEffect>(b.scene, std::move(nb), owner);
    },
    {"vdw_contact", true, readVdwContactTable}})
MESOCHAIN_MDEM_EFFECT(EffectRegistration{
    "contact_damping", 400, "dashpots in parallel with the contacts ([contact_damping])", true, nullptr,
    [](EffectBuild& b) -> EffectPtr {
      bool owner;
      auto nb = sharedNeighbourhood(b, &owner);
      return std::make_unique<ContactDampingEffect>(b.scene, std::move(nb), owner);
    },
    {"contact_damping", true, readContactDampingTable}})

namespace {


double maxHalfLength(const Scene& s) {
  double l = 0.0;
  for (const ElementType& t : s.elementTypes) l = std::max(l, 0.5 * t.length);
  return l;
}
double maxRadius(const Scene& s) {
  double r = 0.0;
  for (const ElementType& t : s.elementTypes) r = std::max(r, t.contactRadius());
  return r;
}


// Adds the per-pair results of elements [lo, hi) to their forces in a fixed order.
void gatherPairs(const NeighbourList& list, const std::vector<ContactPairResult>& results, int lo, int hi,
                 Vec3* force, Vec3* torque) {
  const std::vector<int>& start = list.incidentStart();
  const std::vector<int>& inc = list.incident();
  for (int i = lo; i < hi; ++i) {
    Vec3 f = Vec3::Zero(), t = Vec3::Zero();
    for (int e = start[i]; e < start[i + 1]; ++e) {
      const ContactPairResult& r = results[inc[e] >> 1];
      if (inc[e] & 1) {
        f += r.forceB, t += r.torqueB;
      } else {
        f += r.forceA, t += r.torqueA;
      }
    }
    force[i] += f;
    torque[i] += t;
  }
}

// Every element's axis (body z in the world frame), in parallel when there are many.
void elementAxes(const Bodies& b, std::vector<Vec3>& axes) {
  const int n = b.size();
  axes.resize(n);
#pragma omp parallel for schedule(static) if (n > 2048)
  for (int i = 0; i < n; ++i) axes[i] = rotate(b.orientation[i], Vec3::UnitZ());
}

// The neighbourhood the contact effects of one scene share, with the range of those named; the
// first effect that asks for it owns it (saves it in checkpoints).
std::shared_ptr<ContactNeighbourhood> sharedNeighbourhood(EffectBuild& b, bool* owner) {
  *owner = false;
  return b.shared<ContactNeighbourhood>("contact_neighbourhood", [&] {
    *owner = true;
    validateContactSpec(b.scene);
    double range = 0.0, axis = 0.0;
    if (b.named("vdw_contact")) {
      range = std::max(range, VdwContactEffect::interactionRange(b.scene));
      axis = std::max(axis, VdwContactEffect::axisRange(b.scene));
    }
    if (b.named("contact_damping")) {
      range = std::max(range, ContactDampingEffect::interactionRange(b.scene));
      axis = std::max(axis, ContactDampingEffect::axisRange(b.scene));
    }
    return std::make_shared<ContactNeighbourhood>(b.scene, range, axis);
  });
}
}  // namespace

ContactNeighbourhood::ContactNeighbourhood(const Scene& scene, double range, double axisRange)
    : periodicity_(scene.periodic),
      topology_(buildTopology(scene.bodies.size(), scene.bonds, scene.contacts.excludeWithin,
                              scene.contacts.closedFilaments)),
      list_(range, scene.contacts.skin, scene.periodic, axisRange) {
  for (const ElementType& t : scene.elementTypes) {
    halfLength_.push_back(0.5 * t.length);
    radius_.push_back(t.contactRadius());
  }
  for (int k = 0; k < 3; ++k)
    if (scene.periodic.periodic[k] && scene.periodic.length[k] <= 2.0 * list_.listRange())
      throw InputError(scene.source, "key periodic.length_nm",
                       fmt::format("{:.4g} nm along {}", scene.periodic.length[k], "xyz"[k]),
                       fmt::format("more than twice the neighbour-list range {:.4g} nm (contact "
                                   "range + element length + skin), for the minimum image",
                                   list_.listRange()));
  update(scene.bodies);
}

VdwContactEffect::VdwContactEffect(const Scene& scene, std::shared_ptr<ContactNeighbourhood> nb, bool owner)
    : scene_(scene), spec_(scene.contacts.vdw),
      typeCount_(static_cast<int>(scene.elementTypes.size())), types_(typeCount_ * typeCount_), nb_(std::move(nb)), ownsNeighbourhood_(owner) {
  std::vector<char> used(typeCount_, 0);
  for (int t : scene.bodies.type) used[t] = 1;
  bool bricks = false, tubes = false;
  for (int a = 0; a < typeCount_; ++a) {
    const ElementType& t = scene.elementTypes[a];
    width_.push_back(t.width), length_.push_back(t.length);
    if (!used[a]) continue;
    (t.shape == Shape::Brick ? bricks : tubes) = true;
    if (t.shape == Shape::Brick && spec_.edgeWidth >= 0.5 * std::min(t.width, t.length))
      throw InputError(scene.source, "key vdw_contact.edge_width_nm", fmt::format("{:.4g} nm", spec_.edgeWidth),
                       fmt::format("less than half the width and length of brick type \"{}\" ({:.4g} nm)", t.name,
                                   0.5 * std::min(t.width, t.length)));
  }
  if (bricks && tubes)
    throw InputError(scene.source, "key effects", "\"vdw_contact\" between brick and cylinder elements",
                     "elements of one shape (tube-tube or face-to-face brick contacts; mixed pairs are not implemented)");
  if (bricks) {
    FaceContactSpec fs;
    fs.lj = spec_.lj, fs.layerSpacing = spec_.layerSpacing, fs.edgeWidth = spec_.edgeWidth;
    fs.switchGap = spec_.switchGap, fs.cutoffGap = spec_.cutoffGap;
    face_ = std::make_unique<FaceContactModel>(fs);
    checkInitialOverlaps();
    return;
  }
  for (int a = 0; a < typeCount_; ++a) {
    if (!used[a]) continue;
    const ElementType& ta = scene.elementTypes[a];
    for (int b = a; b < typeCount_; ++b) {
      if (!used[b]) continue;
      const ElementType& tb = scene.elementTypes[b];
      TubePairSpec ps;
      ps.lj = spec_.lj, ps.radiusA = ta.radius, ps.radiusB = tb.radius;
      ps.switchGap = spec_.switchGap, ps.cutoffGap = spec_.cutoffGap;
      TypePair& tp = types_[a * typeCount_ + b];
      tp.potential = std::make_unique<TubePairPotential>(ps);
      if (!spec_.anisotropic) tp.isotropic = std::make_unique<IsotropicVdw>(*tp.potential, 0.5 * ta.length, 0.5 * tb.length);
      if (spec_.anisotropic) {
        tp.kernelAgainst.resize(typeCount_);
        for (const auto& [quad, partner] : {std::pair{&ta, b}, std::pair{&tb, a}}) {
          if (tp.kernelAgainst[partner]) continue;
          const double la = 0.5 * quad->length, lb = 0.5 * scene.elementTypes[partner].length;
          tp.kernelAgainst[partner] =
              spec_.quadratureTolerance > 0.0
                  ? std::make_unique<AnisotropicVdwKernel>(*tp.potential, la, lb, spec_.quadratureTolerance)
                  : std::make_unique<AnisotropicVdwKernel>(*tp.potential, lb, spec_.quadraturePoints);
          tp.kernelAgainst[partner]->enableAlignedPath(la, spec_.alignedWindowDegrees);
          tp.kernelAgainst[partner]->enableCrossingRule(spec_.crossingQuadraturePoints);
        }
      }
    }
  }
  checkInitialOverlaps();
}

void VdwContactEffect::checkInitialOverlaps() const {
  // Elements that start inside each other would meet the steep repulsive wall of the contact
  // and fly apart: tubes whose walls interpenetrate (wall gap < 0 at the closest points of the
  // axes), bricks whose centres are less than half their mean thickness apart across the face
  // while their faces overlap in plane.
  const Bodies& b = scene_.bodies;
  for (const auto& [i, j] : nb_->list().pairs()) {
    const ElementType& ta = scene_.elementTypes[b.type[i]];
    const ElementType& tb = scene_.elementTypes[b.type[j]];
    const Segment sa = nb_->segment(b, i), sb = nb_->imageNear(b, j, sa.centre);
    std::string what;
    if (face_) {
      const Vec3 d = sb.centre - sa.centre;
      const Vec3 n = rotate(b.orientation[i], Vec3::UnitX()), w = rotate(b.orientation[i], Vec3::UnitY());
      if (std::abs(d.dot(n)) < 0.25 * (ta.thickness + tb.thickness) && std::abs(d.dot(w)) < 0.5 * std::max(ta.width, tb.width) &&
          std::abs(d.dot(sa.axis)) < 0.5 * std::max(ta.length, tb.length))
        what = fmt::format("bricks {} and {} overlapping (centres {:.3g} nm apart across the face)", i, j, std::abs(d.dot(n)));
    } else {
      const double gap = wallGap(sa, sb, ta.radius, tb.radius);
      if (gap < 0.0) what = fmt::format("tubes {} and {} overlapping (wall gap {:.3g} nm)", i, j, gap);
    }
    if (!what.empty())
      throw InputError(scene_.source, "elements", what,
                       "elements that do not start inside each other (the contact's repulsion would throw them apart)");
  }
}

double VdwContactEffect::interactionRange(const Scene& s) {
  double range = 2.0 * maxRadius(s) + s.contacts.vdw.cutoffGap + 2.0 * maxHalfLength(s);
  // Bricks: a point of a's face within the in-plane half diagonal of its centre, b's face grown by
  // the edge width, at most t + cutoff from b's mid-plane (face_contact.hpp).
  const VdwContactSpec& v = s.contacts.vdw;
  double diagonal = 0.0, grown = 0.0;
  for (const ElementType& t : s.elementTypes)
    if (t.shape == Shape::Brick) {
      diagonal = std::max(diagonal, std::hypot(0.5 * t.width, 0.5 * t.length));
      grown = std::max(grown, std::hypot(0.5 * t.width + v.edgeWidth, 0.5 * t.length + v.edgeWidth));
    }
  if (diagonal > 0.0) range = std::max(range, diagonal + std::hypot(grown, v.layerSpacing + v.cutoffGap));
  return range;
}

double VdwContactEffect::axisRange(const Scene& s) {
  if (!s.contacts.vdw.anisotropic) return std::numeric_limits<double>::infinity();
  double radius = 0.0;
  for (const ElementType& t : s.elementTypes) {
    if (t.shape == Shape::Brick) return std::numeric_limits<double>::infinity();
    radius = std::max(radius, t.radius);
  }
  // The kernels' own early out (segmentCutDistance), with the pair potentials' d_c = R_a + R_b + g_c.
  return segmentCutDistance(2.0 * radius + s.contacts.vdw.cutoffGap, TubePairPotential::kDefaultGridStep);
}

const TubePairPotential* VdwContactEffect::potential(int a, int b) const {
  return types_[std::min(a, b) * typeCount_ + std::max(a, b)].potential.get();
}

ContactPairResult VdwContactEffect::evaluatePair(const Bodies& b, int i, int j, const Vec3* axes) const {
  const TypePair& tp = types_[std::min(b.type[i], b.type[j]) * typeCount_ + std::max(b.type[i], b.type[j])];
  // Quadrature side: the element of the lower filament (then the lower index), so that a tube
  // sliding along another is always integrated the same way (no corrugation).
  const FilamentTopology& topo = nb_->topology();
  const bool iOuter = topo.filament[i] != topo.filament[j] ? topo.filament[i] < topo.filament[j] : i < j;
  const int o = iOuter ? i : j, in = iOuter ? j : i;
  const Segment so = axes ? nb_->segment(b, o, axes[o]) : nb_->segment(b, o);
  const Segment si = axes ? nb_->imageNear(b, in, axes[in], so.centre) : nb_->imageNear(b, in, so.centre);
  ContactPairResult r =
      face_ ? face_->evaluate(brickFace(so.centre, b.orientation[o], width_[b.type[o]], length_[b.type[o]]),
                              brickFace(si.centre, b.orientation[in], width_[b.type[in]], length_[b.type[in]]))
      : tp.isotropic ? tp.isotropic->evaluate(so.centre, si.centre)
                                     : anisotropicVdw(*tp.kernelAgainst[b.type[in]], so, si);
  if (!iOuter) std::swap(r.forceA, r.forceB), std::swap(r.torqueA, r.torqueB);
  return r;
}

void VdwContactEffect::prepare(const State& state, double) {
  nb_->update(state.bodies);  // (timed by dem --profile as this effect's prepare)
  results_.resize(nb_->list().pairs().size());
  elementAxes(state.bodies, axes_);
}

void VdwContactEffect::computeItems(const State& state, double, int lo, int hi) {
  const auto& pairs = nb_->list().pairs();
  for (int p = lo; p < hi; ++p) results_[p] = evaluatePair(state.bodies, pairs[p].first, pairs[p].second, axes_.data());
}

void VdwContactEffect::gather(const State&, double, int lo, int hi, Vec3* force, Vec3* torque) const {
  gatherPairs(nb_->list(), results_, lo, hi, force, torque);
}

void VdwContactEffect::reportEnergy(const State& state, EnergyLedger& ledger) const {
  const Bodies& s = state.bodies;
  const auto& pairs = nb_->list().pairs();
  const int np = static_cast<int>(pairs.size());
  std::vector<double> e(np);
#pragma omp parallel for schedule(dynamic, 256) if (np > 256)
  for (int p = 0; p < np; ++p) e[p] = evaluatePair(s, pairs[p].first, pairs[p].second).energy;
  double sum = 0.0;  // in pair order: independent of the thread count
  for (double x : e) sum += x;
  ledger.add("vdw", EnergyKind::Potential, sum);
}

void VdwContactEffect::addElementEnergies(const State& state, std::vector<double>& perElement) const {
  for (const auto& [i, j] : nb_->list().pairs()) {
    const double e = evaluatePair(state.bodies, i, j).energy;
    perElement[i] += 0.5 * e, perElement[j] += 0.5 * e;
  }
}

void VdwContactEffect::saveState(BinaryWriter& out) const {
  if (ownsNeighbourhood_) nb_->saveList(out);
}

void VdwContactEffect::loadState(BinaryReader& in) {
  if (ownsNeighbourhood_) nb_->loadList(in, scene_.bodies.size());
  results_.resize(nb_->list().pairs().size());
}

ContactDampingEffect::ContactDampingEffect(const Scene& scene, std::shared_ptr<ContactNeighbourhood> nb, bool owner)
    : scene_(scene), spec_(scene.contacts.damping), nb_(std::move(nb)), ownsNeighbourhood_(owner),
      refreshesList_(refreshesList(scene, owner)) {}

double ContactDampingEffect::interactionRange(const Scene& s) {
  return 2.0 * maxRadius(s) + s.contacts.damping.cutoffGap + 2.0 * maxHalfLength(s);
}

double ContactDampingEffect::axisRange(const Scene& s) {
  // contactDashpot is zero beyond a wall gap of cutoff_gap_nm between the axis segments.
  return 2.0 * maxRadius(s) + s.contacts.damping.cutoffGap;
}

bool ContactDampingEffect::refreshesList(const Scene& scene, bool owner) {
  if (owner) return true;
  // vdw_contact (first in the force order) refreshes the shared list, unless multiple time
  // stepping puts it on the outer step and the dashpots on the inner one.
  // (Without run.outer_effects, the outer group is vdw_contact alone: simulation.cpp.)
  const auto& outer = scene.run.outerEffects;
  const auto named = [&](const char* e) { return std::find(outer.begin(), outer.end(), e) != outer.end(); };
  return scene.run.outerStepRatio != 1 && (outer.empty() || named("vdw_contact") != named("contact_damping"));
}

void ContactDampingEffect::prepare(const State& state, double) {
  // The owner of the shared list refreshes it: vdw_contact, which comes first in the force
  // order, when the scene has it and runs on the same steps (the displacement check would
  // otherwise run twice a step).
  if (refreshesList_) nb_->update(state.bodies);
  results_.resize(nb_->list().pairs().size());
  power_.resize(results_.size());
  const Bodies& b = state.bodies;
  const int n = b.size();
  elementAxes(b, axes_);
  angularVelocity_.resize(n);
#pragma omp parallel for schedule(static) if (n > 2048)
  for (int i = 0; i < n; ++i) angularVelocity_[i] = b.angularVelocityWorld(i);
}

void ContactDampingEffect::computeItems(const State& state, double, int lo, int hi) {
  const Bodies& s = state.bodies;
  const auto& pairs = nb_->list().pairs();
  for (int p = lo; p < hi; ++p) {
    const int i = pairs[p].first, j = pairs[p].second;
    const Segment a = nb_->segment(s, i, axes_[i]), b = nb_->imageNear(s, j, axes_[j], a.centre);
    const Vec3& wi = angularVelocity_[i];
    const Vec3& wj = angularVelocity_[j];
    ContactPairResult& r = results_[p];
    if (!dashpotPair(spec_, a, b, nb_->radius(s.type[i]), nb_->radius(s.type[j]), s.velocity[i], wi, s.velocity[j], wj,
                     &r)) {  // listed but beyond the cut-off
      r = ContactPairResult{};
      power_[p] = 0.0;
      continue;
    }
    power_[p] = -(r.forceA.dot(s.velocity[i]) + r.torqueA.dot(wi) + r.forceB.dot(s.velocity[j]) + r.torqueB.dot(wj));
  }
}

void ContactDampingEffect::gather(const State&, double, int lo, int hi, Vec3* force, Vec3* torque) const {
  gatherPairs(nb_->list(), results_, lo, hi, force, torque);
}

double ContactDampingEffect::powerAtItemVelocities() const {
  double power = 0.0;  // in the pairs' order
  for (double p : power_) power += p;
  return power;
}

double ContactDampingEffect::powerAtStepVelocities(const State& state) const {
  const std::vector<Vec3>& v = state.stepVelocity;
  const std::vector<Vec3>& w = state.stepAngularVelocity;
  const auto& pairs = nb_->list().pairs();
  double power = 0.0;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    if (power_[p] == 0.0) continue;  // beyond the cut-off (or no relative motion): zero forces
    const ContactPairResult& r = results_[p];
    const int i = pairs[p].first, j = pairs[p].second;
    power -= r.forceA.dot(v[i]) + r.torqueA.dot(w[i]) + r.forceB.dot(v[j]) + r.torqueB.dot(w[j]);
  }
  return power;
}

void ContactDampingEffect::finish(const State& state, double time) {
  const double h = work_.stepTo(time);
  // Forces evaluated outside a step (a new simulation, a refresh, a report) charge nothing here
  // (kickForcesReplaced).
  if (!(h > 0.0) || state.stepVelocity.size() != static_cast<std::size_t>(state.bodies.size())) return;
  work_.charge(h, powerAtStepVelocities(state), powerAtItemVelocities());
}

void ContactDampingEffect::kickForcesReplaced(const State&) {
  work_.forcesReplaced(powerAtItemVelocities());
}

void ContactDampingEffect::reportEnergy(const State&, EnergyLedger& ledger) const {
  ledger.add("contact_dissipated", EnergyKind::Dissipated, work_.reported());
}

void ContactDampingEffect::saveState(BinaryWriter& out) const {
  out.write(work_.dissipated), out.write(work_.lastTime);
  if (ownsNeighbourhood_) nb_->saveList(out);
  out.write(work_.pending), out.write(work_.opening);  // last: checkpoints written before they existed end without them
}

void ContactDampingEffect::loadState(BinaryReader& in) {
  work_.dissipated = in.read<double>(), work_.lastTime = in.read<double>();
  if (ownsNeighbourhood_) nb_->loadList(in, scene_.bodies.size());
  work_.pending = in.remaining() >= sizeof(double) ? in.read<double>() : 0.0;
  work_.opening = in.remaining() >= sizeof(double) ? in.read<double>() : 0.0;
  results_.resize(nb_->list().pairs().size());
  power_.resize(results_.size());
}

namespace {
// Types present in the scene.
std::vector<char> usedTypes(const Scene& scene) {
  std::vector<char> used(scene.elementTypes.size(), 0);
  for (int t : scene.bodies.type) used[t] = 1;
  return used;
}
}  // namespace

void VdwContactEffect::addStabilityTerms(std::vector<ContactStabilityTerms>& terms) const {
  const Scene& scene = scene_;
  const int nt = static_cast<int>(scene.elementTypes.size());
  const std::vector<char> used = usedTypes(scene);
  const double n = kContactCoordination;
  for (int a = 0; a < nt; ++a) {
    if (!used[a]) continue;
    const ElementType& ta = scene.elementTypes[a];
    const double l = ta.length;
    ContactStabilityTerms& c = terms[a];
    if (faceModel()) {
      // Bricks: f''(D) at the minimum of the bilayer energy per area, over the face area A = w L;
      // tilting about the width / length axes: A L^2/12, A w^2/12; twisting about the normal
      // moves the edge ramps: |f_min| (perimeter) r^2 / delta with r the half diagonal.
      const FaceContactModel& m = *faceModel();
      double best = 0.0, dEq = 0.0, fMin = 0.0, df;
      for (double d = 0.5 * m.spec().layerSpacing; d < m.cutoffDistance(); d += 1e-3) {
        const double f = m.bilayerEnergy(d, &df);
        if (f < fMin) fMin = f, dEq = d;
      }
      const double delta = 1e-3;
      double up, down;
      m.bilayerEnergy(dEq + delta, &up), m.bilayerEnergy(dEq - delta, &down);
      best = (up - down) / (2.0 * delta);
      const double area = ta.width * ta.length, r2 = 0.25 * (ta.width * ta.width + l * l);
      c.stiffness += 2.0 * n * best * area;
      c.rotationalStiffness += Vec3(2.0 * n * std::abs(fMin) * 2.0 * (ta.width + l) * r2 / m.spec().edgeWidth,
                                    2.0 * n * best * area * l * l / 12.0,
                                    2.0 * n * best * area * ta.width * ta.width / 12.0);
    } else {
      double curvature = 0.0;  // largest Phi'' at the minimum over the partner types
      for (int b = 0; b < nt; ++b) {
        if (!used[b]) continue;
        const TubePairPotential& p = *potential(a, b);
        const double d = p.equilibriumDistance(), delta = 1e-3;
        double up, down;
        p.phi(d + delta, &up), p.phi(d - delta, &down);
        curvature = std::max(curvature, (up - down) / (2.0 * delta));
      }
      c.stiffness += 2.0 * n * curvature * l;
      c.rotationalStiffness += Vec3(1.0, 1.0, 0.0) * (2.0 * n * curvature * l * l * l / 12.0);
    }
  }
}

void ContactDampingEffect::addStabilityTerms(std::vector<ContactStabilityTerms>& terms) const {
  const Scene& scene = scene_;
  const std::vector<char> used = usedTypes(scene);
  const double n = kContactCoordination, rMax = maxRadius(scene);
  for (std::size_t a = 0; a < used.size(); ++a) {
    if (!used[a]) continue;
    const ElementType& ta = scene.elementTypes[a];
    const double l = ta.length, r = ta.contactRadius();
    ContactStabilityTerms& c = terms[a];
    const ContactDampingSpec& d = spec_;
    const double lambda = l + r + rMax, rc = r + 0.5 * d.fullGap;
    const double rn2 = 0.25 * l * l + rc * rc;
    c.damping += 2.0 * n * d.translational * lambda;
    const double normal = 2.0 * n * (d.translational * lambda * rn2 + d.rotational * lambda);
    const double axial = 2.0 * n * (d.translational * lambda * rc * rc + d.rotational * lambda);
    c.rotationalDamping += Vec3(normal, normal, axial);
  }
}


}  // namespace mesochain::mdem
