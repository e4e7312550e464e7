#include "input/xyz_settings.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "dftb/dispersion_table.hpp"
#include "dftb/scc_table.hpp"
#include "dftb/band_table.hpp"

namespace mesochain::objective {

namespace {

const char* flag(bool b) { return b ? "T" : "F"; }

// An entry of a settings table (common/setting_entries.hpp) as the comment line writes it:
// booleans T / F, numbers in their shortest form, strings as they are.
std::string xyzValue(const toml::value& v) {
  if (v.is_boolean()) return flag(v.as_boolean());
  if (v.is_integer()) return std::to_string(v.as_integer());
  if (v.is_floating()) return fmt::format("{}", v.as_floating());
  return v.as_string().str;
}

// A value as one token: quoted when it holds a blank, refused when it holds a quote (the
// comment-line syntax has no escapes).
std::string token(const std::string& value, const std::string& key, const std::string& source) {
  if (value.find('"') != std::string::npos || value.find('\n') != std::string::npos)
    throw InputError(source, "the extended XYZ key mesochain:" + key, "a quote or line break in the value",
                     "a value that fits on an extended XYZ comment line");
  if (value.empty() || value.find_first_of(" \t=") != std::string::npos) return "\"" + value + "\"";
  return value;
}

}  // namespace

std::string xyzSettingsKeys(const CellInput& in) {
  std::string out;
  auto add = [&out, &in](const std::string& key, const std::string& value) {
    out += " mesochain:" + key + "=" + token(value, key, in.source);
  };
  const dftb::BandSettings& band = in.band;
  for (const SettingEntry& e : dftb::kpointsTableEntries(band, in.cell.symmetry.isRing()))
    add("kpoints." + e.key, xyzValue(e.value));
  for (const SettingEntry& e : dftb::electronsTableEntries(band)) add("electrons." + e.key, xyzValue(e.value));
  std::map<std::string, std::string> fromSet;
  if (!in.parameterSet.empty()) {
    add("parameters.set", in.parameterSet);
    fromSet = parameterSetFiles(in.parameterSet, in.cell.speciesNames, in.source, "[parameters] set");
  }
  for (const auto& [pair, file] : in.parameterFiles) {
    auto it = fromSet.find(pair);
    if (it != fromSet.end() && it->second == file) continue;
    add("parameters." + pair, std::filesystem::absolute(file).lexically_normal().string());
  }
  for (const auto& [el, l] : in.maxAngularMomentum)
    add("parameters.max_angular_momentum." + el, std::string(1, "spdf"[l]));
  for (const SettingEntry& e : dftb::dispersionTableEntries(in.dispersion))
    add("dispersion." + e.key, xyzValue(e.value));
  for (const SettingEntry& e : dftb::sccTableEntries(in.scc))
    if (in.scc.enabled || e.key == "enabled") add("scc." + e.key, xyzValue(e.value));
  return out;
}

bool isXyzSettingsKey(const std::string& key) {
  for (const char* section : {"kpoints.", "electrons.", "parameters.", "dispersion.", "scc."}) {
    const std::string prefix = std::string("mesochain:") + section;
    if (key.size() > prefix.size() && key.compare(0, prefix.size(), prefix) == 0) return true;
  }
  return false;
}

}  // namespace mesochain::objective
