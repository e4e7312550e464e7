#include "mdem/compression.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/plot/canvas.hpp"
#include "common/plot/figure.hpp"
#include "common/plot/png_io.hpp"
#include "mdem/contacts/tube_potential.hpp"
#include "mdem/output.hpp"
#include "mdem/wall_effect.hpp"

namespace mesochain::mdem {

const char* phaseName(PlatePhase p) {
  switch (p) {
    case PlatePhase::Closing: return "closing";
    case PlatePhase::Opening: return "opening";
    case PlatePhase::Holding: return "holding";
    case PlatePhase::Done: return "done";
  }
  return "?";
}

double cycleDuration(const CompressionSpec& c) { return 2.0 * c.maxStrain / c.strainRate + c.holdTime; }

PlateState plateStateAt(const CompressionSpec& c, double t) {
  PlateState p;
  const double tau = std::max(0.0, t - c.startTime), half = c.maxStrain / c.strainRate, period = cycleDuration(c);
  const double cycle = std::floor(tau / period);
  if (cycle >= c.cycles) {
    p.cycle = c.cycles, p.phase = PlatePhase::Done;
  } else {
    p.cycle = static_cast<int>(cycle);
    const double s = tau - cycle * period;
    if (s < half) p.phase = PlatePhase::Closing, p.strain = c.strainRate * s;
    else if (s < 2.0 * half) p.phase = PlatePhase::Opening, p.strain = c.strainRate * (2.0 * half - s);
    else p.phase = PlatePhase::Holding;
  }
  const double h0 = c.top0 - c.bottom0;
  p.bottom = c.bottom0 + 0.5 * h0 * p.strain, p.top = c.top0 - 0.5 * h0 * p.strain;
  return p;
}

double parallelTubeCurvature(const LennardJones& lj, double radius) {
  // The minimum of Phi(d) by bisection on Phi' (negative inside the well, positive at contact),
  // then Phi'' by a central difference of Phi'.
  auto slope = [&](double d) {
    double der;
    parallelTubeEnergyPerLength(lj, radius, radius, d, &der);
    return der;
  };
  double lo = 2.0 * radius + 0.5 * lj.sigma, hi = 2.0 * radius + 2.0 * lj.sigma;
  for (int k = 0; k < 60; ++k) {
    const double m = 0.5 * (lo + hi);
    (slope(m) < 0.0 ? lo : hi) = m;
  }
  const double d = 0.5 * (lo + hi), delta = 1e-4;
  return (slope(d + delta) - slope(d - delta)) / (2.0 * delta);
}

void setUpCompression(Scene& s, double startTime, const std::string& key) {
  CompressionSpec& c = s.compression;
  if (!c.enabled) return;
  if (s.periodic.periodic[2])
    throw InputError(s.source, "key periodic.length_nm", "a film periodic along z", "no periodicity along z with plates normal to z");
  const Bodies& b = s.bodies;
  std::vector<char> used(s.elementTypes.size(), 0);
  for (int i = 0; i < b.size(); ++i) used[b.type[i]] = 1;
  if (!(c.stiffness > 0.0)) {
    for (std::size_t t = 0; t < used.size(); ++t) {
      if (!used[t]) continue;
      const ElementType& et = s.elementTypes[t];
      if (et.shape != Shape::Cylinder)
        throw InputError(s.source, key + ".wall_stiffness_pN_per_nm2", "nothing, with brick elements (" + et.name + ")",
                         "the plates' stiffness per unit length (the default is the tube-tube contact's, for tubes)");
      if (!(s.contacts.vdw.lj.epsilon > 0.0))
        throw InputError(s.source, key + ".wall_stiffness_pN_per_nm2", "nothing, and no [vdw_contact] parameters",
                         "the plates' stiffness per unit length, or [vdw_contact] for the default (the tube-tube contact's)");
      c.stiffness = std::max(c.stiffness, parallelTubeCurvature(s.contacts.vdw.lj, et.radius));
    }
  }
  if (!(c.area > 0.0)) {
    if (s.filmSize.isZero())
      throw InputError(s.source, key + ".area_nm2", "nothing (and no [network] film)", "the plate area in nm^2 for the pressure");
    c.area = s.filmSize.x() * s.filmSize.y();
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int i = 0; i < b.size(); ++i) {
    const ElementType& t = s.elementTypes[b.type[i]];
    const double reach = 0.5 * t.length * std::abs(rotate(b.orientation[i], Vec3::UnitZ()).z()) + t.contactRadius();
    lo = std::min(lo, b.position[i].z() - reach), hi = std::max(hi, b.position[i].z() + reach);
  }
  c.bottom0 = lo - c.wallGap, c.top0 = hi + c.wallGap;
  if (c.plateSpeed > 0.0) c.strainRate = 2.0 * c.plateSpeed / (c.top0 - c.bottom0);
  c.startTime = startTime;
}

double filmThickness(const Scene& scene, const Bodies& b) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, r = 0.0;
  for (int i = 0; i < b.size(); ++i) {
    lo = std::min(lo, b.position[i].z()), hi = std::max(hi, b.position[i].z());
    r = std::max(r, scene.elementTypes[b.type[i]].contactRadius());
  }
  return hi - lo + 2.0 * r;
}

CompressionRecorder::CompressionRecorder(const Scene& scene, const std::string& csvPath, const std::string& cyclesPath,
                                         std::int64_t resumeAt, std::int64_t cyclesResumeAt)
    : scene_(scene), area_(scene.compression.area) {
  // The true mass (the bodies carry the scaled one under mass_scale): densities are physical.
  for (int t : scene.bodies.type) mass_ += scene.elementTypes[t].mass;
  if (!csvPath.empty()) csv_ = std::make_unique<AppendFile>(csvPath, resumeAt);
  if (!cyclesPath.empty()) {
    cyclesCsv_ = std::make_unique<AppendFile>(cyclesPath, cyclesResumeAt);
    if (cyclesCsv_->bytes() == 0)
      cyclesCsv_->write("cycle,time_ns,thickness_nm,density_g_per_cm3,smallest_thickness_nm,peak_pressure_MPa\n");
  }
}

const CompressionSample& CompressionRecorder::record(const Simulation& sim, const EnergyLedger& energies) {
  const CompressionSpec& c = scene_.compression;
  CompressionSample s;
  s.time = sim.time();
  const PlateState p = plateStateAt(c, s.time);
  s.cycle = p.cycle, s.phase = p.phase, s.strain = p.strain, s.gap = p.top - p.bottom;
  s.thickness = filmThickness(scene_, sim.bodies());
  const auto* walls = dynamic_cast<const WallEffect*>(sim.effect("walls"));
  if (walls) s.loadBottom = walls->bottomLoad(), s.loadTop = walls->topLoad();
  s.pressure = 0.5 * (s.loadBottom + s.loadTop) / area_;
  if (samples_.empty() && walls) workAtStart_ = walls->plateWork();
  s.plateWork = walls ? walls->plateWork() - workAtStart_ : 0.0;
  s.energies = energies;
  // A cycle is complete at the first sample of a later cycle (or of the end).
  if (samples_.empty()) smallest_ = s.thickness, peak_ = s.pressure;
  const int completed = static_cast<int>(cycles_.size());
  if (p.cycle > completed) {
    CycleRecord r;
    r.cycle = completed + 1, r.time = s.time, r.thickness = s.thickness;
    // 1 ag/nm^3 = 1e-18 g / 1e-21 cm^3 = 1e3 g/cm^3 (as film_statistics.cpp)
    r.density = mass_ / (area_ * s.thickness) * 1e3;
    r.smallestThickness = smallest_, r.peakPressure = peak_;
    cycles_.push_back(r);
    if (cyclesCsv_)
      cyclesCsv_->write(fmt::format("{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}\n", r.cycle, r.time, r.thickness, r.density,
                                    r.smallestThickness, r.peakPressure));
    smallest_ = s.thickness, peak_ = s.pressure;
  }
  smallest_ = std::min(smallest_, s.thickness), peak_ = std::max(peak_, s.pressure);
  done_ = p.phase == PlatePhase::Done;
  samples_.push_back(s);
  if (csv_) {
    if (columns_.empty()) columns_ = energyColumns(s.energies);
    std::string row;
    if (csv_->bytes() == 0) {
      row = "time_ns,cycle,phase,strain,plate_gap_nm,film_thickness_nm,load_bottom_pN,load_top_pN,pressure_MPa,plate_work_zJ";
      for (const std::string& col : columns_) row += "," + (col.empty() ? std::string("total") : col) + "_zJ";
      row += "\n";
    }
    row += fmt::format("{:.10g},{},{},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g}", s.time, s.cycle + 1,
                       phaseName(s.phase), s.strain, s.gap, s.thickness, s.loadBottom, s.loadTop, s.pressure, s.plateWork);
    for (const std::string& col : columns_) row += fmt::format(",{:.10g}", col.empty() ? s.energies.total() : s.energies[col]);
    csv_->write(row + "\n");
  }
  return samples_.back();
}

void CompressionRecorder::writePlot(const std::string& path, const std::string& runningNote) const {
  const int width = 900, height = 420;
  plot::Figure fp("Plate pressure against strain, per cycle"), ft("Thickness against time"), fd("Density after each cycle");
  if (!runningNote.empty()) fp.title += " - " + runningNote;
  fp.x.label = "nominal compressive strain of the plate gap";
  fp.y.label = "pressure (MPa)";
  ft.x.label = "time (ns)";
  ft.y.label = "nm";
  fd.x.label = "cycle";
  fd.y.label = "density (g/cm^3)";
  const int n = scene_.compression.cycles;
  std::vector<std::vector<double>> strain(n), pressure(n);
  std::vector<double> time, gap, thickness;
  for (const CompressionSample& s : samples_) {
    if (s.cycle < n) strain[s.cycle].push_back(s.strain), pressure[s.cycle].push_back(s.pressure);
    time.push_back(s.time), gap.push_back(s.gap), thickness.push_back(s.thickness);
  }
  for (int k = 0; k < n; ++k)
    if (!strain[k].empty()) {
      plot::SeriesStyle st;
      st.color = plot::paletteColor(k);
      fp.add(fmt::format("cycle {}", k + 1), strain[k], pressure[k], st);
    }
  ft.add("plate gap", time, gap);
  plot::SeriesStyle dashed;
  dashed.color = plot::paletteColor(1);
  ft.add("film thickness (centre span + 2R)", time, thickness, dashed);
  std::vector<double> cycle, density;
  for (const CycleRecord& r : cycles_) cycle.push_back(r.cycle), density.push_back(r.density);
  if (!samples_.empty()) cycle.insert(cycle.begin(), 0.0), density.insert(density.begin(), mass_ / (area_ * samples_.front().thickness) * 1e3);
  plot::SeriesStyle marks;
  marks.marker = plot::Marker::Circle;
  fd.add("density (0: before the first cycle)", cycle, density, marks);
  plot::Image image = plot::aboveEachOther(fp.render(width, height, path), ft.render(width, height, path));
  image = plot::aboveEachOther(image, fd.render(width, height, path));
  plot::writePng(path, image);
}

void CompressionRecorder::saveState(BinaryWriter& out) const {
  out.write(workAtStart_), out.write(smallest_), out.write(peak_), out.write<char>(done_ ? 1 : 0);
  out.write<std::uint64_t>(samples_.size());
  for (const CompressionSample& s : samples_) {
    for (double v : {s.time, s.strain, s.gap, s.thickness, s.loadBottom, s.loadTop, s.pressure, s.plateWork}) out.write(v);
    out.write<std::int32_t>(s.cycle), out.write<std::int32_t>(static_cast<std::int32_t>(s.phase));
    writeLedger(out, s.energies);
  }
  out.write<std::uint64_t>(cycles_.size());
  for (const CycleRecord& r : cycles_) {
    out.write<std::int32_t>(r.cycle);
    for (double v : {r.time, r.thickness, r.density, r.smallestThickness, r.peakPressure}) out.write(v);
  }
}

void CompressionRecorder::loadState(BinaryReader& in) {
  workAtStart_ = in.read<double>(), smallest_ = in.read<double>(), peak_ = in.read<double>(), done_ = in.read<char>() != 0;
  const std::uint64_t n = in.read<std::uint64_t>();
  samples_.clear();
  for (std::uint64_t k = 0; k < n; ++k) {
    CompressionSample s;
    for (double* v : {&s.time, &s.strain, &s.gap, &s.thickness, &s.loadBottom, &s.loadTop, &s.pressure, &s.plateWork})
      *v = in.read<double>();
    s.cycle = in.read<std::int32_t>();
    const int phase = in.read<std::int32_t>();
    if (phase < 0 || phase > 3) in.fail("a compression sample of unknown phase");
    s.phase = static_cast<PlatePhase>(phase);
    s.energies = readLedger(in);
    samples_.push_back(std::move(s));
  }
  const std::uint64_t m = in.read<std::uint64_t>();
  cycles_.clear();
  for (std::uint64_t k = 0; k < m; ++k) {
    CycleRecord r;
    r.cycle = in.read<std::int32_t>();
    for (double* v : {&r.time, &r.thickness, &r.density, &r.smallestThickness, &r.peakPressure}) *v = in.read<double>();
    cycles_.push_back(r);
  }
  if (!samples_.empty()) columns_ = energyColumns(samples_.front().energies);
}

}  // namespace mesochain::mdem
