#include "mdem/scene.hpp"

#include <cmath>

namespace mesochain::mdem {

BondStiffness BondType::stiffnessFor(double restLength) const {
  if (!fromModuli) return stiffness;
  return {youngModulus / restLength, shearModulus / restLength};
}

long stepsForDuration(double durationNs, double h) {
  const double n = durationNs / h;
  const double whole = std::round(n);
  return std::max(1L, static_cast<long>(std::abs(n - whole) <= 1e-9 * whole ? whole : std::ceil(n)));
}

BondSection sectionOf(const ElementType& t) {
  if (t.shape == Shape::Brick) return BondSection::rectangle(t.thickness, t.width);
  return BondSection::disc(t.radius);
}

void addBond(Scene& scene, int a, int b, int bondType) {
  const double l = (scene.bodies.position[b] - scene.bodies.position[a]).norm();
  const ElementType& ta = scene.elementTypes[scene.bodies.type[a]];
  scene.bonds.push_back(makeBond(a, b, scene.bodies, scene.bondTypes[bondType].stiffnessFor(l),
                                 sectionOf(ta)));
}

int addFilament(Scene& scene, const FilamentSpec& spec) {
  const ElementType& t = scene.elementTypes[spec.elementType];
  const Vec3 ez = spec.direction.normalized();
  Vec3 ex = spec.thicknessAxis - spec.thicknessAxis.dot(ez) * ez;
  if (ex.norm() < 1e-9) ex = ez.unitOrthogonal();
  ex.normalize();
  Mat3 r;
  r.col(0) = ex, r.col(1) = ez.cross(ex), r.col(2) = ez;
  const Quat q = fromMatrix(r);
  const double spacing = spec.spacing > 0.0 ? spec.spacing : t.length;
  const int first = scene.bodies.size();
  for (int k = 0; k < spec.count; ++k) {
    scene.bodies.add(spec.elementType, t, spec.start + (k * spacing) * ez, q);
    if (k > 0) addBond(scene, first + k - 1, first + k, spec.bondType);
  }
  return first;
}

}  // namespace mesochain::mdem
