#include "mdem/contacts/face_contact.hpp"

#include <cmath>

#include "mdem/units.hpp"

namespace mesochain::mdem {

namespace {
// Quintic smooth step P(x) = 10x^3 - 15x^4 + 6x^5 on [0, 1] (0 below, 1 above), C2, and P'.
double smoothStep(double x, double* slope) {
  if (x <= 0.0) return *slope = 0.0, 0.0;
  if (x >= 1.0) return *slope = 0.0, 1.0;
  const double x2 = x * x;
  *slope = 30.0 * x2 * (1.0 - x) * (1.0 - x);
  return x2 * x * (10.0 - 15.0 * x + 6.0 * x2);
}

// s(x; a): 1 for |x| <= a - delta, 0 for |x| >= a + delta, C2 ramp between; and ds/dx.
double edgeRamp(double x, double a, double delta, double* dsdx) {
  double slope;
  const double p = smoothStep((std::abs(x) - a + delta) / (2.0 * delta), &slope);
  *dsdx = -slope / (2.0 * delta) * (x < 0.0 ? -1.0 : 1.0);
  return 1.0 - p;
}

// (E1) without switch or wall.
double wallEnergy(const LennardJones& lj, double z, double* derivative) {
  const double pre = 2.0 * units::kPi * lj.epsilon * lj.surfaceDensity * lj.surfaceDensity * lj.sigma * lj.sigma;
  const double s = lj.sigma / z, s2 = s * s, s4 = s2 * s2, s10 = s4 * s4 * s2;
  *derivative = pre * (-4.0 * s10 + 4.0 * s4) / z;
  return pre * (0.4 * s10 - s4);
}
}  // namespace

BrickFace brickFace(const Vec3& centre, const Quat& q, double width, double length) {
  BrickFace f;
  f.centre = centre;
  f.normal = rotate(q, Vec3::UnitX());
  f.widthAxis = rotate(q, Vec3::UnitY());
  f.lengthAxis = rotate(q, Vec3::UnitZ());
  f.halfWidth = 0.5 * width, f.halfLength = 0.5 * length;
  return f;
}

FaceContactModel::FaceContactModel(const FaceContactSpec& spec) : spec_(spec) {
  const QuadratureRule gl = gaussLegendre(spec.points);
  for (int p = 0; p < spec.panels; ++p) {
    const double lo = -1.0 + 2.0 * p / spec.panels, half = 1.0 / spec.panels;
    for (std::size_t k = 0; k < gl.x.size(); ++k) {
      rule_.x.push_back(lo + half * (1.0 + gl.x[k]));
      rule_.w.push_back(half * gl.w[k]);
    }
  }
  zWall_ = 0.7 * spec.lj.sigma;
  eWall_ = wallEnergy(spec.lj, zWall_, &dWall_);
}

double FaceContactModel::layerPairEnergy(double z, double* derivative) const {
  if (z >= spec_.cutoffGap) return *derivative = 0.0, 0.0;
  if (z < zWall_) return *derivative = dWall_, eWall_ + dWall_ * (z - zWall_);
  double de;
  const double e = wallEnergy(spec_.lj, z, &de);
  const double span = spec_.cutoffGap - spec_.switchGap;
  double slope;
  const double sw = 1.0 - smoothStep((z - spec_.switchGap) / span, &slope);
  *derivative = de * sw - e * slope / span;
  return e * sw;
}

double FaceContactModel::bilayerEnergy(double d, double* derivative) const {
  const double a = std::abs(d), t = spec_.layerSpacing;
  double d1, d2, d3;
  const double f = layerPairEnergy(a - t, &d1) + 2.0 * layerPairEnergy(a, &d2) + layerPairEnergy(a + t, &d3);
  *derivative = (d1 + 2.0 * d2 + d3) * (d < 0.0 ? -1.0 : 1.0);
  return f;
}

double FaceContactModel::interactionRange(const BrickFace& a, const BrickFace& b) const {
  const double ra = std::hypot(a.halfWidth, a.halfLength);
  const double d = spec_.edgeWidth, rb = std::hypot(b.halfWidth + d, b.halfLength + d);
  return ra + std::hypot(rb, cutoffDistance());
}

ContactPairResult FaceContactModel::evaluate(const BrickFace& a, const BrickFace& b) const {
  ContactPairResult r;
  const double dc = cutoffDistance(), delta = spec_.edgeWidth;
  const double uMax = b.halfWidth + delta, vMax = b.halfLength + delta;
  Vec3 gradR = Vec3::Zero();                  // dE/d(x_a) = -dE/d(x_b)
  Vec3 gradY = Vec3::Zero(), gradZ = Vec3::Zero();  // dE/d(width, length axes of a)
  Vec3 gradN = Vec3::Zero(), gradU = Vec3::Zero(), gradV = Vec3::Zero();  // of b's axes
  const double area = a.halfWidth * a.halfLength;
  const Vec3 rel0 = a.centre - b.centre;
  for (std::size_t i = 0; i < rule_.x.size(); ++i) {
    const double y = a.halfWidth * rule_.x[i];
    const Vec3 relY = rel0 + y * a.widthAxis;
    for (std::size_t j = 0; j < rule_.x.size(); ++j) {
      const double z = a.halfLength * rule_.x[j];
      const Vec3 rel = relY + z * a.lengthAxis;  // p - x_b
      const double g = rel.dot(b.normal);
      if (std::abs(g) >= dc) continue;
      const double u = rel.dot(b.widthAxis), v = rel.dot(b.lengthAxis);
      if (std::abs(u) >= uMax || std::abs(v) >= vMax) continue;
      double su_, sv_, df;
      const double su = edgeRamp(u, b.halfWidth, delta, &su_), sv = edgeRamp(v, b.halfLength, delta, &sv_);
      const double f = bilayerEnergy(g, &df);
      const double w = area * rule_.w[i] * rule_.w[j], cover = su * sv;
      r.energy += w * cover * f;
      // dE_q/d(rel) = S f' n_b + f (s_u' s_v e_u + s_u s_v' e_v)
      const double gg = w * cover * df, gu = w * f * su_ * sv, gv = w * f * su * sv_;
      const Vec3 gRel = gg * b.normal + gu * b.widthAxis + gv * b.lengthAxis;
      gradR += gRel;
      gradY += y * gRel, gradZ += z * gRel;
      gradN += gg * rel, gradU += gu * rel, gradV += gv * rel;
    }
  }
  r.forceA = -gradR;
  r.forceB = gradR;
  r.torqueA = -(a.widthAxis.cross(gradY) + a.lengthAxis.cross(gradZ));
  r.torqueB = -(b.normal.cross(gradN) + b.widthAxis.cross(gradU) + b.lengthAxis.cross(gradV));
  return r;
}

}  // namespace mesochain::mdem
