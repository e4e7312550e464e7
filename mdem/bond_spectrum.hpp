#pragma once
// The true largest vibration frequency of the bonds, to set against the Gershgorin bound of the
// critical time step (stability.hpp). Bonds join the elements of one filament only, so the
// linearised bonded operator M^{-1} K (normal_modes.hpp) is block diagonal by bonded
// component: each component (a filament) is solved densely with Eigen's generalized
// eigensolver, K v = omega^2 M v, and the largest omega over the components is the system's.
// Elements that are completely constrained (stability.hpp) are left out, as there.
//
// The mode of the largest omega is described by where its kinetic energy 1/2 v^T M v sits, in
// each element's body frame (z along the element): translation along the element (axial),
// across it (transverse), rotation about the element's axis (torsion) and about the normal
// axes (bending / shear rotation). Shares sum to 1.
#include <vector>

#include "mdem/boundary.hpp"
#include "mdem/parallel_bond.hpp"

namespace mesochain::mdem {

struct ModeShares {
  double axial = 0.0, transverse = 0.0, torsion = 0.0, bendingRotation = 0.0;
  double rotational() const { return torsion + bendingRotation; }
};

struct BondSpectrum {
  double omegaMax = 0.0;   // rad/ns, the largest eigenfrequency over all components
  int component = -1;      // index of that component (in order of its lowest element)
  int components = 0;      // bonded components solved
  int largestComponent = 0;  // elements of the largest component
  ModeShares mode;         // of the largest omega
};

// Components larger than `maxComponentElements` are refused (NumericalError): the dense solve
// costs (6 n)^3.
BondSpectrum bondSpectrum(const Bodies& bodies, const std::vector<Bond>& bonds, const KinematicMap& kinematics,
                          int maxComponentElements = 800);

}  // namespace mesochain::mdem
