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

// The derivation above with s_a + Delta = x_b + s_b - x_a (the arm of G about x_a).
BondForces bondForces(const Bond& bond, const Vec3& xa, const Quat& qa, const Vec3& xb,
                      const Quat& qb) {
  const Quat fa = qa * bond.frameA;
  const Quat fb = qb * bond.frameB;
  const Mat3 ra = toMatrix(fa);  // bond frame of a -> world
  const Vec3 sb = rotate(qb, bond.anchorB);
  const Vec3 arm = (xb + sb) - xa;
  const Vec3 d = ra.transpose() * arm - bond.anchorAInBondFrame;

  BondForces r;
  const RotationVector rel = trackedLogWithJacobian(conj(fa) * fb, bond.theta);
  r.theta = rel.theta;

  const double kna = bond.k.kn * bond.section.area;
  const double ksa = bond.k.ks * bond.section.area;
  const Vec3 gradD(ksa * d.x(), ksa * d.y(), kna * d.z());
  const Vec3 gradTheta(bond.k.kn * bond.section.ix * rel.theta.x(),
                       bond.k.kn * bond.section.iy * rel.theta.y(),
                       bond.k.ks * bond.section.j * rel.theta.z());

  const Vec3 g = ra * gradD;
  const Vec3 w = ra * inverseLeftJacobianTransposeApply(rel, gradTheta);
  r.forceA = g;
  r.forceB = -g;
  r.torqueA = arm.cross(g) + w;
  r.torqueB = -sb.cross(g) - w;
  return r;
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
