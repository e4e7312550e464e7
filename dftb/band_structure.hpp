#pragma once
// The band-structure term: non-orthogonal tight binding on an objective cell, with helical
// k-points, Fermi-Dirac filling at one Fermi level across all k-points, and the Mermin free
// energy  F_band = sum_k w_k sum_n f_nk e_nk - T S  (per cell).
//
// Registered as "band" (band_structure.cpp), built when SCC is off. evaluate() reports into the
// ledger "band" (sum f e, Energy), "entropy_term_ts" (TS, Entropy) and, with sampled angular
// momenta, "angular_sampling_error_estimate" (Reported); as extras: fermi_level, homo, lumo,
// electrons, kpoints, and timings (time_assembly, time_eigensolver, time_filling, time_density,
// time_density_products (its BLAS-3 part), time_forces, in seconds).
#include <memory>

#include "dftb/eigensolver.hpp"
#include "dftb/energy_term.hpp"
#include "dftb/parameters.hpp"
#include "objective/core/kgrid.hpp"
#include "parallel/communicator.hpp"

namespace mesochain::dftb {

struct BandSettings {
  int helicalKPoints = 1;                 // kappa points on the whole zone
  objective::AngularSampling angular;     // all mu, or sampled
  double electronicTemperature = 0.0;     // k_B T, Hartree (> 0)
  // How the eigenvectors for forces are computed; every path gives the same results to
  // rounding (tests/dftb/test_eigenvector_paths.cpp), Automatic picks the faster by size.
  EigenvectorPath eigenvectors = EigenvectorPath::Automatic;
};

// InputError (source "the calculator settings", the key) for an electronic temperature outside
// common/electronic_temperature.hpp's range (the k-grid checks its own counts).
void validate(const BandSettings& settings);

class BandStructureTerm : public EnergyTerm {
 public:
  // comm: the ranks that share the k-points of every evaluation (dftb/band_solver.hpp).
  BandStructureTerm(std::shared_ptr<const ParameterSet> params, BandSettings settings,
                    parallel::Communicator comm = parallel::Communicator::serial());
  std::string name() const override { return "band"; }
  void evaluate(const objective::ObjectiveCell& cell, const EvaluationRequest& request,
                TermOutput& out) const override;
  const BandSettings& settings() const { return settings_; }

 private:
  std::shared_ptr<const ParameterSet> params_;
  BandSettings settings_;
  parallel::Communicator comm_;
};

struct BandGeometry;
struct BandSolution;
// What every band term reports: ledger entries band, entropy_term_ts (and
// angular_sampling_error_estimate with sampled mu) and extras fermi_level, homo, lumo,
// electrons, kpoints, orbitals, image_pairs.
void reportBandSolution(const BandGeometry& geometry, const BandSolution& solution, double kT,
                        TermOutput& out);

}  // namespace mesochain::dftb
