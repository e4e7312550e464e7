#pragma once
// dftb::Calculator: the list of energy terms a cell asks for (band structure and repulsive
// always; Lennard-Jones dispersion only when named), evaluated on an objective cell.
// A term that is not asked for has no object and costs nothing. With SCC, the calculator keeps
// the last converged charges (ChargeCache) to warm-start the next evaluation of the same atoms.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "dftb/band_structure.hpp"
#include "dftb/energy_term.hpp"
#include "dftb/parameters.hpp"
#include "dftb/scc_term.hpp"

namespace mesochain::dftb {

struct DispersionSettings {
  bool enabled = false;
  double epsilon = 0.0;  // Hartree
  double r0 = 0.0;       // Bohr, position of the pair minimum
  double cutoff = 0.0;   // Bohr
  // r^-6 tail: false = cut off at `cutoff`; true = helical Ewald sum to `ewaldTolerance`
  // (dftb/dispersion_ewald.hpp).
  bool ewald = false;
  double ewaldTolerance = 1e-8;
};

struct CalculatorSettings {
  BandSettings band;
  DispersionSettings dispersion;
  SccSettings scc;  // enabled: the band term is self-consistent (dftb/scc_term.hpp)
};

struct Result {
  // Energies per cell, Hartree.
  double bandEnergy = 0.0;       // sum f e
  double entropyTerm = 0.0;      // T S
  double repulsive = 0.0;
  double dispersion = 0.0;
  double scc = 0.0;              // SCC: -sum_i V_i q_i + 1/2 dq gamma dq (double counting)
  double totalEnergy = 0.0;      // band + scc + repulsive + dispersion
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
  Calculator(std::shared_ptr<const ParameterSet> params, CalculatorSettings settings);
  Result evaluate(const objective::ObjectiveCell& cell, const EvaluationRequest& request) const;
  const CalculatorSettings& settings() const { return settings_; }
  const ParameterSet& parameters() const { return *params_; }
  std::vector<std::string> termNames() const;
  // Converged SCC charges kept between evaluations for the warm start (SccSettings::warmStart);
  // clear() it to make the next evaluation start from neutral atoms.
  ChargeCache& chargeCache() const { return *chargeCache_; }

 private:
  std::shared_ptr<const ParameterSet> params_;
  CalculatorSettings settings_;
  std::vector<std::unique_ptr<EnergyTerm>> terms_;
  std::shared_ptr<const RadialPotential> lj_;
  std::shared_ptr<ChargeCache> chargeCache_ = std::make_shared<ChargeCache>();
};

}  // namespace mesochain::dftb
