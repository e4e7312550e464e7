#pragma once
// Uniaxial tensile test with grips ([tensile] in a scene; docs/scene-file.md).
//
// Grips: the elements whose centre lies within `grip_width_nm` of either edge of the specimen
// along the axis (the smallest and largest centre coordinates). Their axial translation is
// prescribed (FixedDofs with a velocity): the two grips move apart, each at
// v = strain_rate * L0 / 2, reached over a linear velocity ramp; the transverse translations and
// all rotations stay free. L0, the gauge length, is the free length between the grips: the
// smallest axial centre coordinate of the right grip minus the largest of the left grip.
//
// Per sample (every output.energies_every steps):
//   strain  (u_right - u_left) / L0, u the axial displacement of the grips;
//   stress  engineering, (F_left - F_right) / (2 A): F the axial sum of the forces the specimen
//           exerts on a grip's elements (unconstrained, without numerical damping), A the
//           cross-section: cross_section_nm2, or the [network] film's width normal to the axis
//           times (film thickness + 2 R_max), the outer extent of the tubes' walls;
//   the energies of the ledger (kinetic, each effect's; the total; the dissipated work), the
//           work of the grips W = \int sum_i R_i v_i dt (R_i = m_i a(t) - F_i the reaction on
//           grip element i; trapezoid rule between samples) and the work of the dashpots;
//   contacts: pairs with a wall gap below contact_gap_nm, and those crossing below
//           aligned_angle_deg (the aligned pairs).
// Energy balance: total(t) - total(0) = W - dissipated (dashpots; local damping when it tracks
// its work, [local_damping] track_work).
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "mdem/append_file.hpp"
#include "mdem/binary_io.hpp"
#include "mdem/contacts/bundle_sizes.hpp"
#include "mdem/scene.hpp"
#include "mdem/simulation.hpp"

namespace mesochain::mdem {

// Selects the grips, sets their kinematics (scene.boundary.fixed) and the gauge length. Throws
// InputError (naming the [tensile] keys) for empty or overlapping grips, elements already
// constrained, or no cross-section.
void setUpTensile(Scene& scene);

// The time from a tensile test's start until the grips' prescribed motion reaches `strain`
// (engineering, of the gauge length; t.strainRate > 0). Each grip's speed ramps linearly over
// t.ramp (the FixedDofs of setUpTensile), so the strain is rate t^2 / (2 ramp) during the ramp and
// rate (t - ramp / 2) after it. The measured strain (TensileRecorder) is the grips' mean
// displacement, i.e. this motion as the integrator takes it.
double tensileTimeToStrain(const TensileSpec& t, double strain);

struct TensileSample {
  double time = 0.0, strain = 0.0, stress = 0.0;  // ns, -, MPa
  double forceLeft = 0.0, forceRight = 0.0;       // pN, specimen on the grips (axial)
  double gripWork = 0.0;                          // zJ
  EnergyLedger energies;
  int contacts = 0, aligned = 0;
  // Bundles and orientation (contacts/network_structure.hpp; zero without contacts).
  int bundles = 0, largestBundle = 0;
  double meanBundle = 0.0, orderParameter = 0.0, axisAlignment = 0.0;
};

// Least-squares line stress = intercept + slope * strain over the samples with strain in
// [from, to]: the elastic slope (Young's modulus of the specimen, MPa) and how well a line fits.
// A slope is fitted only from at least kElasticMinimumSamples samples spanning at least half of
// [from, to]; otherwise (a stage that ended early, too few samples) there is no slope (fitted
// false, slope 0), and reports say so instead of printing a line through noise.
struct ElasticFit {
  bool fitted = false;
  int samples = 0;                 // in [from, to]
  double slope = 0.0;              // MPa
  double intercept = 0.0;          // MPa
  double r2 = 0.0;                 // coefficient of determination
  double from = 0.0, to = 0.0;     // strain range actually covered by the samples used
};
ElasticFit fitElasticSlope(const std::vector<TensileSample>& samples, double from, double to);
// The strain below which the reports fit the elastic slope (3 %).
inline constexpr double kElasticStrain = 0.03;
inline constexpr int kElasticMinimumSamples = 3;

// The bundle-size distributions (bundle_sizes.hpp) at a stage's start and end, with the
// criteria of the [tensile] contact counts.
struct TensileBundles {
  double contactGap = 0.0, alignedAngle = 0.0;  // nm, rad
  double startStrain = 0.0, endStrain = 0.0;
  BundleSizeDistribution start, end;
};

class TensileRecorder {
 public:
  // Opens the CSV (path) when not empty; resumeAt >= 0 appends to an interrupted run's CSV cut
  // back to that length (the samples before it come from the checkpoint, loadState).
  TensileRecorder(const Scene& scene, const std::string& csvPath, std::int64_t resumeAt = -1);
  // Samples the current state of `sim` (call at increasing times); `energies`: sim.energies(),
  // when the caller has them already.
  const TensileSample& record(const Simulation& sim) { return record(sim, sim.energies()); }
  const TensileSample& record(const Simulation& sim, const EnergyLedger& energies);
  const std::vector<TensileSample>& samples() const { return samples_; }
  // PNG: stress-strain, energies against strain, contact and aligned pair counts, orientation,
  // and the bundle-size distributions at the stage's start and end when given.
  // `runningNote`: as TimeSeriesPlot::write's (the first panel's title).
  void writePlot(const std::string& path, const TensileBundles* bundles = nullptr, const std::string& runningNote = "") const;
  // Checkpoints: the samples so far and the integration state of the grip work.
  void saveState(BinaryWriter& out) const;
  void loadState(BinaryReader& in);
  std::int64_t csvBytes() const { return csv_ ? csv_->bytes() : -1; }

 private:
  const Scene& scene_;
  double area_ = 0.0;
  std::unique_ptr<AppendFile> csv_;
  std::vector<std::string> columns_;  // energy columns (output.hpp, energyColumns), from the first sample
  std::vector<TensileSample> samples_;
  double lastPower_ = 0.0;
};

}  // namespace mesochain::mdem
