#pragma once
// Relaxation of the cell atoms at fixed symmetry (L-BFGS: Nocedal & Wright, Numerical
// Optimization, Alg. 7.4; FIRE: Bitzek et al., Phys. Rev. Lett. 97, 170201 (2006)) and, optionally, a one-dimensional search for the screw translation T0 at zero
// axial force dF/dT = 0 (safeguarded secant / regula falsi on dF/dT, each point relaxed).
// Energies minimised are the Mermin free energy of dftb::Calculator.
#include <functional>
#include <memory>
#include <vector>

#include "dftb/calculator.hpp"
#include "objective/core/cell.hpp"

namespace mesochain::objective {

enum class RelaxAlgorithm { Lbfgs, Fire };

struct RelaxStep {
  double translation = 0.0;  // Bohr
  double freeEnergy = 0.0;   // Hartree per cell
  double maxForce = 0.0;     // Hartree/Bohr
  double axialForce = 0.0;   // -dF/dT, Hartree/Bohr
};

// The search for T0 (relaxTranslation) between two fixed-T relaxations: the safeguarded secant
// until dF/dT changes sign, then regula falsi (Illinois) on the bracket [ta, tb].
struct TranslationSearch {
  int iteration = -1;  // -1: the first fixed-T relaxation, at the starting T, is under way
  double t0 = 0.0, g0 = 0.0;  // the previous translation (Bohr) and its dF/dT (Hartree/Bohr)
  double t1 = 0.0;            // the translation being relaxed at
  bool bracketed = false;
  double ta = 0.0, ga = 0.0, tb = 0.0, gb = 0.0;
  int side = 0;               // which end regula falsi moved last (Illinois halving)
};

// The cell at translation t: its atoms' axial coordinates scaled with T (affinely), the twist and
// the rotation order kept.
void setTranslation(ObjectiveCell& cell, double t);

// One step of the T search (relax.cpp): takes dF/dT at ts.t1, sets the next ts.t1. Exposed for
// its tests.
void advanceTranslationSearch(TranslationSearch& ts, double dFdT);

// Where a relaxation stands after an accepted step: enough to continue it after an
// interruption (RelaxSettings::snapshot, resumeFrom). The fixed-T relaxation under way restarts
// from `cell` with a fresh L-BFGS memory (or FIRE velocity) and its own max_steps again, so a
// resumed relaxation takes other steps than an uninterrupted one to the same tolerances; the
// T search continues where it was.
struct RelaxProgress {
  ObjectiveCell cell;                // the atoms and symmetry (the T) of the accepted step
  int evaluations = 0;               // energy evaluations so far, over every T
  std::vector<RelaxStep> history;    // the fixed-T relaxations finished
  TranslationSearch search;
};

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
  // Called with the relaxation's state after an accepted step, when at least snapshotSeconds
  // of wall time have passed since the start or the previous call (0: after every accepted
  // step): how a scan keeps a long relaxation in its checkpoint.
  std::function<void(const RelaxProgress&)> snapshot;
  double snapshotSeconds = 600.0;
  // Continue this relaxation (a snapshot of the same cell and settings) instead of starting
  // from the cell given to relax().
  std::shared_ptr<const RelaxProgress> resumeFrom;
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
