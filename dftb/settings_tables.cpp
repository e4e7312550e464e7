#include "dftb/settings_tables.hpp"

#include "common/units.hpp"
#include "dftb/dispersion_table.hpp"
#include "dftb/scc_table.hpp"

namespace mesochain::dftb {

SettingEntries kpointsTableEntries(const BandSettings& s, bool ring) {
  // Every member named: a new one fails to compile here until it has its entries (or, like the
  // eigenvector path, is said to have none).
  const auto& [helicalKPoints, angular, electronicTemperature, eigenvectors] = s;
  (void)electronicTemperature;  // [electrons]
  (void)eigenvectors;           // how, not what: no entry (settings_tables.hpp)
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

std::vector<SettingsTable> calculatorSettingsTables(const CalculatorSettings& c, bool ring) {
  const auto& [band, dispersion, kc, scc] = c;  // a new member stops the build here
  std::vector<SettingsTable> out{{"kpoints", kpointsTableEntries(band, ring)},
                                  {"electrons", electronsTableEntries(band)}};
  DispersionTable d;
  d.lj = dispersion;
  if (dispersion.enabled && kc.enabled) {
    // Both terms on (possible through the API, not in a cell file): a table each.
    out.push_back({"dispersion", dispersionTableEntries(d)});
    d.lj = DispersionSettings{};
    d.kc = kc;
    out.push_back({"dispersion_kc", dispersionTableEntries(d)});
  } else {
    d.kc = kc;
    out.push_back({"dispersion", dispersionTableEntries(d)});
  }
  out.push_back({"scc", sccTableEntries(scc)});
  return out;
}

}  // namespace mesochain::dftb
