#pragma once
// Conversions between the atomic units of beam/ (Hartree, Bohr, dalton) and the mDEM system
// (nm, ag, ns; MPa, zJ: docs/mdem-units.md). CODATA 2018.
#include "common/units.hpp"

namespace mesochain::beam::si {

inline constexpr double kBohrInNm = units::kBohrInAngstrom * 0.1;
inline constexpr double kBohrInMeter = units::kBohrInAngstrom * 1e-10;
inline constexpr double kElectronvoltInJoule = 1.602176634e-19;
inline constexpr double kHartreeInJoule = units::kHartreeInEv * kElectronvoltInJoule;
inline constexpr double kHartreeInZeptojoule = kHartreeInJoule * 1e21;  // zJ = pN nm
inline constexpr double kDaltonInAttogram = 1.66053906660e-27 * 1e21;
// Standard atomic weight of carbon (IUPAC; natural isotope mix), dalton.
inline constexpr double kCarbonMassDalton = 12.011;
// Pressure / modulus: Hartree / Bohr^3 in MPa.
inline constexpr double kHartreePerBohr3InMPa =
    kHartreeInJoule / (kBohrInMeter * kBohrInMeter * kBohrInMeter) * 1e-6;
// Stiffness per unit area (k_n, k_s): Hartree / Bohr^4 in MPa / nm.
inline constexpr double kHartreePerBohr4InMPaPerNm = kHartreePerBohr3InMPa / kBohrInNm;

}  // namespace mesochain::beam::si
