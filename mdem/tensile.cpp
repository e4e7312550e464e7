#include "mdem/tensile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "common/csv.hpp"
#include "common/errors.hpp"
#include "common/plot/canvas.hpp"
#include "common/plot/figure.hpp"
#include "common/plot/png_io.hpp"
#include "mdem/contacts/contact_effects.hpp"
#include "mdem/contacts/network_structure.hpp"
#include "mdem/contacts/neighbour_list.hpp"
#include "mdem/integrator.hpp"
#include "mdem/output.hpp"

namespace mesochain::mdem {

namespace {

double meanAxial(const Bodies& b, const std::vector<int>& grip, int axis) {
  double s = 0.0;
  for (int i : grip) s += b.position[i][axis];
  return s / grip.size();
}

// Grip velocity factor and acceleration of the ramp at time t.
double rampAcceleration(double t, double ramp, double speed) { return ramp > 0.0 && t < ramp ? speed / ramp : 0.0; }
double rampVelocity(double t, double ramp, double speed) { return ramp > 0.0 ? speed * std::min(1.0, t / ramp) : speed; }
}  // namespace

double tensileTimeToStrain(const TensileSpec& t, double strain) {
  const double duringRamp = 0.5 * t.strainRate * t.ramp;  // the strain at the ramp's end
  return strain <= duringRamp ? std::sqrt(2.0 * t.ramp * strain / t.strainRate) : strain / t.strainRate + 0.5 * t.ramp;
}

void setUpTensile(Scene& s) {
  TensileSpec& t = s.tensile;
  if (!t.enabled) return;
  const Bodies& b = s.bodies;
  const int a = t.axis;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Vec3& x : b.position) lo = std::min(lo, x[a]), hi = std::max(hi, x[a]);
  t.leftGrip.clear(), t.rightGrip.clear();
  double leftInner = -std::numeric_limits<double>::infinity(), rightInner = -leftInner;
  for (int i = 0; i < b.size(); ++i) {
    const double x = b.position[i][a];
    if (x <= lo + t.gripWidth) t.leftGrip.push_back(i), leftInner = std::max(leftInner, x);
    else if (x >= hi - t.gripWidth) t.rightGrip.push_back(i), rightInner = std::min(rightInner, x);
  }
  t.gaugeLength = rightInner - leftInner;
  if (t.rightGrip.empty() || !(t.gaugeLength > 0.0))
    throw InputError(s.source, "key tensile.grip_width_nm", fmt::format("{:.6g} nm on a specimen of {:.6g} nm", t.gripWidth, hi - lo),
                     "grips narrower than half the specimen, leaving free elements between them");
  for (const FixedDofs& f : s.boundary.fixed)
    if (std::count(t.leftGrip.begin(), t.leftGrip.end(), f.element) || std::count(t.rightGrip.begin(), t.rightGrip.end(), f.element))
      throw InputError(s.source, "key tensile.grip_width_nm", fmt::format("element {} in a grip and in [[fixed]]", f.element),
                       "grip elements without other constraints");
  for (const Prescribed& p : s.boundary.prescribed)
    if (std::count(t.leftGrip.begin(), t.leftGrip.end(), p.element) || std::count(t.rightGrip.begin(), t.rightGrip.end(), p.element))
      throw InputError(s.source, "key tensile.grip_width_nm", fmt::format("element {} in a grip and in [[prescribed]]", p.element),
                       "grip elements without other constraints");
  // The contact counts come from the contacts' neighbour list, which holds every pair whose axis
  // segments are closer than its axis range (2 R + the largest cut-off gap of those named).
  const auto named = [&](const char* e) { return std::find(s.effects.begin(), s.effects.end(), e) != s.effects.end(); };
  double listed = 0.0, radius = 0.0;
  if (named("vdw_contact")) listed = std::max(listed, VdwContactEffect::axisRange(s));
  if (named("contact_damping")) listed = std::max(listed, ContactDampingEffect::axisRange(s));
  for (const ElementType& e : s.elementTypes) radius = std::max(radius, e.contactRadius());
  if (listed > 0.0 && 2.0 * radius + t.contactGap > listed)
    throw InputError(s.source, "key tensile.contact_gap_nm", fmt::format("{:.6g} nm", t.contactGap),
                     fmt::format("at most {:.4g} nm (the contacts' reach beyond the walls)", listed - 2.0 * radius));
  if (!(t.crossSection > 0.0)) {
    if (s.filmSize.isZero())
      throw InputError(s.source, "key tensile.cross_section_nm2", "nothing (and no [network] film)",
                       "the specimen's cross-section in nm^2");
    double r = 0.0;
    for (const ElementType& e : s.elementTypes) r = std::max(r, e.contactRadius());
    t.crossSection = s.filmSize[1 - a] * (s.filmSize.z() + 2.0 * r);
  }
  t.gripSpeed = 0.5 * t.strainRate * t.gaugeLength;
  t.leftReference = meanAxial(b, t.leftGrip, a), t.rightReference = meanAxial(b, t.rightGrip, a);
  for (int side = 0; side < 2; ++side)
    for (int i : side == 0 ? t.leftGrip : t.rightGrip) {
      FixedDofs f;
      f.element = i;
      f.fixed[a] = true;
      f.velocity[a] = side == 0 ? -t.gripSpeed : t.gripSpeed;
      f.ramp = t.ramp;
      f.start = t.startTime;
      s.boundary.fixed.push_back(f);
    }
}

TensileRecorder::TensileRecorder(const Scene& scene, const std::string& csvPath, std::int64_t resumeAt)
    : scene_(scene), area_(scene.tensile.crossSection) {
  if (csvPath.empty()) return;
  csv_ = std::make_unique<AppendFile>(csvPath, resumeAt);
  // The header follows at the first sample, when the ledger's entries are known.
}

const TensileSample& TensileRecorder::record(const Simulation& sim, const EnergyLedger& energies) {
  const TensileSpec& t = scene_.tensile;
  const Bodies& b = sim.bodies();
  const int a = t.axis;
  TensileSample s;
  s.time = sim.time();
  const double du = (meanAxial(b, t.rightGrip, a) - t.rightReference) - (meanAxial(b, t.leftGrip, a) - t.leftReference);
  s.strain = du / t.gaugeLength;
  const std::vector<Vec3> f = sim.unconstrainedForces();
  const double tt = s.time - t.startTime;
  const double acc = rampAcceleration(tt, t.ramp, t.gripSpeed), vel = rampVelocity(tt, t.ramp, t.gripSpeed);
  double power = 0.0;
  for (int side = 0; side < 2; ++side) {
    const double sign = side == 0 ? -1.0 : 1.0;
    double sum = 0.0;
    for (int i : side == 0 ? t.leftGrip : t.rightGrip) {
      sum += f[i][a];
      power += (b.mass[i] * sign * acc - f[i][a]) * sign * vel;  // reaction times grip velocity
    }
    (side == 0 ? s.forceLeft : s.forceRight) = sum;
  }
  s.stress = 0.5 * (s.forceLeft - s.forceRight) / area_;
  s.energies = energies;
  if (!samples_.empty()) s.gripWork = samples_.back().gripWork + 0.5 * (lastPower_ + power) * (s.time - samples_.back().time);
  lastPower_ = power;
  if (const ContactNeighbourhood* nb = sim.contactNeighbourhood()) {
    const NetworkStructure n = networkStructure(*nb, b, t.contactGap, t.alignedAngle, a);
    s.contacts = n.contacts, s.aligned = n.aligned;
    s.bundles = n.bundles, s.largestBundle = n.largestBundle, s.meanBundle = n.meanBundle;
    s.orderParameter = n.orderParameter, s.axisAlignment = n.axisAlignment;
  }
  samples_.push_back(s);
  if (csv_) {
    if (columns_.empty()) columns_ = energyColumns(s.energies);
    std::string row;
    if (csv_->bytes() == 0) {
      row = "time_ns,strain,stress_MPa,force_left_pN,force_right_pN,grip_work_zJ";
      for (const std::string& c : columns_) row += "," + csvField((c.empty() ? std::string("total") : c) + "_zJ");
      row += ",contact_pairs,aligned_pairs,bundles,mean_bundle_elements,largest_bundle_elements,order_parameter,axis_alignment\n";
    }
    row += fmt::format("{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}", s.time, s.strain, s.stress, s.forceLeft,
                       s.forceRight, s.gripWork);
    for (const std::string& c : columns_) row += fmt::format(",{:.10g}", c.empty() ? s.energies.total() : s.energies[c]);
    row += fmt::format(",{},{},{},{:.6g},{},{:.6g},{:.6g}\n", s.contacts, s.aligned, s.bundles, s.meanBundle, s.largestBundle,
                       s.orderParameter, s.axisAlignment);
    csv_->write(row);
  }
  return samples_.back();
}

ElasticFit fitElasticSlope(const std::vector<TensileSample>& samples, double from, double to) {
  ElasticFit f;
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, syy = 0.0;
  f.from = to, f.to = from;
  for (const TensileSample& t : samples) {
    if (t.strain < from || t.strain > to) continue;
    sx += t.strain, sy += t.stress, sxx += t.strain * t.strain, sxy += t.strain * t.stress, syy += t.stress * t.stress;
    f.from = std::min(f.from, t.strain), f.to = std::max(f.to, t.strain);
    ++f.samples;
  }
  const double n = f.samples, dxx = n * sxx - sx * sx, dyy = n * syy - sy * sy, dxy = n * sxy - sx * sy;
  if (f.samples < kElasticMinimumSamples || !(dxx > 0.0) || f.to - f.from < 0.5 * (to - from)) return f;
  f.fitted = true;
  f.slope = dxy / dxx;
  f.intercept = (sy - f.slope * sx) / n;
  f.r2 = dyy > 0.0 ? dxy * dxy / (dxx * dyy) : 1.0;
  return f;
}

void TensileRecorder::writePlot(const std::string& path, const TensileBundles* bundles, const std::string& runningNote) const {
  std::vector<double> strain, stress, contacts, aligned, order, alignment, largest;
  // Each stored (potential) energy, the kinetic energy, the grip work, total - initial and the
  // work of each dissipative effect since the first sample.
  // (grip work = (total - initial) + dissipated).
  std::vector<std::string> names, dissipated;
  if (!samples_.empty()) {
    for (const LedgerEntry& e : samples_.front().energies.entries()) {
      if (e.kind == EnergyKind::Potential) names.push_back(e.name);
      if (e.kind == EnergyKind::Dissipated) dissipated.push_back(e.name);
    }
  }
  const std::size_t stored = names.size();
  names.insert(names.end(), {"kinetic", "grip work", "total - initial"});
  names.insert(names.end(), dissipated.begin(), dissipated.end());
  std::vector<std::vector<double>> energy(names.size());
  for (const TensileSample& s : samples_) {
    strain.push_back(s.strain), stress.push_back(s.stress);
    contacts.push_back(s.contacts), aligned.push_back(s.aligned);
    order.push_back(s.orderParameter), alignment.push_back(s.axisAlignment), largest.push_back(s.largestBundle);
    const EnergyLedger& e = s.energies;
    for (std::size_t k = 0; k < stored; ++k) energy[k].push_back(e[names[k]]);
    energy[stored].push_back(e.kinetic());
    energy[stored + 1].push_back(s.gripWork);
    energy[stored + 2].push_back(e.total() - samples_.front().energies.total());
    for (std::size_t k = 0; k < dissipated.size(); ++k)
      energy[stored + 3 + k].push_back(e[dissipated[k]] - samples_.front().energies[dissipated[k]]);
  }
  const std::string suffix = "_dissipated";
  for (std::string& n : names)
    if (n == "vdw") {
      n = "van der Waals";
    } else if (n.ends_with(suffix)) {  // "contact_dissipated" -> "dissipated: contact"
      n = "dissipated: " + n.substr(0, n.size() - suffix.size());
      std::replace(n.begin(), n.end(), '_', ' ');
    }
  const int width = 900, height = 420;
  plot::Figure fs("Engineering stress against strain"), fe("Energies against strain"), fc("Contacts and bundles against strain");
  if (!runningNote.empty()) fs.title += " - " + runningNote;
  fs.x.label = fe.x.label = fc.x.label = "strain";
  fs.y.label = "stress (MPa)";
  fe.y.label = "energy (zJ)";
  fc.y.label = "pairs, elements";
  fs.add(fmt::format("stress (A = {:.4g} nm^2)", area_), strain, stress);
  const ElasticFit fit = fitElasticSlope(samples_, 0.0, kElasticStrain);
  if (fit.fitted) {
    plot::SeriesStyle dashed;
    dashed.color = plot::paletteColor(1);
    dashed.dashed = true;
    fs.add(fmt::format("elastic fit, strain {:.3g} - {:.3g}: slope {:.4g} MPa (R^2 {:.3f})", fit.from, fit.to, fit.slope, fit.r2),
           {fit.from, fit.to}, {fit.intercept + fit.slope * fit.from, fit.intercept + fit.slope * fit.to}, dashed);
  }
  for (std::size_t k = 0; k < names.size(); ++k) {
    plot::SeriesStyle style;
    style.color = plot::paletteColor(static_cast<int>(k));
    style.dashed = k > stored;
    fe.add(names[k], strain, energy[k], style);
  }
  fc.add("in contact", strain, contacts);
  plot::SeriesStyle st;
  st.color = plot::paletteColor(1);
  fc.add(fmt::format("aligned (< {:.0f} deg)", scene_.tensile.alignedAngle * 180.0 / 3.14159265358979), strain, aligned, st);
  st.color = plot::paletteColor(2);
  st.dashed = true;
  fc.add("elements in the largest bundle", strain, largest, st);
  plot::Figure fo("In-plane orientation against strain");
  fo.x.label = "strain";
  fo.y.label = "order";
  fo.add("order parameter S = lambda1 - lambda2", strain, order);
  plot::SeriesStyle so;
  so.color = plot::paletteColor(1);
  fo.add(fmt::format("alignment with the {} axis, <cos 2 phi>", scene_.tensile.axis == 0 ? "x" : "y"), strain, alignment, so);
  plot::Image image = plot::aboveEachOther(fs.render(width, height, path), fe.render(width, height, path));
  image = plot::aboveEachOther(image, fc.render(width, height, path));
  image = plot::aboveEachOther(image, fo.render(width, height, path));
  if (bundles && bundles->end.elements > 0 && (bundles->start.bundles > 0 || bundles->end.bundles > 0)) {
    plot::Figure fb("Bundle sizes at the stage's start and end");
    fb.x.label = "bundle size (elements), classes [2^k, 2^(k+1)) at their centres";
    fb.x.scale = plot::Scale::Log10;
    fb.y.label = "fraction of all elements";
    const auto add = [&](const char* when, double strain, const BundleSizeDistribution& d, int colour) {
      std::vector<double> size, fraction;
      for (std::size_t c = 0; c < d.elementFractionInClass.size(); ++c)
        size.push_back(std::sqrt(2.0) * static_cast<double>(BundleSizeDistribution::classLower(c))),
            fraction.push_back(d.elementFractionInClass[c]);
      plot::SeriesStyle style;
      style.color = plot::paletteColor(colour);
      style.marker = plot::Marker::Circle;
      fb.add(fmt::format("{}, strain {:.3g}: {} bundles, largest {}", when, strain, d.bundles, d.largest), size, fraction, style);
    };
    if (bundles->start.bundles > 0) add("start", bundles->startStrain, bundles->start, 0);
    if (bundles->end.bundles > 0) add("end", bundles->endStrain, bundles->end, 1);
    image = plot::aboveEachOther(image, fb.render(width, height, path));
  }
  plot::writePng(path, image);
}

}  // namespace mesochain::mdem

namespace mesochain::mdem {

void TensileRecorder::saveState(BinaryWriter& out) const {
  out.write(lastPower_);
  out.write<std::uint64_t>(samples_.size());
  for (const TensileSample& s : samples_) {
    for (double v : {s.time, s.strain, s.stress, s.forceLeft, s.forceRight, s.gripWork}) out.write(v);
    out.write<std::int32_t>(s.contacts), out.write<std::int32_t>(s.aligned);
    out.write<std::int32_t>(s.bundles), out.write<std::int32_t>(s.largestBundle);
    out.write(s.meanBundle), out.write(s.orderParameter), out.write(s.axisAlignment);
    writeLedger(out, s.energies);
  }
}

void TensileRecorder::loadState(BinaryReader& in) {
  lastPower_ = in.read<double>();
  const std::uint64_t n = in.read<std::uint64_t>();
  samples_.clear();
  for (std::uint64_t k = 0; k < n; ++k) {
    TensileSample s;
    for (double* v : {&s.time, &s.strain, &s.stress, &s.forceLeft, &s.forceRight, &s.gripWork}) *v = in.read<double>();
    s.contacts = in.read<std::int32_t>(), s.aligned = in.read<std::int32_t>();
    s.bundles = in.read<std::int32_t>(), s.largestBundle = in.read<std::int32_t>();
    s.meanBundle = in.read<double>(), s.orderParameter = in.read<double>(), s.axisAlignment = in.read<double>();
    s.energies = readLedger(in);
    samples_.push_back(std::move(s));
  }
  if (!samples_.empty()) columns_ = energyColumns(samples_.front().energies);
}

}  // namespace mesochain::mdem
