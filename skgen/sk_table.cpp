#include "skgen/sk_table.hpp"

#include <cmath>
#include <stdexcept>

namespace mesochain::skgen {

int skfColumn(int la, int lb, int m) {
  if (la > lb || m > la) return -1;
  // extended order: 7 dd0 8 dd1 9 dd2 12 pd0 13 pd1 14 pp0 15 pp1 17 sd0 18 sp0 19 ss0
  if (la == 0) return 19 - lb;                 // ss0 19, sp0 18, sd0 17
  if (la == 1) return lb == 1 ? 14 + m : 12 + m;
  if (la == 2) return 7 + m;
  return -1;
}

dftb::SkfTable buildSkTable(const ElementBasis& a, const ElementBasis& b, XcKind xc,
                            const TableGrid& grid, bool homonuclear,
                            const std::function<void(int, int)>& progress) {
  const int rows = static_cast<int>(std::floor(grid.cutoff / grid.spacing + 1e-9));
  if (!(grid.spacing > 0.0) || rows < 1)
    throw std::invalid_argument("Slater-Koster table: the cutoff is shorter than the first grid point");
  dftb::SkfTable t;
  t.homonuclear = homonuclear;
  t.gridSpacing = grid.spacing;
  t.declaredPoints = rows + 1;
  t.ham = Eigen::MatrixXd::Zero(rows, dftb::kSkfColumnCount);
  t.over = Eigen::MatrixXd::Zero(rows, dftb::kSkfColumnCount);
  if (homonuclear) {
    t.onsite = a.data.onsite;
    t.hubbard = a.data.hubbard;
    t.occupation = a.data.occupation;
    t.spinPolarisationError = a.data.spinPolarisationEnergy;
    t.mass = a.element->mass;
  }
  const XcFunctional f(xc, false);
  for (int i = 0; i < rows; ++i) {
    const double d = (i + 1) * grid.spacing;
    for (const SkIntegral& I :
         twoCentreIntegrals(a.orbitals, b.orbitals, &a.atom, &b.atom, &f, d, grid.quadrature)) {
      const int c = skfColumn(I.la, I.lb, I.m);
      if (c < 0) continue;
      t.over(i, c) = I.s;
      t.ham(i, c) = I.h;
    }
    if (progress) progress(i + 1, rows);
  }
  return t;
}

}  // namespace mesochain::skgen
