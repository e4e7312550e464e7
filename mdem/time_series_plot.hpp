#pragma once
// PNG plots of a run's time series ([output] plot_png): the energies (every ledger entry of the
// run: kinetic, each effect's stored energies, work dissipated; the total; zJ) and, when probes
// are given,
// their displacements (nm) and accumulated rotations (rad), one panel each, against time (ns).
#include <string>
#include <vector>

#include "mdem/binary_io.hpp"
#include "mdem/body.hpp"
#include "mdem/effect.hpp"

namespace mesochain::mdem {

class TimeSeriesPlot {
 public:
  explicit TimeSeriesPlot(std::vector<int> probes) : probes_(std::move(probes)) {}

  void record(double time, const EnergyLedger& e, const Bodies& b);
  std::size_t samples() const { return time_.size(); }

  // Energy series that stay exactly zero are left out and named in the panel title; non-finite
  // samples (a run that blew up) are skipped and counted in the legend.
  // `runningNote` (non-empty while the run goes on: mdem/run.cpp's plots at checkpoints) is added to
  // the first panel's title, so that a plot of a run still going is not taken for its result.
  void write(const std::string& path, const std::string& runningNote = "") const;
  // Checkpoints: every sample so far.
  void saveState(BinaryWriter& out) const;
  void loadState(BinaryReader& in);

 private:
  std::vector<int> probes_;
  std::vector<double> time_;
  std::vector<std::string> columns_;           // energyColumns() of the first sample
  std::vector<std::vector<double>> energies_;  // one vector per column
  std::vector<std::vector<double>> probe_;     // per probe 6 vectors: ux uy uz rx ry rz
};

}  // namespace mesochain::mdem
