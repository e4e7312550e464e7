#include "objective/drivers/relax.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "objective/core/cell.hpp"

namespace mesochain::objective {

double maxForce(const Eigen::Matrix3Xd& gradient) {
  return gradient.size() ? gradient.colwise().norm().maxCoeff() : 0.0;
}

namespace {

const dftb::EvaluationRequest kFull{true, true};

// Every geometry a relaxation evaluates passes the check of a read geometry (finite
// coordinates, atoms and images at least kMinimumAtomDistanceAngstrom apart): a step that
// collapses atoms is an error, never an energy.
dftb::Result evaluateChecked(const dftb::Calculator& calc, const ObjectiveCell& cell,
                             int evaluations) {
  cell.validate(evaluations == 0 ? std::string("the starting geometry of the relaxation")
                                 : "the geometry of relaxation evaluation " +
                                       std::to_string(evaluations + 1),
                kMinimumAtomDistanceAngstrom * units::kAngstromInBohr);
  return calc.evaluate(cell, kFull);
}

// FIRE on the cell atoms at fixed symmetry. Unit masses; the time step adapts.
bool relaxAtoms(const dftb::Calculator& calc, ObjectiveCell& cell, const RelaxSettings& s,
                dftb::Result& result, int& evaluations) {
  const double dtMax = 1.0, fInc = 1.1, fDec = 0.5, alphaStart = 0.1, fAlpha = 0.99;
  const int nMin = 5;
  double dt = 0.25, alpha = alphaStart;
  int sinceNegative = 0;
  Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, cell.atomCount());
  result = evaluateChecked(calc, cell, evaluations);
  ++evaluations;
  for (int step = 0; step < s.maxSteps; ++step) {
    Eigen::Matrix3Xd f = -result.gradient;
    const double fmax = maxForce(result.gradient);
    if (s.progress) s.progress(evaluations, result.freeEnergy, fmax);
    if (!std::isfinite(result.freeEnergy) || !f.allFinite())
      throw NumericalError("relaxation: non-finite energy or forces");
    if (fmax < s.forceTolerance) return true;
    const double power = (f.array() * v.array()).sum();
    if (power > 0) {
      const double fn = f.norm(), vn = v.norm();
      v = (1 - alpha) * v + alpha * vn / fn * f;
      if (++sinceNegative > nMin) {
        dt = std::min(dt * fInc, dtMax);
        alpha *= fAlpha;
      }
    } else {
      v.setZero();
      dt *= fDec;
      alpha = alphaStart;
      sinceNegative = 0;
    }
    // Semi-implicit Euler step of FIRE, capped per atom.
    v += dt * f;
    Eigen::Matrix3Xd dx = dt * v;
    const double largest = dx.colwise().norm().maxCoeff();
    if (largest > s.maxDisplacement) dx *= s.maxDisplacement / largest;
    cell.positions += dx;
    result = evaluateChecked(calc, cell, evaluations);
    ++evaluations;
  }
  return maxForce(result.gradient) < s.forceTolerance;
}

// L-BFGS (Nocedal & Wright, Numerical Optimization, 2nd ed., Alg. 7.4) with a backtracking
// Armijo line search, the step capped per atom. Returns false when the line search stalls
// (energy noise near convergence, or a non-convex region); the caller then continues with FIRE.
bool relaxLbfgs(const dftb::Calculator& calc, ObjectiveCell& cell, const RelaxSettings& s,
                dftb::Result& result, int& evaluations, bool& converged) {
  const int memory = 8;
  const Eigen::Index n = 3 * cell.atomCount();
  std::vector<Eigen::VectorXd> ss, ys;
  std::vector<double> rhos;
  result = evaluateChecked(calc, cell, evaluations);
  ++evaluations;
  auto flat = [](const Eigen::Matrix3Xd& m) {
    return Eigen::Map<const Eigen::VectorXd>(m.data(), m.size()).eval();
  };
  Eigen::VectorXd g = flat(result.gradient);
  for (int step = 0; step < s.maxSteps; ++step) {
    const double fmax = maxForce(result.gradient);
    if (s.progress) s.progress(evaluations, result.freeEnergy, fmax);
    if (!std::isfinite(result.freeEnergy) || !g.allFinite())
      throw NumericalError("relaxation: non-finite energy or forces");
    if (fmax < s.forceTolerance) {
      converged = true;
      return true;
    }
    // Two-loop recursion for d = -H g.
    Eigen::VectorXd q = g;
    std::vector<double> alpha(ss.size());
    for (int k = static_cast<int>(ss.size()) - 1; k >= 0; --k) {
      alpha[k] = rhos[k] * ss[k].dot(q);
      q -= alpha[k] * ys[k];
    }
    const double gamma = ss.empty() ? 1.0 : ss.back().dot(ys.back()) / ys.back().squaredNorm();
    Eigen::VectorXd r = gamma * q;
    for (size_t k = 0; k < ss.size(); ++k) r += ss[k] * (alpha[k] - rhos[k] * ys[k].dot(r));
    Eigen::VectorXd d = -r;
    if (g.dot(d) >= 0) {  // not a descent direction: restart from steepest descent
      ss.clear(), ys.clear(), rhos.clear();
      d = -g;
    }
    Eigen::Map<Eigen::Matrix3Xd> dm(d.data(), 3, cell.atomCount());
    const double largest = dm.colwise().norm().maxCoeff();
    double step0 = largest > s.maxDisplacement ? s.maxDisplacement / largest : 1.0;
    const Eigen::Matrix3Xd x0 = cell.positions;
    const double f0 = result.freeEnergy, slope = g.dot(d);
    bool accepted = false;
    for (int trial = 0; trial < 12 && !accepted; ++trial, step0 *= 0.5) {
      cell.positions = x0 + step0 * dm;
      result = evaluateChecked(calc, cell, evaluations);
      ++evaluations;
      accepted = result.freeEnergy <= f0 + 1e-4 * step0 * slope;
    }
    if (!accepted) {
      cell.positions = x0;
      result = evaluateChecked(calc, cell, evaluations);
      ++evaluations;
      return false;
    }
    const Eigen::VectorXd gNew = flat(result.gradient);
    const Eigen::Matrix3Xd moved = cell.positions - x0;
    Eigen::VectorXd sk = Eigen::Map<const Eigen::VectorXd>(moved.data(), n);
    Eigen::VectorXd yk = gNew - g;
    if (sk.dot(yk) > 1e-16) {
      if (static_cast<int>(ss.size()) == memory) {
        ss.erase(ss.begin()), ys.erase(ys.begin()), rhos.erase(rhos.begin());
      }
      rhos.push_back(1.0 / sk.dot(yk));
      ss.push_back(std::move(sk));
      ys.push_back(std::move(yk));
    }
    g = gNew;
  }
  converged = maxForce(result.gradient) < s.forceTolerance;
  return true;
}

// The atoms at fixed symmetry: L-BFGS first, FIRE for whatever remains if its line search stalls.
bool relaxAtomsAtFixedSymmetry(const dftb::Calculator& calc, ObjectiveCell& cell,
                               const RelaxSettings& s, dftb::Result& result, int& evaluations) {
  bool converged = false;
  if (s.algorithm == RelaxAlgorithm::Lbfgs &&
      relaxLbfgs(calc, cell, s, result, evaluations, converged))
    return converged;
  return relaxAtoms(calc, cell, s, result, evaluations);
}

// Changes T and scales the z coordinates with it (an affine warm start).
void setTranslation(ObjectiveCell& cell, double t) {
  const double scale = t / cell.symmetry.translation();
  cell.positions.row(2) *= scale;
  cell.symmetry = cell.symmetry.withTranslation(t);
}

}  // namespace

RelaxOutcome relax(const dftb::Calculator& calc, ObjectiveCell cell, const RelaxSettings& s) {
  RelaxOutcome out;
  auto relaxAt = [&](double t) {
    if (t != cell.symmetry.translation()) setTranslation(cell, t);
    const bool ok = relaxAtomsAtFixedSymmetry(calc, cell, s, out.result, out.evaluations);
    out.history.push_back({cell.symmetry.translation(), out.result.freeEnergy,
                           maxForce(out.result.gradient), -out.result.dFdTranslation});
    return ok;
  };
  bool atomsOk = relaxAt(cell.symmetry.translation());
  if (!s.relaxTranslation || cell.symmetry.isRing()) {
    out.converged = atomsOk;
    out.cell = cell;
    return out;
  }
  // Root of g(T) = dF/dT: bracket by stepping downhill, then regula falsi (Illinois variant).
  double t0 = cell.symmetry.translation(), g0 = out.result.dFdTranslation;
  double t1 = t0 * (1.0 - 0.01 * (g0 > 0 ? 1 : -1)), g1 = 0;
  bool bracketed = false;
  double ta = 0, ga = 0, tb = 0, gb = 0;
  int side = 0;
  for (int it = 0; it < s.maxTranslationSteps; ++it) {
    if (std::abs(out.result.dFdTranslation) < s.axialTolerance && atomsOk) {
      out.converged = true;
      break;
    }
    atomsOk = relaxAt(t1);
    g1 = out.result.dFdTranslation;
    if (!bracketed && g0 * g1 < 0) {
      bracketed = true;
      ta = t0, ga = g0, tb = t1, gb = g1;
    } else if (bracketed) {
      if (g1 * ga < 0) {
        tb = t1, gb = g1;
        if (side == -1) ga *= 0.5;
        side = -1;
      } else {
        ta = t1, ga = g1;
        if (side == 1) gb *= 0.5;
        side = 1;
      }
    }
    double next;
    if (bracketed) {
      next = (ta * gb - tb * ga) / (gb - ga);
    } else {
      // Secant extrapolation, at most 5% per step.
      const double slope = (g1 - g0) / (t1 - t0);
      next = slope > 0 ? t1 - g1 / slope : t1 - 0.05 * t1 * (g1 > 0 ? 1 : -1);
      next = std::clamp(next, 0.95 * t1, 1.05 * t1);
    }
    t0 = t1, g0 = g1, t1 = next;
  }
  if (!out.converged)
    out.converged = atomsOk && std::abs(out.result.dFdTranslation) < s.axialTolerance;
  out.cell = cell;
  return out;
}

}  // namespace mesochain::objective
