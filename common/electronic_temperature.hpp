#pragma once
// The one validation of an electronic temperature, wherever it comes from (cell file, command
// line, calculator settings).
#include <string>

namespace mesochain {

// The range of electronic temperatures (Kelvin) Fermi filling accepts, with reasons:
// below 0.01 K (k_B T = 3.2e-8 Ha) the filling cannot be resolved in double precision: the
// electron count jumps by about g ulp(mu) / kT between neighbouring doubles of the Fermi level
// mu (g levels degenerate at mu, ulp(mu) ~ 1e-16 Ha), which passes 1e-8 electrons there, and
// near 1e-13 K levels at the Fermi level are filled wholly or not at all (a wrong electron
// count, a free energy off by 5e-4 Ha/atom in metallic tubes); for T -> 0 use the
// extrapolated energy of a run at 1-300 K. Above 1e5 K (k_B T = 8.6 eV) the smearing spans the
// whole valence band of carbon and the result is no longer a Mermin free energy of the
// structure.
inline constexpr double kMinimumElectronicTemperatureKelvin = 0.01;
inline constexpr double kMaximumElectronicTemperatureKelvin = 1e5;
// Throws InputError(source, where, ...) unless kT (Hartree) is in that range; the message gives
// the temperature in K and the range with its reason.
void requireElectronicTemperature(double kT, const std::string& source, const std::string& where);
// The parts of that check, for readers that compose their own message (with the line):
bool electronicTemperatureInRange(double kT);
std::string describeElectronicTemperature(double kT);  // "1e-13 K (k_B T = 3.2e-19 Ha)"
std::string electronicTemperatureRange();              // the expected range with its reasons

}  // namespace mesochain
