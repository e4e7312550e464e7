#include "dftb/density_matrix.hpp"

#include <cmath>
#include <type_traits>

#include "dftb/lapack.hpp"

namespace mesochain::dftb {

using cd = std::complex<double>;

template <class Scalar>
void formDensityMatrices(MatrixMap<Scalar> c, int m, const Eigen::VectorXd& f,
                         const Eigen::VectorXd& e, MatrixMap<Scalar> rho, MatrixMap<Scalar> rhoE) {
  const int n = static_cast<int>(rho.rows());
  if (m <= 0) {
    rho.setZero();
    rhoE.setZero();
    return;
  }
  for (int s = 0; s < m; ++s) c.col(s) *= std::sqrt(f[s]);
  lapack::herk(n, m, 1.0, c.data(), 0.0, rho.data());  // rho = X X^+
  // The levels ascend: the first `negative` columns have e < 0.
  int negative = 0;
  while (negative < m && e[negative] < 0.0) ++negative;
  for (int s = 0; s < m; ++s) c.col(s) *= std::sqrt(std::abs(e[s]));
  if (negative > 0) lapack::herk(n, negative, -1.0, c.data(), 0.0, rhoE.data());
  if (negative < m)
    lapack::herk(n, m - negative, 1.0, c.col(negative).data(), negative > 0 ? 1.0 : 0.0,
                 rhoE.data());
}

namespace {
inline double conjugate(double x) { return x; }
inline cd conjugate(cd x) { return std::conj(x); }
}  // namespace

template <class Scalar>
void foldDensityBlocks(const OrbitalLayout& layout, const objective::ImageList& images,
                       const objective::HelicalKGrid& grid, const objective::HelicalKPoint& k,
                       double weight, const MatrixMap<Scalar>& rho, const MatrixMap<Scalar>& rhoE,
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
        const bool lower = r >= col;
        const Scalar x = lower ? rho(r, col) : conjugate(rho(col, r));
        const Scalar y = lower ? rhoE(r, col) : conjugate(rhoE(col, r));
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

template void formDensityMatrices<double>(MatrixMap<double>, int, const Eigen::VectorXd&,
                                          const Eigen::VectorXd&, MatrixMap<double>,
                                          MatrixMap<double>);
template void formDensityMatrices<cd>(MatrixMap<cd>, int, const Eigen::VectorXd&,
                                      const Eigen::VectorXd&, MatrixMap<cd>, MatrixMap<cd>);
template void foldDensityBlocks<double>(const OrbitalLayout&, const objective::ImageList&,
                                        const objective::HelicalKGrid&,
                                        const objective::HelicalKPoint&, double,
                                        const MatrixMap<double>&, const MatrixMap<double>&,
                                        std::vector<OrbitalBlock>&, std::vector<OrbitalBlock>&);
template void foldDensityBlocks<cd>(const OrbitalLayout&, const objective::ImageList&,
                                    const objective::HelicalKGrid&,
                                    const objective::HelicalKPoint&, double, const MatrixMap<cd>&,
                                    const MatrixMap<cd>&, std::vector<OrbitalBlock>&,
                                    std::vector<OrbitalBlock>&);

}  // namespace mesochain::dftb
