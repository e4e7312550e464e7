#pragma once
// Units of mesochain.
//
// Inside dftb/, objective/ and ewald/: Hartree atomic units (energy in Hartree, length in Bohr,
// angles in radians, temperature as k_B T in Hartree). Conversions happen only where input is
// read and output is written; every input value names its unit (Å, degrees, K, kcal/mol).
//
// CODATA 2018 values.
namespace mesochain::units {

inline constexpr double kBohrInAngstrom = 0.529177210903;
inline constexpr double kAngstromInBohr = 1.0 / kBohrInAngstrom;
inline constexpr double kHartreeInEv = 27.211386245988;
inline constexpr double kEvInHartree = 1.0 / kHartreeInEv;
inline constexpr double kHartreeInKcalPerMol = 627.5094740631;
inline constexpr double kKcalPerMolInHartree = 1.0 / kHartreeInKcalPerMol;
// Boltzmann constant in Hartree per kelvin.
inline constexpr double kBoltzmannHartreePerKelvin = 3.166811563e-6;
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegree = kPi / 180.0;

// The bridge to SI and to the mDEM system (nm, ag, ns; MPa, zJ: docs/mdem-units.md), where the
// chain hands DFTB results (Hartree, Bohr, dalton) to beam/ and mdem/. Defined here only.
namespace si {
inline constexpr double kElectronvoltInJoule = 1.602176634e-19;  // exact (SI 2019)
inline constexpr double kDaltonInKilogram = 1.66053906660e-27;
inline constexpr double kBohrInMeter = kBohrInAngstrom * 1e-10;
inline constexpr double kBohrInNm = kBohrInAngstrom * 0.1;
inline constexpr double kHartreeInJoule = kHartreeInEv * kElectronvoltInJoule;
inline constexpr double kHartreeInZeptojoule = kHartreeInJoule * 1e21;  // zJ = pN nm
inline constexpr double kDaltonInAttogram = kDaltonInKilogram * 1e21;
// Standard atomic weight of carbon (IUPAC; natural isotope mix), dalton.
inline constexpr double kCarbonMassDalton = 12.011;
// Pressure / modulus: Hartree / Bohr^3 in MPa.
inline constexpr double kHartreePerBohr3InMPa = kHartreeInJoule / (kBohrInMeter * kBohrInMeter * kBohrInMeter) * 1e-6;
// Stiffness per unit area (k_n, k_s): Hartree / Bohr^4 in MPa / nm.
inline constexpr double kHartreePerBohr4InMPaPerNm = kHartreePerBohr3InMPa / kBohrInNm;
}  // namespace si

}  // namespace mesochain::units
