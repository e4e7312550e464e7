#include "skgen/atomic_data.hpp"

#include <algorithm>
#include <stdexcept>

namespace mesochain::skgen {

double hubbardU(const AtomSettings& free, int n, int l, double delta) {
  double e[2];
  for (int k = 0; k < 2; ++k) {
    AtomSettings s = free;
    s.overfill = std::max(s.overfill, 2.0 * delta);  // full shells (He 1s) step beyond capacity
    bool found = false;
    for (auto& sh : s.shells) {
      if (sh.n == n && sh.l == l) {
        const double d = (k == 0 ? -delta : delta);
        sh.occupation[0] += 0.5 * d;
        sh.occupation[1] += 0.5 * d;
        found = true;
      }
    }
    if (!found) throw std::invalid_argument("hubbardU: no shell with the given n, l");
    const AtomSolution a = solveAtom(s);
    const ShellSolution& sh = a.shell(n, l);
    e[k] = 0.5 * (sh.energy[0] + sh.energy[1]);
  }
  return (e[1] - e[0]) / (2.0 * delta);
}

OccupationDerivatives occupationDerivatives(const AtomSettings& free,
                                            const std::vector<int>& shells, double delta) {
  const int m = static_cast<int>(shells.size());
  if (m == 0) throw std::invalid_argument("occupationDerivatives: no shells");
  AtomSettings ref = free;
  ref.polarised = true;
  ref.overfill = std::max(ref.overfill, 2.0 * delta);
  for (auto& sh : ref.shells) {
    const double q = sh.occupation[0] + sh.occupation[1];
    sh.occupation = {0.5 * q, 0.5 * q};
  }
  int homo = -1;
  for (int k = 0; k < m; ++k) {
    if (shells[k] < 0 || shells[k] >= static_cast<int>(ref.shells.size()))
      throw std::invalid_argument("occupationDerivatives: shell index out of range");
    if (ref.shells[shells[k]].occupation[0] > 0.0) homo = k;
  }
  if (homo < 0) throw std::invalid_argument("occupationDerivatives: all shells are empty");

  // dUp[k][k'] = ∂ε_k↑/∂n_k'↑, dDown[k][k'] = ∂ε_k↑/∂n_k'↓ by central differences
  std::vector<std::vector<double>> dUp(m, std::vector<double>(m, 0.0)), dDown = dUp;
  for (int kp = 0; kp < m; ++kp) {
    if (ref.shells[shells[kp]].occupation[0] <= 0.0) continue;  // empty: HOMO values below
    for (int spin = 0; spin < 2; ++spin) {
      std::vector<double> e[2];
      for (int sign = 0; sign < 2; ++sign) {
        AtomSettings s = ref;
        s.shells[shells[kp]].occupation[spin] += sign == 0 ? -delta : delta;
        const AtomSolution a = solveAtom(s);
        for (int k = 0; k < m; ++k) e[sign].push_back(a.shells[shells[k]].energy[0]);
      }
      for (int k = 0; k < m; ++k)
        (spin == 0 ? dUp : dDown)[k][kp] = (e[1][k] - e[0][k]) / (2.0 * delta);
    }
  }
  OccupationDerivatives out;
  out.w.assign(m, std::vector<double>(m, 0.0));
  out.u = out.w;
  auto source = [&](int k) { return ref.shells[shells[k]].occupation[0] > 0.0 ? k : homo; };
  for (int k = 0; k < m; ++k)
    for (int kp = 0; kp < m; ++kp) {
      const int a = source(k), b = source(kp);
      out.w[k][kp] = 0.5 * (dUp[a][b] - dDown[a][b]);
      out.u[k][kp] = 0.5 * (dUp[a][b] + dDown[a][b]);
    }
  return out;
}

AtomSettings hundPolarised(const AtomSettings& unpolarised) {
  AtomSettings s = unpolarised;
  s.polarised = true;
  for (auto& sh : s.shells) {
    const double q = sh.occupation[0] + sh.occupation[1];
    const double up = std::min(q, 2.0 * sh.l + 1.0);
    sh.occupation = {up, q - up};
  }
  return s;
}

double spinPolarisationEnergy(const AtomSettings& free) {
  AtomSettings flat = free;
  flat.polarised = false;
  return solveAtom(hundPolarised(free)).energies.total - solveAtom(flat).energies.total;
}

}  // namespace mesochain::skgen
