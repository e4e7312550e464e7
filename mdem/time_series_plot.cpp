#include "mdem/time_series_plot.hpp"

#include <fmt/format.h>

#include "common/plot/canvas.hpp"
#include "common/plot/figure.hpp"
#include "common/plot/png_io.hpp"

namespace mesochain::mdem {

namespace {
constexpr const char* kEnergyNames[] = {"kinetic translational", "kinetic rotational", "stretching",
                                        "shearing", "twisting", "bending", "load potential",
                                        "van der Waals", "dissipated by dashpots", "total"};
constexpr int kEnergyKinds = 10;
constexpr const char* kProbeNames[] = {"ux", "uy", "uz", "rx", "ry", "rz"};
}  // namespace

void TimeSeriesPlot::record(double time, const Energies& e, const Bodies& b) {
  if (energies_.empty()) {
    energies_.resize(kEnergyKinds);
    probe_.resize(6 * probes_.size());
  }
  time_.push_back(time);
  const double values[kEnergyKinds] = {e.kineticTranslational, e.kineticRotational, e.bonds.stretching,
                                       e.bonds.shearing, e.bonds.twisting, e.bonds.bending,
                                       e.loadPotential, e.vdw, e.contactDissipated, e.total()};
  for (int k = 0; k < kEnergyKinds; ++k) energies_[k].push_back(values[k]);
  for (std::size_t p = 0; p < probes_.size(); ++p) {
    const int i = probes_[p];
    const Vec3 u = b.position[i] - b.initialPosition[i];
    const Vec3& r = b.accumulatedRotation[i];
    for (int c = 0; c < 3; ++c) {
      probe_[6 * p + c].push_back(u[c]);
      probe_[6 * p + 3 + c].push_back(r[c]);
    }
  }
}

void TimeSeriesPlot::write(const std::string& path) const {
  const int width = 900, height = 450;
  plot::Figure energies;
  energies.x.label = "time (ns)";
  energies.y.label = "energy (zJ)";
  std::vector<std::string> zero;
  for (int k = 0; k < kEnergyKinds && !energies_.empty(); ++k) {
    bool allZero = true;
    for (double v : energies_[k]) allZero = allZero && v == 0.0;
    if (allZero) {
      zero.push_back(kEnergyNames[k]);
      continue;
    }
    plot::SeriesStyle style;
    style.color = plot::paletteColor(k);
    style.dashed = k >= kEnergyKinds - 2;  // the dissipated work and the total
    energies.add(kEnergyNames[k], time_, energies_[k], style);
  }
  energies.title = zero.empty() ? "Energies" : fmt::format("Energies (zero throughout: {})", fmt::join(zero, ", "));
  plot::Image image = energies.render(width, height, path);
  if (!probes_.empty()) {
    plot::Figure moved("Probe displacements"), turned("Probe rotations (integral of omega dt)");
    moved.x.label = turned.x.label = "time (ns)";
    moved.y.label = "displacement (nm)";
    turned.y.label = "rotation (rad)";
    for (std::size_t p = 0; p < probes_.size(); ++p)
      for (int c = 0; c < 6; ++c) {
        plot::SeriesStyle style;
        style.color = plot::paletteColor(static_cast<int>(3 * p) + c % 3);
        style.dashed = p % 2 == 1;
        (c < 3 ? moved : turned)
            .add(fmt::format("element {} {}", probes_[p], kProbeNames[c]), time_, probe_[6 * p + c], style);
      }
    image = plot::aboveEachOther(image, moved.render(width, height, path));
    image = plot::aboveEachOther(image, turned.render(width, height, path));
  }
  plot::writePng(path, image);
}

}  // namespace mesochain::mdem
