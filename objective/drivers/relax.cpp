#include "objective/drivers/relax.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"

namespace mesochain::objective {

double maxForce(const Eigen::Matrix3Xd& gradient) {
  return gradient.size() ? gradient.colwise().norm().maxCoeff() : 0.0;
}

namespace {

const dftb::EvaluationRequest kFull{true, true};

// FIRE on the cell atoms at fixed symmetry. Unit masses; the time step adapts.
bool relaxAtoms(const dftb::Calculator& calc, ObjectiveCell& cell, const RelaxSettings& s,
                dftb::Result& result, int& evaluations) {
  const double dtMax = 1.0, fInc = 1.1, fDec = 0.5, alphaStart = 0.1, fAlpha = 0.99;
  const int nMin = 5;
  double dt = 0.25, alpha = alphaStart;
  int sinceNegative = 0;
  Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, cell.atomCount());
  result = calc.evaluate(cell, kFull);
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
    result = calc.evaluate(cell, kFull);
    ++evaluations;
  }
  return maxForce(result.gradient) < s.forceTolerance;
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
    const bool ok = relaxAtoms(calc, cell, s, out.result, out.evaluations);
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
