#include "dftb/scc_table.hpp"

#include <fmt/format.h>

namespace mesochain::dftb {

void readSccTable(const TomlTable& t, SccSettings& s) {
  t.allowOnly({"enabled", "charge_tolerance", "energy_tolerance", "max_iterations", "mixer",
               "mixing", "ewald_tolerance", "stop_if_unconverged", "warm_start"});
  s.enabled = t.booleanOr("enabled", s.enabled);
  auto bounded = [&](const char* key, double def, double lo, double hi, const char* what) {
    if (!t.has(key)) return def;
    const double x = t.number(key, what);
    if (!(x >= lo && x <= hi)) t.fail(key, fmt::format("{}", x), what);
    return x;
  };
  // Below 1e-13 the Mulliken charges and energies cannot be resolved in double precision.
  s.chargeTolerance = bounded("charge_tolerance", s.chargeTolerance, 1e-13, 1.0,
                              "a charge tolerance in [1e-13, 1] (electrons)");
  s.energyTolerance = bounded("energy_tolerance", s.energyTolerance, 1e-13, 1.0,
                              "an energy tolerance in [1e-13, 1] (Hartree per cell)");
  s.mixing = bounded("mixing", s.mixing, 1e-6, 1.0, "a mixing parameter in (0, 1]");
  s.ewaldTolerance = bounded("ewald_tolerance", s.ewaldTolerance, 1e-13, 1e-2,
                             "a tolerance in [1e-13, 1e-2]");
  if (t.has("max_iterations")) {
    const long n = t.integer("max_iterations", "1 .. 100000");
    if (n < 1 || n > 100000L) t.fail("max_iterations", std::to_string(n), "1 .. 100000");
    s.maxIterations = static_cast<int>(n);
  }
  if (t.has("mixer")) {
    s.mixer = t.string("mixer", "\"broyden\" or \"simple\"");
    if (s.mixer != "broyden" && s.mixer != "simple")
      t.fail("mixer", "\"" + s.mixer + "\"", "\"broyden\" or \"simple\"");
  }
  s.stopIfUnconverged = t.booleanOr("stop_if_unconverged", s.stopIfUnconverged);
  s.warmStart = t.booleanOr("warm_start", s.warmStart);
}

SettingEntries sccTableEntries(const SccSettings& s) {
  // Every member named: a new one fails to compile here until it has its entry.
  const auto& [enabled, chargeTolerance, energyTolerance, maxIterations, mixer, mixing, ewaldTolerance,
               stopIfUnconverged, warmStart] = s;
  return {{"enabled", toml::value(enabled), ""},
          {"charge_tolerance", toml::value(chargeTolerance), "e"},
          {"energy_tolerance", toml::value(energyTolerance), "Ha"},
          {"max_iterations", toml::value(maxIterations), ""},
          {"mixer", toml::value(mixer), ""},
          {"mixing", toml::value(mixing), ""},
          {"ewald_tolerance", toml::value(ewaldTolerance), ""},
          {"stop_if_unconverged", toml::value(stopIfUnconverged), ""},
          {"warm_start", toml::value(warmStart), ""}};
}

}  // namespace mesochain::dftb
