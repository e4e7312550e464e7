#include "dftb/band_table.hpp"

#include <fmt/format.h>

#include "common/electronic_temperature.hpp"
#include "common/units.hpp"

namespace mesochain::dftb {

void readKPointsTable(const TomlTable& t, bool ring, BandSettings& s) {
  t.allowOnly({"helical", "angular"});
  if (t.has("helical")) {
    const char* expected = "a number of helical k-points from 1 to 1000000";
    const long n = t.integer("helical", expected);
    if (n < 1 || n > 1000000) t.fail("helical", std::to_string(n), expected);
    if (ring && n != 1)
      t.fail("helical", fmt::format("{} for a closed ring (translation 0)", n),
             "helical = 1 or no helical key: a ring has no helical wave number");
    s.helicalKPoints = static_cast<int>(n);
  } else if (!ring) {
    t.missing("helical", "the number of helical k-points (an integer >= 1)");
  }
  if (t.has("angular"))
    s.angular.samples =
        static_cast<int>(t.integerOrWord("angular", "all", 1, 1000000000L, "sampled angular quantum numbers").value_or(0));
}

void readElectronsTable(const TomlTable& t, BandSettings& s) {
  t.allowOnly({"temperature"});
  const double kelvin = t.number("temperature", "a positive temperature (K)");
  s.electronicTemperature = kelvin * units::kBoltzmannHartreePerKelvin;
  if (!electronicTemperatureInRange(s.electronicTemperature))
    t.fail("temperature", describeElectronicTemperature(s.electronicTemperature), electronicTemperatureRange());
}

SettingEntries kpointsTableEntries(const BandSettings& s, bool ring) {
  // Every member named: a new one fails to compile here until it has its entries (or, like the
  // eigenvector path, is said to have none).
  const auto& [helicalKPoints, angular, electronicTemperature, eigenvectors] = s;
  (void)electronicTemperature;  // [electrons]
  (void)eigenvectors;           // how, not what: no entry (dftb/settings_tables.hpp)
  SettingEntries out;
  if (!ring) out.push_back({"helical", toml::value(helicalKPoints), ""});
  if (angular.samples > 0)
    out.push_back({"angular", toml::value(angular.samples), ""});
  else
    out.push_back({"angular", toml::value("all"), ""});
  return out;
}

SettingEntries electronsTableEntries(const BandSettings& s) {
  return {{"temperature", toml::value(s.electronicTemperature / units::kBoltzmannHartreePerKelvin), "K"}};
}

}  // namespace mesochain::dftb
