#pragma once
// Self-consistent-charge DFTB (DFTB2; Elstner et al., Phys. Rev. B 58, 7260 (1998)) on an
// objective cell: the band-structure term driven to self-consistency of the Mulliken
// populations (dftb/mulliken.hpp) by the charge interactions the calculator built
// (dftb/charge_interaction.hpp; for DFTB2 the gamma interaction, dftb/gamma_interaction.hpp):
//   H_mu nu(g) = H0_mu nu(g) + 1/2 S_mu nu(g) (V_i + V_j),   V_i = sum_j gamma~_ij dq_j,
// with gamma~ the sum of the interactions' kernels and dq_i = q_i - q0_i (electrons relative to
// the neutral atom).
//
// Energy per cell (DFTB+ convention; the double counting of the shift is removed):
//   F = [sum_k w_k sum_n f e - sum_i V_in,i q_i] - TS + 1/2 sum_ij dq_i gamma~_ij dq_j,
// the bracket being Tr(rho H0) of the output density. The "band" registration
// (band_structure.cpp) builds this term instead of the plain one when the calculator has charge
// interactions. evaluate() reports into the ledger "band" (sum f e
// with the shifted H), "entropy_term_ts", "scc" (F - band + TS: the double counting
// -sum_i V_i q_i plus the Coulomb energy), and, Reported beside them, "h0" (Tr(rho H0)) and
// "scc_coulomb" (1/2 dq gamma~ dq); extras scc_iterations, scc_converged, and series
// mulliken_populations / mulliken_charges (q0 - q, elementary charges) and the iteration
// history (scc_history_energy, scc_history_residual).
//
// Gradient (at self-consistency): P:dH0 - W:dS + 1/2 (V_i + V_j) P:dS + 1/2 dq (dgamma~) dq,
// the middle terms through contractDerivatives with W' = W - 1/2 (V_i + V_j) P, the last from
// each interaction's derivatives at w = dq dq^T.
//
// Warm start (SccSettings::warmStart): the loop starts from the charges in the ChargeCache
// (dftb/charge_cache.hpp) when they belong to a cell with the same atoms, else from neutral
// atoms, and stores its converged charges there (extras scc_warm_start = 1 or 0).
//
// A loop that does not converge within max_iterations, or stagnates above the tolerance, throws
// NumericalError with the history (or, when `stopIfUnconverged` is false, returns the last
// iterate flagged scc_converged = 0 with the history).
#include <memory>
#include <string>
#include <vector>

#include "dftb/band_structure.hpp"
#include "dftb/charge_cache.hpp"
#include "dftb/charge_interaction.hpp"
#include "dftb/energy_term.hpp"
#include "dftb/parameters.hpp"
#include "parallel/communicator.hpp"

namespace mesochain::dftb {

struct SccSettings {
  bool enabled = false;
  double chargeTolerance = 1e-8;   // max_i |q_out,i - q_in,i|, electrons
  double energyTolerance = 1e-8;   // |F_m - F_{m-1}|, Hartree per cell
  int maxIterations = 100;
  std::string mixer = "broyden";   // or "simple"
  double mixing = 0.2;
  double ewaldTolerance = 1e-10;   // long-range 1/r sum and short-range image cutoff
  bool stopIfUnconverged = true;   // false: return the last iterate, flagged
  bool warmStart = true;           // start from the cached charges of the last converged loop
};

// InputError (source "the calculator settings", key scc.*) for tolerances below what double
// precision resolves, a non-positive iteration count, an Ewald tolerance outside
// [1e-13, 1e-2], or an unknown mixer / mixing.
void validate(const SccSettings& settings);

class SccBandStructureTerm : public EnergyTerm {
 public:
  // interactions: at least one; cache: where converged charges are kept between evaluations
  // (may be null: no warm start).
  SccBandStructureTerm(std::shared_ptr<const ParameterSet> params, BandSettings band,
                       SccSettings scc,
                       std::vector<std::shared_ptr<const ChargeInteraction>> interactions,
                       std::shared_ptr<ChargeCache> cache = nullptr,
                       parallel::Communicator comm = parallel::Communicator::serial());
  std::string name() const override { return "band"; }
  void evaluate(const objective::ObjectiveCell& cell, const EvaluationRequest& request,
                TermOutput& out) const override;

  // gamma~ of the cell: the interactions' kernels summed (N_o x N_o, Hartree per electron^2).
  Eigen::MatrixXd gammaMatrix(const objective::ObjectiveCell& cell) const;

 private:
  std::shared_ptr<const ParameterSet> params_;
  BandSettings band_;
  SccSettings scc_;
  std::vector<std::shared_ptr<const ChargeInteraction>> interactions_;
  std::shared_ptr<ChargeCache> cache_;
  parallel::Communicator comm_;  // the ranks that share the k-points (dftb/band_solver.hpp)
};

}  // namespace mesochain::dftb
