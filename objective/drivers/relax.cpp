#include "objective/drivers/relax.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "objective/core/cell.hpp"

namespace mesochain::objective {

double maxForce(const Eigen::Matrix3Xd& gradient) {
  return gradient.size() ? gradient.colwise().norm().maxCoeff() : 0.0;
}

namespace {

const dftb::EvaluationRequest kFull{true, true};

// Called by the fixed-T relaxers with the cell of each accepted step that is not yet converged.
using AcceptedStep = std::function<void(const ObjectiveCell&)>;

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
                dftb::Result& result, int& evaluations, const AcceptedStep& accepted) {
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
    accepted(cell);
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
                dftb::Result& result, int& evaluations, bool& converged,
                const AcceptedStep& accepted) {
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
    accepted(cell);
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
                               const RelaxSettings& s, dftb::Result& result, int& evaluations,
                               const AcceptedStep& accepted) {
  bool converged = false;
  if (s.algorithm == RelaxAlgorithm::Lbfgs &&
      relaxLbfgs(calc, cell, s, result, evaluations, converged, accepted))
    return converged;
  return relaxAtoms(calc, cell, s, result, evaluations, accepted);
}

// The first step of the T search from the atoms relaxed at T0 with dF/dT = g0: Newton on the
// clamped-ion axial stiffness k = d(dF/dT)/dT of the atoms scaled affinely with T, measured by
// one evaluation at T0 (1 -+ 1e-4), downhill. Relaxing the atoms can only soften the cell, so k is
// an upper bound of the relaxed stiffness and the step does not overshoot the root; at most
// 1 % of T (the step taken when k is not positive). A start close to T0 (a relaxed structure
// read back, T off by 1e-4) so takes a step of its own size instead of 1 % and back, which
// cost as much as the whole relaxation (docs/cell-file.md, [task]).
double firstTranslationStep(const dftb::Calculator& calc, const ObjectiveCell& cell, double g0,
                            int& evaluations) {
  const double t0 = cell.symmetry.translation(), maxStep = 0.01 * t0;
  const double downhill = g0 > 0 ? -1.0 : 1.0;
  ObjectiveCell probe = cell;
  const double dt = 1e-4 * t0 * downhill;
  setTranslation(probe, t0 + dt);
  const dftb::Result r = evaluateChecked(calc, probe, evaluations);
  ++evaluations;
  const double k = (r.dFdTranslation - g0) / dt;
  if (!std::isfinite(k) || !(k > 0)) return downhill * maxStep;
  return std::clamp(-g0 / k, -maxStep, maxStep);
}

}  // namespace

// Changes T and scales the z coordinates with it (an affine warm start).
void setTranslation(ObjectiveCell& cell, double t) {
  const double scale = t / cell.symmetry.translation();
  cell.positions.row(2) *= scale;
  cell.symmetry = cell.symmetry.withTranslation(t);
}

// Advances the T search by the dF/dT g1 found at t1: bracket by stepping downhill (secant, at
// most 5 % per step), then regula falsi with the Illinois halving; sets the next t1.
// g is dF/dT of the atoms relaxed at T only to the force tolerance, so two visits of one T may
// disagree (by ~0.02 Hartree/Bohr for 180 atoms at 1e-4): a bracket end measured once with the
// opposite sign can hold a sign change that is not there. Regula falsi then closes the bracket
// onto that end and evaluates the same T again and again. A bracket that has shrunk to
// 1e-10 of T without axial convergence is therefore dropped, and the search brackets afresh from
// the current point with a step of 0.1 % of T downhill.
void advanceTranslationSearch(TranslationSearch& ts, double g1) {
  const double t1 = ts.t1;
  if (!ts.bracketed && ts.g0 * g1 < 0) {
    ts.bracketed = true;
    ts.ta = ts.t0, ts.ga = ts.g0, ts.tb = t1, ts.gb = g1;
  } else if (ts.bracketed) {
    if (g1 * ts.ga < 0) {
      ts.tb = t1, ts.gb = g1;
      if (ts.side == -1) ts.ga *= 0.5;
      ts.side = -1;
    } else {
      ts.ta = t1, ts.ga = g1;
      if (ts.side == 1) ts.gb *= 0.5;
      ts.side = 1;
    }
  }
  double next;
  if (ts.bracketed && std::abs(ts.tb - ts.ta) <= 1e-10 * std::abs(t1)) {
    ts.bracketed = false, ts.side = 0;
    next = t1 * (1.0 - 1e-3 * (g1 > 0 ? 1 : -1));
  } else if (ts.bracketed) {
    next = (ts.ta * ts.gb - ts.tb * ts.ga) / (ts.gb - ts.ga);
  } else {
    const double slope = (g1 - ts.g0) / (t1 - ts.t0);
    next = slope > 0 ? t1 - g1 / slope : t1 - 0.05 * t1 * (g1 > 0 ? 1 : -1);
    next = std::clamp(next, 0.95 * t1, 1.05 * t1);
  }
  ts.t0 = t1, ts.g0 = g1, ts.t1 = next;
  ++ts.iteration;
}

RelaxOutcome relax(const dftb::Calculator& calc, ObjectiveCell cell, const RelaxSettings& s) {
  RelaxOutcome out;
  TranslationSearch ts;
  if (s.resumeFrom) {
    const RelaxProgress& from = *s.resumeFrom;
    if (from.cell.atomCount() != cell.atomCount() || from.cell.species != cell.species)
      throw InputError("the relaxation to resume", "its snapshot",
                       fmt::format("a snapshot of {} atoms of other species or order", from.cell.atomCount()),
                       fmt::format("a snapshot of this cell ({} atoms)", cell.atomCount()));
    cell = from.cell;
    out.evaluations = from.evaluations;
    out.history = from.history;
    ts = from.search;
  }
  using Clock = std::chrono::steady_clock;
  auto lastSnapshot = Clock::now();
  const AcceptedStep accepted = [&](const ObjectiveCell& now) {
    if (!s.snapshot ||
        std::chrono::duration<double>(Clock::now() - lastSnapshot).count() < s.snapshotSeconds)
      return;
    s.snapshot(RelaxProgress{now, out.evaluations, out.history, ts});
    lastSnapshot = Clock::now();
  };
  auto relaxAt = [&](double t) {
    if (t != cell.symmetry.translation()) setTranslation(cell, t);
    const bool ok = relaxAtomsAtFixedSymmetry(calc, cell, s, out.result, out.evaluations, accepted);
    out.history.push_back({cell.symmetry.translation(), out.result.freeEnergy,
                           maxForce(out.result.gradient), -out.result.dFdTranslation});
    return ok;
  };
  const bool searching = s.relaxTranslation && !cell.symmetry.isRing();
  const auto axialConverged = [&] { return std::abs(out.result.dFdTranslation) < s.axialTolerance; };
  bool atomsOk = false;
  if (ts.iteration < 0) {
    atomsOk = relaxAt(cell.symmetry.translation());
    if (!searching) {
      out.converged = atomsOk;
      out.cell = cell;
      return out;
    }
    if (atomsOk && axialConverged()) {
      out.converged = true;
      out.cell = cell;
      return out;
    }
    // The first step of the search: Newton on the clamped-ion stiffness, at most 1 % of T.
    ts.t0 = cell.symmetry.translation(), ts.g0 = out.result.dFdTranslation;
    ts.t1 = ts.t0 + firstTranslationStep(calc, cell, ts.g0, out.evaluations);
    ts.iteration = 0;
  }
  // Root of g(T) = dF/dT (the state between fixed-T relaxations is `ts`, so that a snapshot
  // taken inside relaxAt resumes here).
  while (ts.iteration < s.maxTranslationSteps) {
    atomsOk = relaxAt(ts.t1);
    advanceTranslationSearch(ts, out.result.dFdTranslation);
    if (atomsOk && axialConverged()) {
      out.converged = true;
      break;
    }
  }
  out.cell = cell;
  return out;
}

}  // namespace mesochain::objective
