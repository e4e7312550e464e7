#pragma once
// Scene-side description of contacts between tubes and of periodic boundaries (plain data; the
// scene file reader fills it, contact_effects.cpp builds the effects from it).
#include <array>
#include <cmath>
#include <vector>

#include "mdem/contacts/tube_potential.hpp"
#include "mdem/quaternion.hpp"

namespace mesochain::mdem {

// Periodic boundaries on any subset of the axes. Positions are never wrapped (bonds keep using
// unwrapped coordinates); contacts use the minimum image of the separation of two elements.
struct Periodicity {
  std::array<bool, 3> periodic{};  // x, y, z
  Vec3 length = Vec3::Zero();      // box length on the periodic axes, nm
  bool any() const { return periodic[0] || periodic[1] || periodic[2]; }
  Vec3 minimumImage(Vec3 d) const {
    for (int k = 0; k < 3; ++k)
      if (periodic[k]) d[k] -= length[k] * std::nearbyint(d[k] / length[k]);
    return d;
  }
};

// "vdw_contact": LJ parameters and the form of the contact (docs/mdem-contacts.md).
struct VdwContactSpec {
  bool anisotropic = true;      // false: isotropic central potential between element centres
  LennardJones lj;              // epsilon zJ, sigma nm, surface density atoms/nm^2
  double switchGap = 0.8;       // nm
  double cutoffGap = 1.2;       // nm
  int quadraturePoints = 8;     // Gauss points along the quadrature element (anisotropic form)
  // > 0: the points are chosen once per pair of element kinds as the fewest whose sampled energy
  // error is below this fraction of the contact energy scale (quadraturePointsForTolerance in
  // vdw_contact.hpp); quadraturePoints is then not used. 0: quadraturePoints.
  double quadratureTolerance = 0.0;
  // Nearly parallel pairs within this angle (degrees) use the tilt expansion of the parallel
  // tables, blended with the rule (AnisotropicVdwKernel::enableAlignedPath). 0: off (default: on
  // the bundled 150-nm film fewer than 2 % of the interacting pairs lie within its 1.15-degree
  // limit, docs/benchmarks.md).
  double alignedWindowDegrees = 0.0;
  // > 0: pairs crossing at more than 40 degrees use this many Gauss points instead, blended with
  // the rule above between 20 and 40 degrees (AnisotropicVdwKernel::enableCrossingRule): the
  // corrugation a sliding crossing feels falls with the points, while nearly parallel pairs are
  // already accurate (docs/benchmarks.md, "The quadrature points and the stress-strain curve").
  int crossingQuadraturePoints = 0;
  // Bricks (face-to-face form, face_contact.hpp): spacing of the two graphene layers of a
  // collapsed tube, and the width of the smooth edge of a face.
  double layerSpacing = 0.34;   // nm
  double edgeWidth = 0.6;       // nm
};

// "contact_damping": a dashpot in parallel with each contact, per unit contact length.
struct ContactDampingSpec {
  double translational = 0.0;  // gamma, pN ns / nm^2 (force per length per velocity)
  double rotational = 0.0;     // gamma_r, pN ns (moment per length per angular velocity)
  double fullGap = 0.5;        // nm: full weight below this gap between the tube walls
  double cutoffGap = 1.0;      // nm: zero weight beyond
};

// A filament whose last element neighbours its first across a periodic boundary.
struct ClosedFilament {
  int first = 0, count = 0;
};

struct ContactSpec {
  VdwContactSpec vdw;
  ContactDampingSpec damping;
  int excludeWithin = 3;       // pairs of one filament at most this many elements apart are excluded
  double skin = 0.3;           // Verlet skin, nm
  std::vector<ClosedFilament> closedFilaments;
};

}  // namespace mesochain::mdem
