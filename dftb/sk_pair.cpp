#include "dftb/sk_pair.hpp"

#include "common/errors.hpp"
#include "dftb/sk_rotation.hpp"

namespace mesochain::dftb {

namespace {

int orbitalCount(int l, const std::string& source) {
  if (l == 0) return 1;
  if (l == 1) return 4;
  throw InputError(source, "", "highest shell " + std::to_string(l), "s (0) or p (1)");
}

SkRadial pick(const double* x, int offset) {
  return {x[offset + 0], x[offset + 1], x[offset + 2], x[offset + 3], x[offset + 4]};
}

}  // namespace

SkGrid SkPairIntegrals::makeGrid(const SkfTable& ab, const SkfTable& ba) {
  const std::string source = ab.path == ba.path ? ab.path : ab.path + " / " + ba.path;
  // DFTB+ (parser.F90, checkSKCompElec) requires equal grids for A-B and B-A.
  if (ab.gridSpacing != ba.gridSpacing || ab.rows() != ba.rows()) {
    throw InputError(source, "grid of " + ba.path + ": spacing " +
                                 std::to_string(ba.gridSpacing) + ", " +
                                 std::to_string(ba.rows()) + " rows, and of " + ab.path +
                                 ": spacing " + std::to_string(ab.gridSpacing) + ", " +
                                 std::to_string(ab.rows()) + " rows; expected the same grid");
  }
  Eigen::MatrixXd t(ab.rows(), kColumns);
  const Eigen::MatrixXd* mats[2][2] = {{&ab.ham, &ba.ham}, {&ab.over, &ba.over}};
  for (int k = 0; k < 2; ++k) {
    const Eigen::MatrixXd& abm = *mats[k][0];
    const Eigen::MatrixXd& bam = *mats[k][1];
    t.col(5 * k + 0) = abm.col(kSkfSsSigma);
    t.col(5 * k + 1) = abm.col(kSkfSpSigma);  // s on A, p on B
    t.col(5 * k + 2) = bam.col(kSkfSpSigma);  // s on B, p on A
    t.col(5 * k + 3) = abm.col(kSkfPpSigma);
    t.col(5 * k + 4) = abm.col(kSkfPpPi);
  }
  return SkGrid(ab.gridSpacing, std::move(t), source);
}

SkPairIntegrals::SkPairIntegrals(const SkfTable& ab, const SkfTable& ba, int lA, int lB)
    : nA_(orbitalCount(lA, ab.path)), nB_(orbitalCount(lB, ab.path)), grid_(makeGrid(ab, ba)) {}

void SkPairIntegrals::blocks(const Eigen::Vector3d& d, OrbitalBlock& h, OrbitalBlock& s) const {
  double v[kColumns], dv[kColumns];
  grid_.evaluate(d.norm(), v, dv);
  skBlock(d, pick(v, 0), nA_, nB_, h);
  skBlock(d, pick(v, 5), nA_, nB_, s);
}

void SkPairIntegrals::blocksWithDerivatives(const Eigen::Vector3d& d, OrbitalBlock& h,
                                            OrbitalBlock& s, OrbitalBlock dh[3],
                                            OrbitalBlock ds[3]) const {
  double v[kColumns], dv[kColumns];
  grid_.evaluate(d.norm(), v, dv);
  skBlockWithDerivatives(d, pick(v, 0), pick(dv, 0), nA_, nB_, h, dh);
  skBlockWithDerivatives(d, pick(v, 5), pick(dv, 5), nA_, nB_, s, ds);
}

}  // namespace mesochain::dftb
