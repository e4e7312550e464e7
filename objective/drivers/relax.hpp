#pragma once
// Relaxation of the cell atoms at fixed symmetry (L-BFGS: Nocedal & Wright, Numerical
// Optimization, Alg. 7.4; FIRE: Bitzek et al., Phys. Rev. Lett. 97, 170201 (2006)) and, optionally, a one-dimensional search for the screw translation T0 at zero
// axial force dF/dT = 0 (safeguarded secant / regula falsi on dF/dT, each point relaxed).
// Energies minimised are the Mermin free energy of dftb::Calculator.
#include <functional>
#include <vector>

#include "dftb/calculator.hpp"
#include "objective/core/cell.hpp"

namespace mesochain::objective {

enum class RelaxAlgorithm { Lbfgs, Fire };

struct RelaxSettings {
  // L-BFGS with a backtracking line search (falls back to FIRE when the search stalls), or FIRE.
  RelaxAlgorithm algorithm = RelaxAlgorithm::Lbfgs;
  double forceTolerance = 1e-4;  // Hartree/Bohr, on the largest atomic force
  int maxSteps = 500;            // FIRE steps per fixed-T relaxation
  bool relaxTranslation = false; // also find T0 with |dF/dT| < axialTolerance
  double axialTolerance = 1e-4;  // Hartree/Bohr
  int maxTranslationSteps = 30;
  double maxDisplacement = 0.2;  // Bohr per FIRE step
  // Called after every energy evaluation: (step, free energy, largest force).
  std::function<void(int, double, double)> progress;
};

struct RelaxStep {
  double translation = 0.0;  // Bohr
  double freeEnergy = 0.0;   // Hartree per cell
  double maxForce = 0.0;     // Hartree/Bohr
  double axialForce = 0.0;   // -dF/dT, Hartree/Bohr
};

struct RelaxOutcome {
  ObjectiveCell cell;
  dftb::Result result;  // at the final geometry, with gradient and strain derivatives
  bool converged = false;
  int evaluations = 0;
  std::vector<RelaxStep> history;  // one entry per fixed-T relaxation
};

RelaxOutcome relax(const dftb::Calculator& calculator, ObjectiveCell cell,
                   const RelaxSettings& settings);

// Largest Euclidean norm of a column of the gradient.
double maxForce(const Eigen::Matrix3Xd& gradient);

}  // namespace mesochain::objective
