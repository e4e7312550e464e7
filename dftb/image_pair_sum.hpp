#pragma once
// The one pair kernel of dftb (in the style of HOOMD-blue's pair evaluators): a radial kernel
// K_ij(r) summed over the image pairs (i, j, g) of an objective cell within a cutoff,
//   E = 1/2 sum_{(i, j, g)} w_ij K_ij(|d|),   d = g(x_j) - x_i   (per cell),
// with its derivatives with respect to the cell atoms, the screw translation T and the twist
// gamma from the one chain rule of d:
//   dd/dx_i = -1,  dd/dx_j = R(g),  dd/dT = zeta e_z,  dd/dgamma = zeta R'(phi_g) x_j
// (each unordered pair appears twice in the list, hence the 1/2). Terms supply only the
// evaluator of one pair; this file owns the loop, the chain rule (addImagePointDerivative) and
// the OpenMP.
//
// kernel(i, j, r, value, derivative) fills K and dK/dr for cell atoms i, j at distance r;
// weight(i, j) gives w_ij (a pair of weight 0 is skipped).
//
// Threads: above kParallelPairs pairs the list is split into contiguous blocks, one per thread
// (static schedule), each summed into its own buffer, and the buffers are added in thread
// order: the result is reproducible for a given thread count, and with one thread it is the
// serial sum in list order.
#include <vector>

#include <omp.h>

#include <Eigen/Dense>

#include "objective/core/images.hpp"

namespace mesochain::dftb {

struct ImagePairSum {
  double energy = 0.0;         // 1/2 sum w K
  Eigen::Matrix3Xd gradient;   // with respect to the cell atoms, 3 x N_o (empty if not asked)
  double dTranslation = 0.0;   // with respect to the screw translation T (0 for a ring)
  double dTwist = 0.0;         // with respect to the twist gamma (0 for a ring)
};

struct UnitWeight {
  double operator()(int, int) const { return 1.0; }
};

inline constexpr std::size_t kParallelPairs = 4096;

// M_ij = sum_g K_ij(|g(x_j) - x_i|) (identity excluded for i == j), N_o x N_o.
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

// The chain rule of an image point y = g(x_j), for dE/dy = f: adds dE/dx_j = R(g)^T f (when
// `gradient`), dE/dT = zeta f_z and dE/dgamma = f . zeta R'(phi_g) x_j (when `screw`). A pair
// d = g(x_j) - x_i is this at its far end and -f at x_i; terms whose energy depends on other
// image points (the neighbours that define a normal, dftb/dispersion_kc.cpp) use it for those.
inline void addImagePointDerivative(const objective::ObjectiveCell& cell, int j,
                                    const objective::GroupElement& g, const Eigen::Vector3d& f,
                                    bool gradient, bool screw, ImagePairSum& out) {
  const auto& sym = cell.symmetry;
  if (gradient) out.gradient.col(j) += sym.rotation(g).transpose() * f;
  if (screw) {
    const double zeta = static_cast<double>(g.zeta);
    out.dTranslation += zeta * f.z();
    out.dTwist += f.dot(zeta * objective::rotationZDerivative(sym.angle(g)) * cell.positions.col(j));
  }
}

namespace detail {
// The pairs [lo, hi) of the list into `out` (gradient sized when wanted).
template <class Kernel, class Weight>
void addImagePairs(const objective::ObjectiveCell& cell, const std::vector<objective::ImagePair>& pairs,
                   std::size_t lo, std::size_t hi, bool gradient, bool strain, Kernel& kernel,
                   Weight& weight, ImagePairSum& out) {
  const auto& sym = cell.symmetry;
  const bool screw = strain && !sym.isRing();
  double v = 0, dv = 0;
  for (std::size_t k = lo; k < hi; ++k) {
    const objective::ImagePair& p = pairs[k];
    const double w = weight(p.i, p.j);
    if (w == 0.0) continue;
    kernel(p.i, p.j, p.r, v, dv);
    out.energy += 0.5 * w * v;
    if (!gradient && !screw) continue;
    const Eigen::Vector3d f = (0.5 * w * dv / p.r) * p.d;  // d(1/2 w K)/dd
    if (gradient) out.gradient.col(p.i) -= f;
    addImagePointDerivative(cell, p.j, p.g, f, gradient, screw, out);
  }
}
}  // namespace detail

template <class Kernel, class Weight = UnitWeight>
ImagePairSum imagePairSum(const objective::ObjectiveCell& cell, const objective::ImageList& images,
                          bool gradient, bool strain, Kernel&& kernel, Weight&& weight = {}) {
  const auto& pairs = images.pairs();
  const int n = cell.atomCount();
  auto fresh = [&] {
    ImagePairSum s;
    if (gradient) s.gradient = Eigen::Matrix3Xd::Zero(3, n);
    return s;
  };
  const int threads = pairs.size() > kParallelPairs && !omp_in_parallel() ? omp_get_max_threads() : 1;
  if (threads <= 1) {
    ImagePairSum out = fresh();
    detail::addImagePairs(cell, pairs, 0, pairs.size(), gradient, strain, kernel, weight, out);
    return out;
  }
  std::vector<ImagePairSum> part(static_cast<std::size_t>(threads));
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num(), nt = omp_get_num_threads();
    const std::size_t lo = pairs.size() * t / nt, hi = pairs.size() * (t + 1) / nt;
    ImagePairSum s = fresh();
    detail::addImagePairs(cell, pairs, lo, hi, gradient, strain, kernel, weight, s);
    part[static_cast<std::size_t>(t)] = std::move(s);
  }
  ImagePairSum out = fresh();
  for (const ImagePairSum& s : part) {
    if (gradient && s.gradient.size()) out.gradient += s.gradient;
    out.energy += s.energy;
    out.dTranslation += s.dTranslation;
    out.dTwist += s.dTwist;
  }
  return out;
}

// Derivatives (and energy) of 1/2 sum_ij w_ij M_ij: gradient and strain.
template <class Kernel>
ImagePairSum imagePairDerivatives(const objective::ObjectiveCell& cell,
                                  const objective::ImageList& images,
                                  const Eigen::MatrixXd& weights, Kernel&& kernel) {
  return imagePairSum(cell, images, true, true, kernel,
                      [&weights](int i, int j) { return weights(i, j); });
}

}  // namespace mesochain::dftb
