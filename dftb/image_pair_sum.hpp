#pragma once
// Radial pair kernels K(r) summed over the image pairs (i, j, g) of an objective cell within a
// cutoff: the matrix M_ij = sum_g K_{ij}(|g(x_j) - x_i|) (identity excluded for i == j) and the
// derivatives of 1/2 sum_ij w_ij M_ij with respect to the cell atoms, T and gamma (from
// d = g(x_j) - x_i: dd/dx_i = -1, dd/dx_j = R(g), dd/dT = zeta e_z, dd/dgamma = zeta R'(phi) x_j).
// kernel(i, j, r, value, derivative) fills K and dK/dr for cell atoms i, j.
#include "dftb/coulomb_lattice_sum.hpp"
#include "objective/core/images.hpp"

namespace mesochain::dftb {

template <class Kernel>
Eigen::MatrixXd imagePairMatrix(const objective::ObjectiveCell& cell,
                                const objective::ImageList& images, Kernel&& kernel) {
  const int n = cell.atomCount();
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
  double v = 0, dv = 0;
  for (const auto& p : images.pairs()) {
    kernel(p.i, p.j, p.r, v, dv);
    m(p.i, p.j) += v;
  }
  return m;
}

template <class Kernel>
LatticeSumDerivatives imagePairDerivatives(const objective::ObjectiveCell& cell,
                                           const objective::ImageList& images,
                                           const Eigen::MatrixXd& weights, Kernel&& kernel) {
  LatticeSumDerivatives out;
  out.gradient = Eigen::Matrix3Xd::Zero(3, cell.atomCount());
  const auto& sym = cell.symmetry;
  double v = 0, dv = 0;
  for (const auto& p : images.pairs()) {
    const double w = weights(p.i, p.j);
    if (w == 0.0) continue;
    kernel(p.i, p.j, p.r, v, dv);
    const Eigen::Vector3d f = (0.5 * w * dv / p.r) * p.d;  // d(1/2 w K)/dd
    out.gradient.col(p.i) -= f;
    out.gradient.col(p.j) += sym.rotation(p.g).transpose() * f;
    if (!sym.isRing()) {
      const double zeta = static_cast<double>(p.g.zeta);
      out.dTranslation += zeta * f.z();
      out.dTwist += f.dot(zeta * objective::rotationZDerivative(sym.angle(p.g)) *
                          cell.positions.col(p.j));
    }
  }
  return out;
}

}  // namespace mesochain::dftb
