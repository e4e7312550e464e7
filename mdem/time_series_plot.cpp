#include "mdem/time_series_plot.hpp"

#include <fmt/format.h>

#include "common/plot/canvas.hpp"
#include "common/plot/figure.hpp"
#include "common/plot/png_io.hpp"
#include "mdem/output.hpp"

namespace mesochain::mdem {

namespace {
constexpr const char* kProbeNames[] = {"ux", "uy", "uz", "rx", "ry", "rz"};
// Legend name of a ledger entry ("" = the total).
std::string legendName(const std::string& entry) {
  if (entry.empty()) return "total";
  if (entry == "vdw") return "van der Waals";
  if (entry == "contact_dissipated") return "dissipated by dashpots";
  std::string n = entry;
  for (char& c : n)
    if (c == '_') c = ' ';
  return n;
}
}  // namespace

void TimeSeriesPlot::record(double time, const EnergyLedger& e, const Bodies& b) {
  if (energies_.empty()) {
    columns_ = energyColumns(e);
    energies_.resize(columns_.size());
    probe_.resize(6 * probes_.size());
  }
  time_.push_back(time);
  for (std::size_t k = 0; k < columns_.size(); ++k) energies_[k].push_back(columns_[k].empty() ? e.total() : e[columns_[k]]);
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

void TimeSeriesPlot::write(const std::string& path, const std::string& runningNote) const {
  // 1000 px: wide enough that a legend of the ten-odd energy entries can go beside the plot when
  // every inner corner would hide curves (plot::Figure keeps the plot at least half the width).
  const int width = 1000, height = 450;
  plot::Figure energies;
  energies.x.label = "time (ns)";
  energies.y.label = "energy (zJ)";
  std::vector<std::string> zero;
  bool afterTotal = false;
  for (std::size_t k = 0; k < columns_.size(); ++k) {
    afterTotal = afterTotal || columns_[k].empty();
    bool allZero = true;
    for (double v : energies_[k]) allZero = allZero && v == 0.0;
    if (allZero) {
      zero.push_back(legendName(columns_[k]));
      continue;
    }
    plot::SeriesStyle style;
    style.color = plot::paletteColor(static_cast<int>(k));
    style.dashed = afterTotal;  // the total and the dissipated work
    energies.add(legendName(columns_[k]), time_, energies_[k], style);
  }
  energies.title = zero.empty() ? "Energies" : fmt::format("Energies (zero throughout: {})", fmt::join(zero, ", "));
  if (!runningNote.empty()) energies.title += " - " + runningNote;
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

namespace mesochain::mdem {

void TimeSeriesPlot::saveState(BinaryWriter& out) const {
  out.writeVector(columns_);
  out.writeVector(time_);
  out.write<std::uint64_t>(energies_.size());
  for (const auto& v : energies_) out.writeVector(v);
  out.write<std::uint64_t>(probe_.size());
  for (const auto& v : probe_) out.writeVector(v);
}

void TimeSeriesPlot::loadState(BinaryReader& in) {
  columns_ = in.readVector<std::string>("plot columns");
  time_ = in.readVector<double>("plot times");
  energies_.resize(in.read<std::uint64_t>());
  if (energies_.size() != columns_.size()) in.fail("plot series that do not match their columns");
  for (auto& v : energies_) v = in.readVector<double>("plot energies");
  in.expectCount("plot probes", 6 * probes_.size());
  probe_.resize(6 * probes_.size());
  for (auto& v : probe_) v = in.readVector<double>("plot probes");
}

}  // namespace mesochain::mdem
