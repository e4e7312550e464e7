#include "skgen/atom.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "common/errors.hpp"
#include "skgen/radial_schrodinger.hpp"

namespace mesochain::skgen {

std::vector<double> AtomSolution::totalDensity() const {
  std::vector<double> n = density[0];
  if (spins == 2)
    for (std::size_t i = 0; i < n.size(); ++i) n[i] += density[1][i];
  return n;
}

const ShellSolution& AtomSolution::shell(int n, int l) const {
  for (const auto& s : shells)
    if (s.n == n && s.l == l) return s;
  throw std::invalid_argument(fmt::format("atom has no shell n={} l={}", n, l));
}

namespace {

constexpr double kFourPi = 4.0 * std::numbers::pi;

// V_H(r) = 4π [ (1/r) ∫_0^r n r'² dr' + ∫_r^∞ n r' dr' ]  (radial Poisson equation)
std::vector<double> hartreePotential(const LogGrid& g, const std::vector<double>& n) {
  const int np = g.size();
  std::vector<double> a(np), b(np);
  for (int i = 0; i < np; ++i) {
    const double r = g.r[i];
    a[i] = n[i] * r * r * r;
    b[i] = n[i] * r * r;
  }
  const std::vector<double> qa = g.cumulativeDx(a), qb = g.cumulativeDx(b);
  std::vector<double> v(np);
  for (int i = 0; i < np; ++i) v[i] = kFourPi * (qa[i] / g.r[i] + (qb[np - 1] - qb[i]));
  return v;
}

double integrate3d(const LogGrid& g, const std::vector<double>& f) {
  std::vector<double> w(g.size());
  for (int i = 0; i < g.size(); ++i) w[i] = f[i] * g.r[i] * g.r[i] * g.r[i];
  return kFourPi * g.integrateDx(w);
}

struct Step {
  std::vector<std::vector<double>> nOut;
  std::vector<std::vector<double>> v;  // potentials used (no confinement)
  std::vector<double> vH;
  std::vector<std::vector<double>> vxc;
  std::vector<ShellSolution> shells;
  AtomEnergies e;
};

}  // namespace

AtomSolution solveAtom(const AtomSettings& s) {
  if (!(s.z > 0.0)) throw InputError(s.name, "nuclear charge", std::to_string(s.z), "Z > 0");
  double electrons = 0.0;
  for (const auto& sh : s.shells) {
    if (sh.l < 0 || sh.l >= sh.n)
      throw InputError(s.name, fmt::format("shell n={} l={}", sh.n, sh.l), "l >= n", "0 <= l < n");
    const double capacity = 2 * sh.l + 1;
    const bool over = s.polarised ? std::max(sh.occupation[0], sh.occupation[1]) > capacity + s.overfill
                                  : sh.occupation[0] + sh.occupation[1] > 2.0 * capacity + s.overfill;
    if (sh.occupation[0] < 0 || sh.occupation[1] < 0 || over)
      throw InputError(s.name, fmt::format("shell n={} l={}", sh.n, sh.l),
                       fmt::format("occupation {} + {}", sh.occupation[0], sh.occupation[1]),
                       fmt::format("0 to {} electrons per spin", 2 * sh.l + 1));
    electrons += sh.occupation[0] + sh.occupation[1];
  }
  if (s.shells.empty()) throw InputError(s.name, "shells", "none", "at least one shell");

  AtomSolution out;
  out.grid = LogGrid::make(s.rMinTimesZ / s.z, s.rMax, s.h);
  const LogGrid& g = out.grid;
  const int np = g.size();
  const int ns = s.polarised ? 2 : 1;
  out.spins = ns;
  XcFunctional xc(s.xc, s.polarised);

  std::vector<double> vconf(np), vnuc(np);
  for (int i = 0; i < np; ++i) {
    vconf[i] = s.confinement(g.r[i]);
    vnuc[i] = -s.z / g.r[i];
  }

  // Slater back-end: one basis per angular momentum, and the states of each l asked for
  std::vector<std::unique_ptr<SlaterRadialSolver>> slater;
  std::vector<int> statesPerL;
  if (!s.slater.empty()) {
    for (const auto& sh : s.shells) {
      if (sh.l >= static_cast<int>(statesPerL.size())) statesPerL.resize(sh.l + 1, 0);
      statesPerL[sh.l] = std::max(statesPerL[sh.l], sh.n - sh.l);
    }
    for (int l = 0; l < static_cast<int>(statesPerL.size()); ++l)
      slater.push_back(std::make_unique<SlaterRadialSolver>(s.slater, g, l));
  }

  std::vector<std::array<double, 2>> guesses(s.shells.size(),
                                             {std::numeric_limits<double>::quiet_NaN(),
                                              std::numeric_limits<double>::quiet_NaN()});

  // One Kohn-Sham step: potentials from the input densities, states, output densities.
  auto step = [&](const std::vector<std::vector<double>>& nIn, Step& st) {
    std::vector<double> nTot = nIn[0];
    if (ns == 2)
      for (int i = 0; i < np; ++i) nTot[i] += nIn[1][i];
    st.vH = hartreePotential(g, nTot);
    double exc = 0.0;
    st.v = xc.radialPotential(g, nIn, exc);
    st.vxc = st.v;
    for (int sp = 0; sp < ns; ++sp)
      for (int i = 0; i < np; ++i) st.v[sp][i] += vnuc[i] + st.vH[i];
    st.nOut.assign(ns, std::vector<double>(np, 0.0));
    st.shells.clear();
    double bandSum = 0.0;
    // Slater back-end: all states of every l and spin from one generalized eigenproblem
    std::vector<std::array<std::vector<SlaterState>, 2>> slaterStates(slater.size());
    for (std::size_t l = 0; l < slater.size(); ++l)
      for (int sp = 0; sp < ns; ++sp) {
        if (statesPerL[l] == 0) continue;
        std::vector<double> vt(np);
        for (int i = 0; i < np; ++i) vt[i] = st.v[sp][i] + vconf[i];
        slaterStates[l][sp] = slater[l]->solve(vt, statesPerL[l]);
      }
    for (std::size_t k = 0; k < s.shells.size(); ++k) {
      const AtomShell& sh = s.shells[k];
      ShellSolution sol;
      sol.n = sh.n;
      sol.l = sh.l;
      sol.occupation = sh.occupation;
      for (int sp = 0; sp < ns; ++sp) {
        std::vector<double> vt(np);
        for (int i = 0; i < np; ++i) vt[i] = st.v[sp][i] + vconf[i];
        RadialState rs;
        if (!slater.empty()) {
          SlaterState& ss = slaterStates[sh.l][sp][sh.n - sh.l - 1];
          rs.energy = ss.energy;
          rs.u = ss.u;
          sol.terms[sp] = ss.terms;
        } else {
          try {
            rs = solveRadial(g, vt, s.z, sh.n, sh.l, guesses[k][sp]);
          } catch (const NumericalError& e) {
            throw NumericalError(s.name + ": " + e.what());
          }
        }
        guesses[k][sp] = rs.energy;
        const double occ = ns == 2 ? sh.occupation[sp] : sh.occupation[0] + sh.occupation[1];
        bandSum += occ * rs.energy;
        for (int i = 0; i < np; ++i)
          st.nOut[sp][i] += occ * rs.u[i] * rs.u[i] / (kFourPi * g.r[i] * g.r[i]);
        sol.energy[sp] = rs.energy;
        sol.u[sp] = std::move(rs.u);
      }
      if (ns == 1) {
        sol.energy[1] = sol.energy[0];
        sol.u[1] = sol.u[0];
        sol.terms[1] = sol.terms[0];
      }
      st.shells.push_back(std::move(sol));
    }
    // energies of the output density; kinetic from the band sum and the input potential
    std::vector<double> nOutTot = st.nOut[0];
    if (ns == 2)
      for (int i = 0; i < np; ++i) nOutTot[i] += st.nOut[1][i];
    std::vector<double> f(np, 0.0);
    for (int sp = 0; sp < ns; ++sp)
      for (int i = 0; i < np; ++i) f[i] += st.nOut[sp][i] * (st.v[sp][i] + vconf[i]);
    st.e.kinetic = bandSum - integrate3d(g, f);
    const std::vector<double> vHout = hartreePotential(g, nOutTot);
    for (int i = 0; i < np; ++i) f[i] = nOutTot[i] * vHout[i];
    st.e.hartree = 0.5 * integrate3d(g, f);
    for (int i = 0; i < np; ++i) f[i] = nOutTot[i] * vnuc[i];
    st.e.nuclear = integrate3d(g, f);
    for (int i = 0; i < np; ++i) f[i] = nOutTot[i] * vconf[i];
    st.e.confinement = integrate3d(g, f);
    double excOut = 0.0;
    xc.radialPotential(g, st.nOut, excOut);
    st.e.xc = excOut;
    st.e.total = st.e.kinetic + st.e.hartree + st.e.nuclear + st.e.xc;
  };

  // Start: bare-nucleus (hydrogen-like) states.
  std::vector<std::vector<double>> nIn(ns, std::vector<double>(np, 0.0));
  Step st;
  step(nIn, st);
  nIn = st.nOut;

  // Anderson / Pulay mixing on the concatenated spin densities, inner product ∫ · d³r.
  std::vector<double> weight(np);
  for (int i = 0; i < np; ++i) weight[i] = kFourPi * g.h * std::pow(g.r[i], 3);
  auto flat = [&](const std::vector<std::vector<double>>& a) {
    Eigen::VectorXd v(ns * np);
    for (int sp = 0; sp < ns; ++sp)
      for (int i = 0; i < np; ++i) v[sp * np + i] = a[sp][i];
    return v;
  };
  const Eigen::Map<const Eigen::VectorXd> wv(weight.data(), np);
  auto dot = [&](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    double d = 0.0;
    for (int sp = 0; sp < ns; ++sp)
      d += (a.segment(sp * np, np).array() * b.segment(sp * np, np).array() * wv.array()).sum();
    return d;
  };
  std::vector<Eigen::VectorXd> xs, fs;
  double residual = std::numeric_limits<double>::infinity();
  for (int it = 1; it <= s.maxIterations; ++it) {
    step(nIn, st);
    const Eigen::VectorXd x = flat(nIn);
    const Eigen::VectorXd fres = flat(st.nOut) - x;
    residual = std::sqrt(dot(fres, fres));
    if (!std::isfinite(residual)) break;
    if (residual < s.tolerance) {
      out.shells = std::move(st.shells);
      out.density = std::move(st.nOut);
      out.potential = std::move(st.v);
      out.hartree = std::move(st.vH);
      out.xc = std::move(st.vxc);
      out.energies = st.e;
      out.iterations = it;
      out.residual = residual;
      return out;
    }
    xs.push_back(x);
    fs.push_back(fres);
    if (static_cast<int>(xs.size()) > s.history) {
      xs.erase(xs.begin());
      fs.erase(fs.begin());
    }
    const int m = static_cast<int>(xs.size());
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(m + 1, m + 1);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m + 1);
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j <= i; ++j) b(i, j) = b(j, i) = dot(fs[i], fs[j]);
      b(i, m) = b(m, i) = 1.0;
    }
    const double scale = b.topLeftCorner(m, m).diagonal().maxCoeff();
    b.topLeftCorner(m, m) /= scale;
    b.topLeftCorner(m, m).diagonal().array() += 1e-12;
    rhs[m] = 1.0;
    const Eigen::VectorXd c = b.colPivHouseholderQr().solve(rhs);
    Eigen::VectorXd next = Eigen::VectorXd::Zero(ns * np);
    for (int i = 0; i < m; ++i) next += c[i] * (xs[i] + s.mixing * fs[i]);
    for (int sp = 0; sp < ns; ++sp)
      for (int i = 0; i < np; ++i) nIn[sp][i] = std::max(0.0, next[sp * np + i]);
    (void)electrons;
  }
  throw NumericalError(fmt::format(
      "{}: the Kohn-Sham self-consistency did not converge in {} iterations (density residual "
      "{:.3e}, tolerance {:.1e}); try a smaller mixing parameter (now {}) or more iterations",
      s.name, s.maxIterations, residual, s.tolerance, s.mixing));
}

void requireBound(const AtomSolution& atom, const Confinement& confinement, int n, int l,
                  const std::string& source, const std::string& key) {
  const ShellSolution& sh = atom.shell(n, l);
  const double e = std::max(sh.energy[0], sh.energy[1]);
  const double limit = confinement.type == Confinement::Type::None ? 0.0 : confinement(confinement.r0);
  if (!(e < limit)) {
    throw InputError(source, key,
                     fmt::format("confinement {} under which the n={} l={} level is at {:+.4f} Ha, "
                                 "above the confining potential at r0 ({:.4f} Ha)",
                                 confinement.describe(), n, l, e, limit),
                     "a confinement radius large enough for a bound state");
  }
}

}  // namespace mesochain::skgen
