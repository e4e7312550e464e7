#pragma once
// The band-structure term: non-orthogonal tight binding on an objective cell, with helical
// k-points, Fermi-Dirac filling at one Fermi level across all k-points, and the Mermin free
// energy  F_band = sum_k w_k sum_n f_nk e_nk - T S  (per cell).
//
// evaluate() reports as `energy` the band free energy (the quantity whose gradient is exact),
// and as extras: band_energy, entropy_term (TS), fermi_level, homo, lumo, electrons,
// kpoints, and timings (time_assembly, time_eigensolver, time_filling, time_density,
// time_forces, in seconds).
#include <memory>

#include "dftb/eigensolver.hpp"
#include "dftb/energy_term.hpp"
#include "dftb/parameters.hpp"
#include "objective/core/kgrid.hpp"

namespace mesochain::dftb {

struct BandSettings {
  int helicalKPoints = 1;                 // kappa points on the whole zone
  objective::AngularSampling angular;     // all mu, or sampled
  double electronicTemperature = 0.0;     // k_B T, Hartree (> 0)
  // How the eigenvectors for forces are computed; every path gives the same results to
  // rounding (tests/dftb/test_eigenvector_paths.cpp), Automatic picks the faster by size.
  EigenvectorPath eigenvectors = EigenvectorPath::Automatic;
};

class BandStructureTerm : public EnergyTerm {
 public:
  BandStructureTerm(std::shared_ptr<const ParameterSet> params, BandSettings settings);
  std::string name() const override { return "band"; }
  void evaluate(const objective::ObjectiveCell& cell, const EvaluationRequest& request,
                TermOutput& out) const override;
  const BandSettings& settings() const { return settings_; }

 private:
  std::shared_ptr<const ParameterSet> params_;
  BandSettings settings_;
};

struct BandGeometry;
struct BandSolution;
// The extras every band term reports (band_energy, entropy_term, fermi_level, homo, lumo,
// electrons, kpoints, orbitals, image_pairs, angular_sampling_error_estimate).
void reportBandSolution(const BandGeometry& geometry, const BandSolution& solution, double kT,
                        TermOutput& out);

}  // namespace mesochain::dftb
