#include "skgen/atomic_data.hpp"

#include <stdexcept>

namespace mesochain::skgen {

double hubbardU(const AtomSettings& free, int n, int l, double delta) {
  double e[2];
  for (int k = 0; k < 2; ++k) {
    AtomSettings s = free;
    bool found = false;
    for (auto& sh : s.shells) {
      if (sh.n == n && sh.l == l) {
        const double d = (k == 0 ? -delta : delta);
        if (s.polarised) {
          sh.occupation[0] += 0.5 * d;
          sh.occupation[1] += 0.5 * d;
        } else {
          sh.occupation[0] += 0.5 * d;
          sh.occupation[1] += 0.5 * d;
        }
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

}  // namespace mesochain::skgen
