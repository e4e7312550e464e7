#include "dftb/density_matrix.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "dftb/lapack.hpp"

namespace mesochain::dftb {

using cd = std::complex<double>;

DensityBlockPlan::DensityBlockPlan(const OrbitalLayout& layout, const objective::ImageList& images,
                                   int groupOrbitals) {
  const int atoms = static_cast<int>(layout.offset.size());
  std::vector<int> groupOfAtom(atoms);
  int groups = 0;
  for (int a = 0; a < atoms; ++a) {
    if (groupStart.empty() || layout.offset[a] - groupStart.back() >= groupOrbitals) {
      groupStart.push_back(layout.offset[a]);
      ++groups;
    }
    groupOfAtom[a] = groups - 1;
  }
  groupStart.push_back(layout.total);
  groupOfOrbital.resize(layout.total);
  for (int g = 0; g < groups; ++g)
    std::fill(groupOfOrbital.begin() + groupStart[g], groupOfOrbital.begin() + groupStart[g + 1],
              g);
  std::vector<char> needed(static_cast<std::size_t>(groups) * groups, 0);
  for (int g = 0; g < groups; ++g) needed[g * groups + g] = 1;
  for (const objective::ImagePair& pair : images.pairs()) {
    const int r = groupOfAtom[pair.j], c = groupOfAtom[pair.i];
    needed[std::max(r, c) * groups + std::min(r, c)] = 1;
  }
  double elements = 0;
  for (int r = 0; r < groups; ++r)
    for (int c = 0; c <= r; ++c)
      if (needed[r * groups + c]) {
        blocks.emplace_back(r, c);
        elements += double(groupStart[r + 1] - groupStart[r]) * (groupStart[c + 1] - groupStart[c]);
      }
  fraction = layout.total > 0 ? elements / (double(layout.total) * layout.total) : 0.0;
}

template <class Scalar>
void formDensityMatrices(const DensityBlockPlan& plan, MatrixMap<Scalar> c, MatrixMap<Scalar> y,
                         int m, const Eigen::VectorXd& f, const Eigen::VectorXd& e,
                         MatrixMap<Scalar> rho, MatrixMap<Scalar> rhoE) {
  const int n = static_cast<int>(rho.rows());
  for (int s = 0; s < m; ++s) {
    c.col(s) *= std::sqrt(f[s]);  // X
    y.col(s) = e[s] * c.col(s);   // Y = X diag(e)
  }
  for (const auto& [r, col] : plan.blocks) {
    const int r0 = plan.groupStart[r], nr = plan.groupStart[r + 1] - r0;
    const int c0 = plan.groupStart[col], nc = plan.groupStart[col + 1] - c0;
    if (m <= 0) {
      rho.block(r0, c0, nr, nc).setZero();
      rhoE.block(r0, c0, nr, nc).setZero();
      continue;
    }
    const long at = r0 + long(c0) * n;  // the block's first element
    lapack::gemmAdjoint(nr, nc, m, c.data() + r0, c.data() + c0, rho.data() + at, n);
    lapack::gemmAdjoint(nr, nc, m, y.data() + r0, c.data() + c0, rhoE.data() + at, n);
  }
}

namespace {
inline double conjugate(double x) { return x; }
inline cd conjugate(cd x) { return std::conj(x); }
}  // namespace

template <class Scalar>
void foldDensityBlocks(const DensityBlockPlan& plan, const OrbitalLayout& layout,
                       const objective::ImageList& images, const objective::HelicalKGrid& grid,
                       const objective::HelicalKPoint& k, double weight,
                       const MatrixMap<Scalar>& rho, const MatrixMap<Scalar>& rhoE,
                       std::vector<OrbitalBlock>& p, std::vector<OrbitalBlock>& w) {
  const auto& pairs = images.pairs();
  for (std::size_t q = 0; q < pairs.size(); ++q) {
    const objective::ImagePair& pair = pairs[q];
    const int oi = layout.offset[pair.i], oj = layout.offset[pair.j];
    const int ni = layout.count[pair.i], nj = layout.count[pair.j];
    p[q].setZero();
    w[q].setZero();
    // The Bloch factor exp(i theta_g); +-1 at a k-point with real phases.
    const double theta = grid.phase(k, pair.g);
    for (int b = 0; b < nj; ++b)
      for (int a = 0; a < ni; ++a) {
        const int r = oj + b, col = oi + a;
        const bool formed = plan.groupOfOrbital[r] >= plan.groupOfOrbital[col];
        const Scalar x = formed ? rho(r, col) : conjugate(rho(col, r));
        const Scalar y = formed ? rhoE(r, col) : conjugate(rhoE(col, r));
        if constexpr (std::is_same_v<Scalar, cd>) {
          const cd phase = weight * std::polar(1.0, theta);
          p[q](a, b) = (phase * x).real();
          w[q](a, b) = (phase * y).real();
        } else {
          const double phase = weight * std::cos(theta);
          p[q](a, b) = phase * x;
          w[q](a, b) = phase * y;
        }
      }
  }
}

template void formDensityMatrices<double>(const DensityBlockPlan&, MatrixMap<double>,
                                          MatrixMap<double>, int, const Eigen::VectorXd&,
                                          const Eigen::VectorXd&, MatrixMap<double>,
                                          MatrixMap<double>);
template void formDensityMatrices<cd>(const DensityBlockPlan&, MatrixMap<cd>, MatrixMap<cd>, int,
                                      const Eigen::VectorXd&, const Eigen::VectorXd&,
                                      MatrixMap<cd>, MatrixMap<cd>);
template void foldDensityBlocks<double>(const DensityBlockPlan&, const OrbitalLayout&,
                                        const objective::ImageList&,
                                        const objective::HelicalKGrid&,
                                        const objective::HelicalKPoint&, double,
                                        const MatrixMap<double>&, const MatrixMap<double>&,
                                        std::vector<OrbitalBlock>&, std::vector<OrbitalBlock>&);
template void foldDensityBlocks<cd>(const DensityBlockPlan&, const OrbitalLayout&,
                                    const objective::ImageList&, const objective::HelicalKGrid&,
                                    const objective::HelicalKPoint&, double, const MatrixMap<cd>&,
                                    const MatrixMap<cd>&, std::vector<OrbitalBlock>&,
                                    std::vector<OrbitalBlock>&);

}  // namespace mesochain::dftb
