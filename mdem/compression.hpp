#pragma once
// Compression cycles of a film between two rigid plates normal to z ([stages.compression],
// docs/scene-file.md): e.g. six compress-recover cycles to 60 % that precondition a buckypaper.
//
// Plates: at the stage's start the bottom plate is placed at the rest gap g_w below the lowest
// point of any element's wall (z_b0 = min_i (z_i - L/2 |t_z,i| - R_i) - g_w) and the top plate
// as far above the highest one, so no element feels a plate at zero strain; H0 = z_t0 - z_b0.
// Protocol (nominal strain eps = (H0 - H) / H0 of the plate gap H): each cycle the plates close
// symmetrically at the strain rate r to eps_max (time eps_max / r), open again at the same rate
// to eps = 0 and rest there for hold_ns; after `cycles` cycles the stage ends. Each plate moves by
// H0 eps / 2, so z_b = z_b0 + H0 eps / 2, z_t = z_t0 - H0 eps / 2.
//
// Samples (every energies_every steps): time, cycle, phase, eps, H, the film thickness (the
// film report's: span of the element centres + 2 R_max, film_statistics.hpp), the film's loads
// on the plates N_b, N_t (pN) and the pressure P = (N_b + N_t) / (2 A) (MPa, A the plate area:
// area_nm2 or the [network] film's x * y), the plates' work and the energies. Per cycle (first
// sample after the cycle's hold has ended): the thickness and density m / (A t) then, the
// smallest thickness and largest pressure of the cycle.
#include <memory>
#include <string>
#include <vector>

#include "mdem/append_file.hpp"
#include "mdem/binary_io.hpp"
#include "mdem/scene.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::mdem {

enum class PlatePhase { Closing = 0, Opening = 1, Holding = 2, Done = 3 };
const char* phaseName(PlatePhase p);

struct PlateState {
  int cycle = 0;      // 0-based; == cycles once the protocol is done
  PlatePhase phase = PlatePhase::Closing;
  double strain = 0.0;
  double bottom = 0.0, top = 0.0;  // nm, plate planes
};
// The protocol at absolute time t (before the stage's start: its initial state).
PlateState plateStateAt(const CompressionSpec& c, double t);
double cycleDuration(const CompressionSpec& c);  // ns

// Default stiffness (when c.stiffness == 0): the largest Phi''(d_eq) over the element types
// present, of two parallel tubes of that kind (tube_potential.hpp). Places the plates from the
// positions and sets c.startTime. InputError (naming the keys) when the film has periodic z,
// bricks without wall_stiffness_pN_per_nm2, no vdW parameters for the default, or no plate area;
// `key` is the table's key in messages. The scene reader calls it once on the scene's initial
// state to find such errors before the run.
void setUpCompression(Scene& scene, double startTime, const std::string& key = "key stages.compression");
// Phi''(d) at the minimum of the parallel-tube energy per length (pN/nm^2).
double parallelTubeCurvature(const LennardJones& lj, double radius);

struct CompressionSample {
  double time = 0.0, strain = 0.0, gap = 0.0, thickness = 0.0;
  int cycle = 0;
  PlatePhase phase = PlatePhase::Closing;
  double loadBottom = 0.0, loadTop = 0.0, pressure = 0.0, plateWork = 0.0;  // pN, pN, MPa, zJ
  EnergyLedger energies;
};

struct CycleRecord {
  int cycle = 0;                    // 1-based
  double time = 0.0;                // ns, of the sample that closed it
  double thickness = 0.0;           // nm, after the cycle
  double density = 0.0;             // g/cm^3, m / (A thickness)
  double smallestThickness = 0.0;   // nm, during the cycle
  double peakPressure = 0.0;        // MPa
};

// The film's thickness as the film report measures it (centre span + 2 R_max).
double filmThickness(const Scene& scene, const Bodies& bodies);

class CompressionRecorder {
 public:
  // Opens the two CSVs (paths, "" = none); resumeAt >= 0: cut back to those lengths (the state
  // follows from loadState).
  CompressionRecorder(const Scene& scene, const std::string& csvPath, const std::string& cyclesPath,
                      std::int64_t resumeAt = -1, std::int64_t cyclesResumeAt = -1);
  const CompressionSample& record(const Simulation& sim, const EnergyLedger& energies);
  bool done() const { return done_; }
  const std::vector<CompressionSample>& samples() const { return samples_; }
  const std::vector<CycleRecord>& cycles() const { return cycles_; }
  // `runningNote`: as TimeSeriesPlot::write's (the first panel's title).
  void writePlot(const std::string& path, const std::string& runningNote = "") const;
  void saveState(BinaryWriter& out) const;
  void loadState(BinaryReader& in);
  std::int64_t csvBytes() const { return csv_ ? csv_->bytes() : -1; }
  std::int64_t cyclesBytes() const { return cyclesCsv_ ? cyclesCsv_->bytes() : -1; }

 private:
  const Scene& scene_;
  double area_ = 0.0, mass_ = 0.0;
  std::unique_ptr<AppendFile> csv_, cyclesCsv_;
  std::vector<std::string> columns_;
  std::vector<CompressionSample> samples_;
  std::vector<CycleRecord> cycles_;
  double workAtStart_ = 0.0;
  double smallest_ = 0.0, peak_ = 0.0;  // of the running cycle
  bool done_ = false;
};

}  // namespace mesochain::mdem
