#pragma once
// Units of mdem/ (one consistent mechanical system; see docs/mdem-units.md).
//
//   length  nm            (1e-9 m)
//   mass    ag, attogram  (1e-21 kg)
//   time    ns            (1e-9 s)
// derived, and verified below:
//   force   ag nm / ns^2  = 1e-21 kg * 1e-9 m / 1e-18 s^2 = 1e-12 N   = pN
//   energy  pN nm         = 1e-12 N * 1e-9 m               = 1e-21 J   = zJ
//   moment  pN nm         (same dimension as energy)
//   stress  pN / nm^2     = 1e-12 N / 1e-18 m^2            = 1e6 Pa    = MPa
//   bond stiffness per unit area (k_n, k_s): MPa / nm = pN / nm^3
//   moment of inertia: ag nm^2; angular velocity: rad / ns; velocity: nm / ns (= m/s).
// Input keys carry their unit in their name (length_nm, mass_ag, young_modulus_MPa, ...).
#include "common/units.hpp"

namespace mesochain::mdem::units {

inline constexpr double kPi = mesochain::units::kPi;

// SI value of one internal unit.
inline constexpr double kLengthSI = 1e-9;   // m
inline constexpr double kMassSI = 1e-21;    // kg
inline constexpr double kTimeSI = 1e-9;     // s
inline constexpr double kForceSI = kMassSI * kLengthSI / (kTimeSI * kTimeSI);  // N
inline constexpr double kEnergySI = kForceSI * kLengthSI;                      // J
inline constexpr double kStressSI = kForceSI / (kLengthSI * kLengthSI);        // Pa

// Conversions from common units to internal ones.
inline constexpr double kGigapascal = 1e9 / kStressSI;       // 1 GPa in MPa = 1000
inline constexpr double kKgPerM3 = 1.0 / (kMassSI / (kLengthSI * kLengthSI * kLengthSI));  // ag/nm^3
inline constexpr double kElectronvolt = mesochain::units::si::kElectronvoltInJoule / kEnergySI;  // 1 eV in zJ
inline constexpr double kDalton = mesochain::units::si::kDaltonInKilogram / kMassSI;        // 1 u in ag

// Relative comparison used by the static checks below.
constexpr bool near(double a, double b) { return (a > b ? a - b : b - a) <= 1e-12 * (a > b ? a : b); }
static_assert(near(kForceSI, 1e-12), "force unit must be the piconewton");
static_assert(near(kEnergySI, 1e-21), "energy unit must be the zeptojoule");
static_assert(near(kStressSI, 1e6), "stress unit must be the megapascal");
static_assert(near(kKgPerM3, 1e-6), "1 kg/m^3 must be 1e-6 ag/nm^3");

}  // namespace mesochain::mdem::units
