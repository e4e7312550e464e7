#include "dftb/sk_rotation.hpp"

namespace mesochain::dftb {

void skBlock(const Eigen::Vector3d& d, const SkRadial& v, int nA, int nB, OrbitalBlock& block) {
  block.setZero();
  const double r = d.norm();
  const Eigen::Vector3d e = d / r;
  block(0, 0) = v.ss;
  if (nB > 1) {
    for (int a = 0; a < 3; ++a) block(0, 1 + a) = e(a) * v.sp;
  }
  if (nA > 1) {
    for (int a = 0; a < 3; ++a) block(1 + a, 0) = -e(a) * v.ps;
  }
  if (nA > 1 && nB > 1) {
    const double diff = v.ppSigma - v.ppPi;
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        block(1 + a, 1 + b) = e(a) * e(b) * diff + (a == b ? v.ppPi : 0.0);
      }
    }
  }
}

void skBlockWithDerivatives(const Eigen::Vector3d& d, const SkRadial& v, const SkRadial& dv,
                            int nA, int nB, OrbitalBlock& block, OrbitalBlock dblock[3]) {
  skBlock(d, v, nA, nB, block);
  const double r = d.norm();
  const Eigen::Vector3d e = d / r;
  // de(a, c) = d e_a / d d_c
  const Eigen::Matrix3d de = (Eigen::Matrix3d::Identity() - e * e.transpose()) / r;
  const double diff = v.ppSigma - v.ppPi;
  const double ddiff = dv.ppSigma - dv.ppPi;
  for (int c = 0; c < 3; ++c) {
    OrbitalBlock& g = dblock[c];
    g.setZero();
    g(0, 0) = dv.ss * e(c);
    if (nB > 1) {
      for (int a = 0; a < 3; ++a) g(0, 1 + a) = de(a, c) * v.sp + e(a) * e(c) * dv.sp;
    }
    if (nA > 1) {
      for (int a = 0; a < 3; ++a) g(1 + a, 0) = -(de(a, c) * v.ps + e(a) * e(c) * dv.ps);
    }
    if (nA > 1 && nB > 1) {
      for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) {
          const double angular = de(a, c) * e(b) + e(a) * de(b, c);
          g(1 + a, 1 + b) = angular * diff + e(a) * e(b) * e(c) * ddiff +
                            (a == b ? dv.ppPi * e(c) : 0.0);
        }
      }
    }
  }
}

}  // namespace mesochain::dftb
