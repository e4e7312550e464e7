#include "mdem/parallel_bond.hpp"

#include "mdem/units.hpp"

namespace mesochain::mdem {

BondSection BondSection::rectangle(double alongX, double alongY) {
  BondSection s;
  s.area = alongX * alongY;
  s.ix = alongX * alongY * alongY * alongY / 12.0;
  s.iy = alongY * alongX * alongX * alongX / 12.0;
  s.j = s.ix + s.iy;
  return s;
}

BondSection BondSection::disc(double r) {
  BondSection s;
  const double r2 = r * r;
  s.area = units::kPi * r2;
  s.ix = s.iy = 0.25 * units::kPi * r2 * r2;
  s.j = 0.5 * units::kPi * r2 * r2;
  return s;
}

Bond makeBond(int a, int b, const Bodies& bodies, const BondStiffness& k, const BondSection& s) {
  Bond bond;
  bond.a = a, bond.b = b, bond.k = k, bond.section = s;
  const Vec3& xa = bodies.position[a];
  const Vec3& xb = bodies.position[b];
  const Quat& qa = bodies.orientation[a];
  const Quat& qb = bodies.orientation[b];
  const Vec3 centre = 0.5 * (xa + xb);
  bond.anchorA = rotateInverse(qa, centre - xa);
  bond.anchorB = rotateInverse(qb, centre - xb);
  bond.restLength = (xb - xa).norm();
  // Bond frame in a's body frame: z along the centre line, x from a's thickness axis.
  const Vec3 ez = rotateInverse(qa, (xb - xa) / bond.restLength);
  Vec3 ex = Vec3::UnitX() - ez.x() * ez;
  if (ex.norm() < 1e-6) ex = Vec3::UnitY() - ez.y() * ez;
  ex.normalize();
  Mat3 f;
  f.col(0) = ex, f.col(1) = ez.cross(ex), f.col(2) = ez;
  bond.frameA = fromMatrix(f);
  bond.frameB = normalized(conj(qb) * qa * bond.frameA);
  bond.anchorAInBondFrame = rotateInverse(bond.frameA, bond.anchorA);
  return bond;
}

// Derivation of the forces (R' = R_a' the bond frame of a in the world, G = R' dE/dd,
// w = J_l^{-T}(theta) dE/dtheta, s = R q r the world anchor offsets, Delta = p_b - p_a):
//  * translation of b by u: d -> d + R'^T u           => F_b = -G,  F_a = +G.
//  * rotation of b by phi (left, world): p_b moves by phi x s_b, and R_b' -> exp[phi] R_b' so
//    R_rel -> exp[R'^T phi] R_rel, theta -> theta + J_l^{-1} R'^T phi
//                                                     => T_b = -s_b x G - R' w.
//  * rotation of a by phi: p_a moves by phi x s_a, R'^T -> R'^T exp[-phi] changes d by
//    -R'^T (phi x Delta), R_rel -> exp[-R'^T phi] R_rel
//                                                     => T_a = (s_a + Delta) x G + R' w.
// Sum of moments about the origin: x_a x G + (p_b - x_a) x G - x_b x G - (p_b - x_b) x G = 0.
BondResult evaluateBond(const Bond& bond, const Vec3& xa, const Quat& qa, const Vec3& xb,
                        const Quat& qb) {
  const Quat fa = qa * bond.frameA;
  const Quat fb = qb * bond.frameB;
  const Vec3 sa = rotate(qa, bond.anchorA);
  const Vec3 sb = rotate(qb, bond.anchorB);
  const Vec3 delta = (xb + sb) - (xa + sa);

  BondResult r;
  r.d = rotateInverse(fa, delta);
  r.theta = trackedLog(conj(fa) * fb, bond.theta);

  const double kna = bond.k.kn * bond.section.area;
  const double ksa = bond.k.ks * bond.section.area;
  const Vec3 gradD(ksa * r.d.x(), ksa * r.d.y(), kna * r.d.z());
  const Vec3 gradTheta(bond.k.kn * bond.section.ix * r.theta.x(),
                       bond.k.kn * bond.section.iy * r.theta.y(),
                       bond.k.ks * bond.section.j * r.theta.z());

  r.energy.stretching = 0.5 * kna * r.d.z() * r.d.z();
  r.energy.shearing = 0.5 * ksa * (r.d.x() * r.d.x() + r.d.y() * r.d.y());
  r.energy.twisting = 0.5 * gradTheta.z() * r.theta.z();
  r.energy.bending = 0.5 * (gradTheta.x() * r.theta.x() + gradTheta.y() * r.theta.y());

  const Vec3 g = rotate(fa, gradD);
  const Vec3 w = rotate(fa, inverseLeftJacobianTransposeApply(r.theta, gradTheta));
  r.forceA = g;
  r.forceB = -g;
  r.torqueA = (sa + delta).cross(g) + w;
  r.torqueB = -sb.cross(g) - w;
  return r;
}

namespace {
// The forces kernel for N bonds at once: every scalar of the derivation above as an array over
// the lanes (bonds), each written with the same operations in the same order as for one bond,
// so the compiler packs two lanes into one two-wide operation and every bond's result is bit
// for bit that of N = 1 (test MdemParallelBond.PairedKernelEqualsTwoSingleKernelsBitForBit).
// s_a + Delta = x_b + s_b - x_a is the arm of G about x_a; R' = R(q_a frameA) is formed once as a
// matrix, d = R'^T arm - R(frameA)^T anchorA.
template <int N>
[[gnu::always_inline]] inline void bondForcesLanes(const Bond* const (&bond)[N], const Vec3* const (&xa)[N],
                                                   const Quat* const (&qa)[N], const Vec3* const (&xb)[N],
                                                   const Quat* const (&qb)[N], BondForces* const (&out)[N]) {
  // fa = q_a frameA, fb = q_b frameB (w, x, y, z)
  double fa[4][N], fb[4][N];
  for (int k = 0; k < N; ++k) {
    const Quat a = *qa[k] * bond[k]->frameA, b = *qb[k] * bond[k]->frameB;
    fa[0][k] = a.w, fa[1][k] = a.x, fa[2][k] = a.y, fa[3][k] = a.z;
    fb[0][k] = b.w, fb[1][k] = b.x, fb[2][k] = b.y, fb[3][k] = b.z;
  }
  // ra = R(fa) (toMatrix), row by row
  double ra[3][3][N];
  for (int k = 0; k < N; ++k) {
    const double w = fa[0][k], x = fa[1][k], y = fa[2][k], z = fa[3][k];
    const double xx = x * x, yy = y * y, zz = z * z, xy = x * y, xz = x * z, yz = y * z;
    const double wx = w * x, wy = w * y, wz = w * z;
    ra[0][0][k] = 1.0 - 2.0 * (yy + zz), ra[0][1][k] = 2.0 * (xy - wz), ra[0][2][k] = 2.0 * (xz + wy);
    ra[1][0][k] = 2.0 * (xy + wz), ra[1][1][k] = 1.0 - 2.0 * (xx + zz), ra[1][2][k] = 2.0 * (yz - wx);
    ra[2][0][k] = 2.0 * (xz - wy), ra[2][1][k] = 2.0 * (yz + wx), ra[2][2][k] = 1.0 - 2.0 * (xx + yy);
  }
  // sb = rotate(q_b, anchorB) = v + w t + u x t with t = 2 u x v; arm = (x_b + s_b) - x_a;
  // d = ra^T arm - anchorAInBondFrame
  double sb[3][N], arm[3][N], d[3][N];
  for (int k = 0; k < N; ++k) {
    const Quat& q = *qb[k];
    const Vec3& v = bond[k]->anchorB;
    const double t0 = 2.0 * (q.y * v[2] - q.z * v[1]), t1 = 2.0 * (q.z * v[0] - q.x * v[2]),
                 t2 = 2.0 * (q.x * v[1] - q.y * v[0]);
    sb[0][k] = (v[0] + q.w * t0) + (q.y * t2 - q.z * t1);
    sb[1][k] = (v[1] + q.w * t1) + (q.z * t0 - q.x * t2);
    sb[2][k] = (v[2] + q.w * t2) + (q.x * t1 - q.y * t0);
    for (int c = 0; c < 3; ++c) arm[c][k] = ((*xb[k])[c] + sb[c][k]) - (*xa[k])[c];
  }
  for (int k = 0; k < N; ++k)
    for (int c = 0; c < 3; ++c)
      d[c][k] = (ra[0][c][k] * arm[0][k] + ra[1][c][k] * arm[1][k] + ra[2][c][k] * arm[2][k]) -
                bond[k]->anchorAInBondFrame[c];
  // The relative rotation conj(fa) fb and its tracked log (trackedLogWithJacobian: the series
  // branch in every lane, the general case where a lane is outside it).
  double rel[4][N], theta[3][N], beta[N];
  bool general[N];
  bool anyGeneral = false;
  for (int k = 0; k < N; ++k) {
    const Quat r = conj(Quat{fa[0][k], fa[1][k], fa[2][k], fa[3][k]}) * Quat{fb[0][k], fb[1][k], fb[2][k], fb[3][k]};
    rel[0][k] = r.w, rel[1][k] = r.x, rel[2][k] = r.y, rel[3][k] = r.z;
  }
  for (int k = 0; k < N; ++k) {
    const double sign = rel[0][k] < 0.0 ? -1.0 : 1.0;
    const double w = sign * rel[0][k];
    const double s2 = rel[1][k] * rel[1][k] + rel[2][k] * rel[2][k] + rel[3][k] * rel[3][k];
    general[k] = !logSeriesHolds(w, s2, bond[k]->theta);
    anyGeneral = anyGeneral || general[k];
    const LogSeries l = logSeries(sign, w, s2);  // inf or NaN in a general lane: replaced below
    for (int c = 0; c < 3; ++c) theta[c][k] = l.scale * rel[1 + c][k];
    beta[k] = l.beta;
  }
  if (anyGeneral)
    for (int k = 0; k < N; ++k)
      if (general[k]) {
        const RotationVector r =
            trackedLogWithJacobianGeneral(Quat{rel[0][k], rel[1][k], rel[2][k], rel[3][k]}, bond[k]->theta);
        for (int c = 0; c < 3; ++c) theta[c][k] = r.theta[c];
        beta[k] = r.beta;
      }
  // G = ra gradD and W = ra J_l^{-T}(theta) gradTheta (inverseLeftJacobianTransposeApply).
  double gradD[3][N], m[3][N], g[3][N], w[3][N];
  for (int k = 0; k < N; ++k) {
    const Bond& b = *bond[k];
    const double kna = b.k.kn * b.section.area, ksa = b.k.ks * b.section.area;
    gradD[0][k] = ksa * d[0][k], gradD[1][k] = ksa * d[1][k], gradD[2][k] = kna * d[2][k];
    const double gt0 = b.k.kn * b.section.ix * theta[0][k], gt1 = b.k.kn * b.section.iy * theta[1][k],
                 gt2 = b.k.ks * b.section.j * theta[2][k];
    const double th0 = theta[0][k], th1 = theta[1][k], th2 = theta[2][k];
    const double tm0 = th1 * gt2 - th2 * gt1, tm1 = th2 * gt0 - th0 * gt2, tm2 = th0 * gt1 - th1 * gt0;
    m[0][k] = (gt0 + 0.5 * tm0) + beta[k] * (th1 * tm2 - th2 * tm1);
    m[1][k] = (gt1 + 0.5 * tm1) + beta[k] * (th2 * tm0 - th0 * tm2);
    m[2][k] = (gt2 + 0.5 * tm2) + beta[k] * (th0 * tm1 - th1 * tm0);
  }
  for (int k = 0; k < N; ++k)
    for (int c = 0; c < 3; ++c) {
      g[c][k] = ra[c][0][k] * gradD[0][k] + ra[c][1][k] * gradD[1][k] + ra[c][2][k] * gradD[2][k];
      w[c][k] = ra[c][0][k] * m[0][k] + ra[c][1][k] * m[1][k] + ra[c][2][k] * m[2][k];
    }
  // F_a = G, F_b = -G, T_a = arm x G + W, T_b = -s_b x G - W.
  for (int k = 0; k < N; ++k) {
    BondForces& r = *out[k];
    r.theta = Vec3(theta[0][k], theta[1][k], theta[2][k]);
    r.forceA = Vec3(g[0][k], g[1][k], g[2][k]);
    r.forceB = Vec3(-g[0][k], -g[1][k], -g[2][k]);
    r.torqueA = Vec3((arm[1][k] * g[2][k] - arm[2][k] * g[1][k]) + w[0][k],
                     (arm[2][k] * g[0][k] - arm[0][k] * g[2][k]) + w[1][k],
                     (arm[0][k] * g[1][k] - arm[1][k] * g[0][k]) + w[2][k]);
    r.torqueB = Vec3(-(sb[1][k] * g[2][k] - sb[2][k] * g[1][k]) - w[0][k],
                     -(sb[2][k] * g[0][k] - sb[0][k] * g[2][k]) - w[1][k],
                     -(sb[0][k] * g[1][k] - sb[1][k] * g[0][k]) - w[2][k]);
  }
}
}  // namespace

BondForces bondForces(const Bond& bond, const Vec3& xa, const Quat& qa, const Vec3& xb,
                      const Quat& qb) {
  BondForces r;
  bondForcesLanes<1>({&bond}, {&xa}, {&qa}, {&xb}, {&qb}, {&r});
  return r;
}

void bondForcesPair(const Bond& b0, const Bond& b1, const Bodies& s, BondForces& r0, BondForces& r1) {
  bondForcesLanes<2>({&b0, &b1}, {&s.position[b0.a], &s.position[b1.a]}, {&s.orientation[b0.a], &s.orientation[b1.a]},
                     {&s.position[b0.b], &s.position[b1.b]}, {&s.orientation[b0.b], &s.orientation[b1.b]},
                     {&r0, &r1});
}

Eigen::Matrix<double, 12, 12> linearStiffness(const Bond& bond, const Bodies& bodies) {
  const Quat& qa = bodies.orientation[bond.a];
  const Mat3 rt = toMatrix(qa * bond.frameA).transpose();  // world -> bond frame
  const Vec3 sa = rotate(qa, bond.anchorA);
  const Vec3 sb = rotate(bodies.orientation[bond.b], bond.anchorB);
  // B maps the 12 DOFs to (d, theta) in the bond frame; phi x s = -[s]x phi.
  Eigen::Matrix<double, 6, 12> bmat = Eigen::Matrix<double, 6, 12>::Zero();
  bmat.block<3, 3>(0, 0) = -rt;
  bmat.block<3, 3>(0, 3) = rt * skew(sa);
  bmat.block<3, 3>(0, 6) = rt;
  bmat.block<3, 3>(0, 9) = -rt * skew(sb);
  bmat.block<3, 3>(3, 3) = -rt;
  bmat.block<3, 3>(3, 9) = rt;
  Eigen::Matrix<double, 6, 1> dvec;
  const double a = bond.section.area;
  dvec << bond.k.ks * a, bond.k.ks * a, bond.k.kn * a, bond.k.kn * bond.section.ix,
      bond.k.kn * bond.section.iy, bond.k.ks * bond.section.j;
  return bmat.transpose() * dvec.asDiagonal() * bmat;
}

BondLoad bondLoad(const Bond& bond, const Vec3& d, const Vec3& theta) {
  const BondSection& c = bond.section;
  BondLoad l;
  l.normalForce = bond.k.kn * c.area * d.z();
  l.shearForce = bond.k.ks * c.area * std::hypot(d.x(), d.y());
  l.bendingMoment = bond.k.kn * std::hypot(c.ix * theta.x(), c.iy * theta.y());
  l.twistingMoment = bond.k.ks * c.j * std::abs(theta.z());
  return l;
}

}  // namespace mesochain::mdem
