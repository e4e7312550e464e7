#include "dftb/settings_tables.hpp"

#include "dftb/band_table.hpp"
#include "dftb/dispersion_table.hpp"
#include "dftb/scc_table.hpp"

namespace mesochain::dftb {

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
