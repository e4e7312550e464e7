#pragma once
// The units DFTB+ accepts in `[unit]` attributes, with the conversion constants of DFTB+ 25.1
// (src/dftbp/common/constants.F90, unitconversion.F90), so that a dftb_in.hsd gives the numbers
// DFTB+ gives: Bohr = 0.529177249 Å, Hartree = 27.2113845 eV, k_B = 3.16681534524639e-6 Ha/K,
// 1 kcal/mol = 0.0015946683859874898 Ha. These differ from the CODATA 2018 constants of
// common/units.hpp (the cell file's) by up to 7e-4 relative (kcal/mol); docs/cell-file.md.
// Names are matched without regard to case.
#include <optional>
#include <string>

namespace mesochain::input::hsd {

enum class UnitKind { Length, Energy, Force };

inline constexpr double kDftbPlusBohrInAngstrom = 0.529177249;
inline constexpr double kDftbPlusAngstromInBohr = 1.0 / kDftbPlusBohrInAngstrom;
inline constexpr double kDftbPlusHartreeInEv = 27.2113845;
inline constexpr double kDftbPlusBoltzmannHartreePerKelvin = 0.00000316681534524639;
inline constexpr double kDftbPlusKcalPerMolInHartree = 0.0015946683859874898;

// The factor that converts a value in `unit` to atomic units (Bohr, Hartree, Hartree/Bohr), or
// nullopt for a name DFTB+ does not accept for this kind (or mesochain does not convert: the
// energy unit "nm", a wavelength).
std::optional<double> unitFactor(UnitKind kind, const std::string& unit);
// The accepted names, for messages: "angstrom, aa, a, ...".
std::string unitNames(UnitKind kind);

}  // namespace mesochain::input::hsd
