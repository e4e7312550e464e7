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

}  // namespace mesochain::units
