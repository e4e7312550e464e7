#pragma once
// dftb::Calculator: the energy terms a cell's settings ask for, evaluated on an objective cell.
// Terms register themselves (dftb/term_registry.hpp); the calculator builds, in registration
// order, every term whose wanted() holds for its settings (band structure and repulsive always,
// dispersion when enabled, the SCC charge interaction that makes the band term self-consistent
// when enabled), and sums what
// they report: energies into one ledger (dftb/energy_ledger.hpp), gradients and strain
// derivatives into one total. A term that is not asked for has no object and costs nothing.
// With SCC, the calculator keeps the last converged charges (ChargeCache) to warm-start the next
// evaluation of the same atoms.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "dftb/band_structure.hpp"
#include "dftb/dispersion_kc.hpp"
#include "dftb/dispersion_term.hpp"
#include "dftb/energy_ledger.hpp"
#include "dftb/energy_term.hpp"
#include "dftb/parameters.hpp"
#include "dftb/scc_term.hpp"
#include "parallel/communicator.hpp"

namespace mesochain::dftb {

// The settings of every term, each declared (with its defaults, units and validation) in its
// term's header.
struct CalculatorSettings {
  BandSettings band;              // dftb/band_structure.hpp
  DispersionSettings dispersion;  // dftb/dispersion_term.hpp
  KolmogorovCrespiSettings kc;    // dftb/dispersion_kc.hpp (instead of `dispersion`)
  SccSettings scc;  // dftb/scc_term.hpp; enabled: the band term is self-consistent
};

struct Result {
  // Energies per cell (Hartree) as the terms reported them: band, entropy_term_ts, repulsive,
  // dispersion, scc, ... (see each term's header).
  EnergyLedger energies;
  // From the ledger:
  double totalEnergy = 0.0;      // energies.total(): the sum of the Energy entries
  double freeEnergy = 0.0;       // total - TS (Mermin); forces are its negative gradient
  double extrapolatedEnergy = 0.0;  // total - TS/2, the T -> 0 estimate
  Eigen::Matrix3Xd gradient;     // dF/dx, Hartree/Bohr (empty unless requested)
  double dFdTranslation = 0.0;   // Hartree/Bohr
  double dFdTwist = 0.0;         // Hartree/rad
  std::map<std::string, double> extras;  // fermi_level, homo, lumo, timings, ...
  std::map<std::string, std::vector<double>> series;  // mulliken_charges, SCC history, ...
  int atoms = 0;
};

class Calculator {
 public:
  // comm: the ranks that share every evaluation (the k-points and angular points of the band
  // term; dftb/band_solver.hpp); evaluate() is then collective over them and returns the same
  // result on every rank. The default, all ranks of the run, is one rank without MPI.
  Calculator(std::shared_ptr<const ParameterSet> params, CalculatorSettings settings,
             parallel::Communicator comm = parallel::Communicator::world());
  Result evaluate(const objective::ObjectiveCell& cell, const EvaluationRequest& request) const;
  const CalculatorSettings& settings() const { return settings_; }
  const ParameterSet& parameters() const { return *params_; }
  const parallel::Communicator& communicator() const { return comm_; }
  // The registrations built (energy terms and charge interactions), in registration order.
  const std::vector<std::string>& termNames() const { return names_; }
  // Converged SCC charges kept between evaluations for the warm start (SccSettings::warmStart);
  // clear() it to make the next evaluation start from neutral atoms.
  ChargeCache& chargeCache() const { return *chargeCache_; }

 private:
  std::shared_ptr<const ParameterSet> params_;
  CalculatorSettings settings_;
  parallel::Communicator comm_;
  std::vector<std::unique_ptr<EnergyTerm>> terms_;
  std::vector<std::string> names_;
  std::shared_ptr<ChargeCache> chargeCache_ = std::make_shared<ChargeCache>();
};

}  // namespace mesochain::dftb
