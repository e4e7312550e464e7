#pragma once
// Total linear and angular momentum (about the origin) of the bodies, for conservation tests.
#include "mdem/body.hpp"
#include "mdem/quaternion.hpp"

namespace mesochain::mdem::test_support {

inline Vec3 linearMomentum(const Bodies& b) {
  Vec3 p = Vec3::Zero();
  for (int i = 0; i < b.size(); ++i) p += b.mass[i] * b.velocity[i];
  return p;
}

// Orbital part m x × v plus each body's spin (its body-frame angular momentum rotated to world).
inline Vec3 angularMomentum(const Bodies& b) {
  Vec3 l = Vec3::Zero();
  for (int i = 0; i < b.size(); ++i)
    l += b.mass[i] * b.position[i].cross(b.velocity[i]) + rotate(b.orientation[i], b.angularMomentumBody[i]);
  return l;
}

}  // namespace mesochain::mdem::test_support
