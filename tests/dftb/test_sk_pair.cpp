// Slater-Koster blocks: derivatives, rotational invariance, (A,B) versus (B,A), axis directions,
// and the heteronuclear file convention of DFTB+.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "dftb/sk_pair.hpp"
#include "dftb/skf_file.hpp"
#include "skf_test_util.hpp"

using namespace mesochain::dftb;
using namespace skftest;

namespace {

struct Tables {
  SkfTable cc = readSkfFile(pbc("C-C.skf"), true);
  SkfTable ch = readSkfFile(ob3("C-H.skf"), false);  // 3ob: C-H and H-C differ in the sp column
  SkfTable hc = readSkfFile(ob3("H-C.skf"), false);
};
const Tables& tables() {
  static const Tables t;
  return t;
}

Eigen::Matrix3d randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> n;
  const Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  return q.normalized().toRotationMatrix();
}

std::vector<Eigen::Vector3d> testVectors() {
  std::vector<Eigen::Vector3d> v = {{2.7, 0, 0}, {0, 2.7, 0}, {0, 0, 2.7}, {0, 0, -2.1},
                                    {-1.9, 0, 0}, {1.2, -1.7, 0.4}, {-0.3, 0.8, 3.9}};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int k = 0; k < 5; ++k) v.emplace_back(u(rng), u(rng), u(rng));
  v.emplace_back(7.0, 6.0, 5.0);  // |d| = 10.49: the last rows of the table
  v.emplace_back(0.0, 10.9, 0.0);  // in the tail beyond the last row (10.38)
  return v;
}

void expectDerivatives(const PairIntegrals& p, const Eigen::Vector3d& d) {
  OrbitalBlock h, s, dh[3], ds[3];
  p.blocksWithDerivatives(d, h, s, dh, ds);
  OrbitalBlock h0, s0;
  p.blocks(d, h0, s0);
  EXPECT_EQ(h, h0);
  EXPECT_EQ(s, s0);
  const double step = 1e-5;
  for (int c = 0; c < 3; ++c) {
    OrbitalBlock hp, sp, hm, sm;
    Eigen::Vector3d e = Eigen::Vector3d::Zero();
    e(c) = step;
    p.blocks(d + e, hp, sp);
    p.blocks(d - e, hm, sm);
    const OrbitalBlock fh = (hp - hm) / (2 * step), fs = (sp - sm) / (2 * step);
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) {
        EXPECT_NEAR(dh[c](i, j), fh(i, j), 1e-7 * (1 + std::abs(fh(i, j))))
            << "H d = " << d.transpose() << " c " << c << " (" << i << "," << j << ")";
        EXPECT_NEAR(ds[c](i, j), fs(i, j), 1e-7 * (1 + std::abs(fs(i, j))))
            << "S d = " << d.transpose() << " c " << c << " (" << i << "," << j << ")";
      }
    }
  }
}

}  // namespace

TEST(SkPair, DerivativesMatchFiniteDifferences) {
  const Tables& t = tables();
  const SkPairIntegrals cc(t.cc, t.cc, 1, 1), ch(t.ch, t.hc, 1, 0), hc(t.hc, t.ch, 0, 1);
  for (const Eigen::Vector3d& d : testVectors()) {
    expectDerivatives(cc, d);
    expectDerivatives(ch, d);
    expectDerivatives(hc, d);
  }
}

TEST(SkPair, RotationalInvariance) {
  const Tables& t = tables();
  const SkPairIntegrals cc(t.cc, t.cc, 1, 1), ch(t.ch, t.hc, 1, 0);
  std::mt19937 rng(11);
  for (int k = 0; k < 10; ++k) {
    const Eigen::Matrix3d q = randomRotation(rng);
    OrbitalBlock big = OrbitalBlock::Identity();
    big.block<3, 3>(1, 1) = q;
    for (const Eigen::Vector3d& d : testVectors()) {
      for (const PairIntegrals* p : {static_cast<const PairIntegrals*>(&cc),
                                     static_cast<const PairIntegrals*>(&ch)}) {
        OrbitalBlock h, s, hq, sq;
        p->blocks(d, h, s);
        p->blocks(q * d, hq, sq);
        EXPECT_LT((hq - big * h * big.transpose()).cwiseAbs().maxCoeff(), 1e-13);
        EXPECT_LT((sq - big * s * big.transpose()).cwiseAbs().maxCoeff(), 1e-13);
      }
    }
  }
}

TEST(SkPair, ReversedPairIsTransposeAtMinusD) {
  const Tables& t = tables();
  const SkPairIntegrals ch(t.ch, t.hc, 1, 0), hc(t.hc, t.ch, 0, 1), cc(t.cc, t.cc, 1, 1);
  for (const Eigen::Vector3d& d : testVectors()) {
    OrbitalBlock h1, s1, h2, s2;
    ch.blocks(d, h1, s1);
    hc.blocks(-d, h2, s2);
    EXPECT_LT((h1 - h2.transpose()).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_LT((s1 - s2.transpose()).cwiseAbs().maxCoeff(), 1e-15);
    cc.blocks(d, h1, s1);
    cc.blocks(-d, h2, s2);
    EXPECT_LT((h1 - h2.transpose()).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_LT((s1 - s2.transpose()).cwiseAbs().maxCoeff(), 1e-15);
  }
}

TEST(SkPair, AlongEachAxis) {
  const Tables& t = tables();
  const SkPairIntegrals cc(t.cc, t.cc, 1, 1);
  const double r = 2.66;  // row 133 of C-C.skf
  double v[10], dv[10];
  cc.radial(r, v, dv);
  EXPECT_NEAR(v[0], -2.861096914660e-01, 1e-13);  // H ss
  EXPECT_NEAR(v[8], -3.369019963390e-01, 1e-13);  // S pp sigma
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {1.0, -1.0}) {
      Eigen::Vector3d d = Eigen::Vector3d::Zero();
      d(axis) = sign * r;
      OrbitalBlock h, s;
      cc.blocks(d, h, s);
      for (int k = 0; k < 2; ++k) {
        const OrbitalBlock& b = k == 0 ? h : s;
        const double* x = v + 5 * k;  // ss sp ps pps ppp
        OrbitalBlock want = OrbitalBlock::Zero();
        want(0, 0) = x[0];
        want(0, 1 + axis) = sign * x[1];
        want(1 + axis, 0) = -sign * x[2];
        for (int a = 0; a < 3; ++a) want(1 + a, 1 + a) = (a == axis) ? x[3] : x[4];
        EXPECT_LT((b - want).cwiseAbs().maxCoeff(), 1e-15) << "axis " << axis << " " << sign;
      }
    }
  }
}

TEST(SkPair, HeteronuclearConventionOfDftbPlus) {
  // For the pair (C, H): <p_C | s_H> comes from the sp column of H-C.skf (s on H, p on C), with
  // the sign -e_a. In 3ob-3-1 the sp column of C-H.skf is identically zero, so any other choice
  // would give a zero block.
  const Tables& t = tables();
  EXPECT_EQ(t.ch.ham.col(kSkfSpSigma).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT(t.hc.over.col(kSkfSpSigma).cwiseAbs().maxCoeff(), 0.1);
  const SkPairIntegrals ch(t.ch, t.hc, 1, 0);
  const double r = 2.06;  // C-H bond length, row 103
  OrbitalBlock h, s;
  ch.blocks(Eigen::Vector3d(r, 0, 0), h, s);  // H at +x from C
  EXPECT_NEAR(s(1, 0), -t.hc.over(102, kSkfSpSigma), 1e-13);
  EXPECT_NEAR(h(1, 0), -t.hc.ham(102, kSkfSpSigma), 1e-13);
  EXPECT_NEAR(s(0, 0), t.ch.over(102, kSkfSsSigma), 1e-13);
  // Physical sign: the positive lobe of p_x on C points at H, so the overlap is positive.
  EXPECT_GT(s(1, 0), 0.3);
  // Only the s column of the C-H block is used; p_H does not exist.
  EXPECT_EQ(s.rightCols<3>().cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(h.bottomRows<3>().rightCols<3>().cwiseAbs().maxCoeff(), 0.0);
}

TEST(SkPair, IncompatibleGridsAreRefused) {
  const Tables& t = tables();
  const std::string msg = inputErrorOf([&] { SkPairIntegrals(t.ch, t.cc, 1, 1); });
  EXPECT_NE(msg.find("C-H.skf"), std::string::npos) << msg;
  EXPECT_NE(msg.find("C-C.skf"), std::string::npos) << msg;
}
