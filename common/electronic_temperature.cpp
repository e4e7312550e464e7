#include "common/electronic_temperature.hpp"

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/units.hpp"

namespace mesochain {

bool electronicTemperatureInRange(double kT) {
  const double kelvin = kT / units::kBoltzmannHartreePerKelvin;
  return kelvin >= kMinimumElectronicTemperatureKelvin &&
         kelvin <= kMaximumElectronicTemperatureKelvin;
}

std::string describeElectronicTemperature(double kT) {
  return fmt::format("{:.6g} K (k_B T = {:.6g} Ha)", kT / units::kBoltzmannHartreePerKelvin, kT);
}

std::string electronicTemperatureRange() {
  return fmt::format(
      "an electronic temperature from {} K to {:g} K (below, Fermi filling cannot be resolved in "
      "double precision; for T -> 0 use the extrapolated energy of a run at 1-300 K; above, the "
      "smearing spans the whole band)",
      kMinimumElectronicTemperatureKelvin, kMaximumElectronicTemperatureKelvin);
}

void requireElectronicTemperature(double kT, const std::string& source,
                                  const std::string& where) {
  if (!electronicTemperatureInRange(kT))
    throw InputError(source, where, describeElectronicTemperature(kT),
                     electronicTemperatureRange());
}

}  // namespace mesochain
