#pragma once
// One interaction interface for every energy term of an objective cell (band structure,
// repulsive, dispersion, SCC): the named energies per cell it reports into a ledger
// (dftb/energy_ledger.hpp), their gradient with respect to the cell atoms, and their
// derivatives with respect to the screw translation T and twist gamma. Parameters are
// immutable; per-geometry work happens inside evaluate(). Terms register themselves
// (dftb/term_registry.hpp).
#include <map>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "dftb/energy_ledger.hpp"
#include "objective/core/cell.hpp"

namespace mesochain::dftb {

struct EvaluationRequest {
  bool gradient = false;  // dE/dx of the cell atoms
  bool strain = false;    // dE/dT and dE/dgamma
};

struct TermOutput {
  // The term's energies per cell (Hartree); its gradient and strain derivatives are those of
  // energies.free() (the Energy entries minus the entropy term).
  EnergyLedger energies;
  Eigen::Matrix3Xd gradient;   // Hartree/Bohr, 3 x N_o (empty when not requested)
  double dEdTranslation = 0.0; // Hartree/Bohr
  double dEdTwist = 0.0;       // Hartree/rad
  // Named extra scalars a term reports (e.g. "fermi_level"), in atomic units.
  std::map<std::string, double> extras;
  // Named per-atom or per-iteration lists (e.g. "mulliken_charges"), in atomic units.
  std::map<std::string, std::vector<double>> series;
};

class EnergyTerm {
 public:
  virtual ~EnergyTerm() = default;
  virtual std::string name() const = 0;
  virtual void evaluate(const objective::ObjectiveCell& cell, const EvaluationRequest& request,
                        TermOutput& out) const = 0;
};

}  // namespace mesochain::dftb
