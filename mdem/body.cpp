#include "mdem/body.hpp"

#include "mdem/units.hpp"

namespace mesochain::mdem {

double ElementType::volume() const {
  if (shape == Shape::Brick) return thickness * width * length;
  return units::kPi * radius * radius * length;
}

Vec3 ElementType::principalInertia() const {
  const double m = mass, l2 = length * length;
  if (shape == Shape::Brick) {
    const double h2 = thickness * thickness, w2 = width * width;
    return {m * (w2 + l2) / 12.0, m * (h2 + l2) / 12.0, m * (h2 + w2) / 12.0};
  }
  const double r2 = radius * radius;
  const double ib = m * (3.0 * r2 + l2) / 12.0;
  return {ib, ib, 0.5 * m * r2};
}

Vec3 ElementType::halfExtents() const {
  if (shape == Shape::Brick) return 0.5 * Vec3(thickness, width, length);
  return {radius, radius, 0.5 * length};
}

void Bodies::add(int typeIndex, const ElementType& t, const Vec3& x, const Quat& q) {
  type.push_back(typeIndex);
  position.push_back(x);
  orientation.push_back(normalized(q));
  velocity.push_back(Vec3::Zero());
  angularMomentumBody.push_back(Vec3::Zero());
  mass.push_back(t.mass);
  inertia.push_back(t.principalInertia());
  force.push_back(Vec3::Zero());
  torque.push_back(Vec3::Zero());
  initialPosition.push_back(x);
  accumulatedRotation.push_back(Vec3::Zero());
}

void Bodies::setAngularVelocityWorld(int i, const Vec3& omega) {
  angularMomentumBody[i] = inertia[i].cwiseProduct(rotateInverse(orientation[i], omega));
}

void scaleInertia(Bodies& b, const std::vector<ElementType>& types, double massScale, double rotationalScale) {
  for (int i = 0; i < b.size(); ++i) {
    const ElementType& t = types[b.type[i]];
    const double mass = massScale * t.mass;
    const Vec3 inertia = (massScale * rotationalScale) * t.principalInertia();
    if (b.mass[i] == mass && b.inertia[i] == inertia) continue;
    b.angularMomentumBody[i] = b.angularMomentumBody[i].cwiseQuotient(b.inertia[i]).cwiseProduct(inertia);
    b.inertia[i] = inertia;
    b.mass[i] = mass;
  }
}

}  // namespace mesochain::mdem
