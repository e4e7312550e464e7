#include "objective/drivers/scan_checkpoint.hpp"

// The identity of a scan's input (scanIdentity: every setting that changes a point's result, by
// name; its hash; the hashes of earlier versions) and the refusal of a checkpoint of another
// input. Split from scan.cpp: what a checkpoint is checked against, not how a scan runs.
#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "dftb/settings_tables.hpp"
#include "objective/drivers/scan_reference.hpp"
#include "objective/drivers/settings_fields.hpp"

namespace mesochain::objective {

namespace {

// FNV-1a, 64 bit (Fowler, Noll & Vo).
std::string fnv1a(const std::string& text) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return fmt::format("{:016x}", h);
}

// The hashed text of earlier versions (formats 1 and 2): a hand-kept list, which left out the
// SCC settings, the dispersion summation and the angular momenta of the tables. Recognised only
// to refuse such a checkpoint with a message saying why (readers of an old checkpoint cannot
// know those settings). withList: format 1, which also included the deformation list.
std::string legacyHashText(const ObjectiveCell& cell, const dftb::CalculatorSettings& c,
                           const ScanSettings& s, bool withList) {
  std::string t = withList ? "mesochain-scan-1\n" : "mesochain-scan-2\n";
  t += fmt::format("kind {} direction {}\n", scanKindName(s.kind), bendDirectionName(s.direction));
  if (withList) {
    for (double v : s.values) t += fmt::format("value {:.17g}\n", v);
    for (int n : s.rotationOrders) t += fmt::format("order {}\n", n);
  }
  const RelaxSettings& r = s.relax;
  t += fmt::format("relax {} {:.17g} {} {} {:.17g} {} {:.17g}\n", static_cast<int>(r.algorithm),
                   r.forceTolerance, r.maxSteps, r.relaxTranslation, r.axialTolerance,
                   r.maxTranslationSteps, r.maxDisplacement);
  t += fmt::format("ring angular {}\n", s.ringAngular.samples);
  t += fmt::format("band {} {} {:.17g}\n", c.band.helicalKPoints, c.band.angular.samples,
                   c.band.electronicTemperature);
  t += fmt::format("dispersion {} {:.17g} {:.17g} {:.17g}\n", c.dispersion.enabled,
                   c.dispersion.epsilon, c.dispersion.r0, c.dispersion.cutoff);
  t += fmt::format("symmetry {:.17g} {:.17g} {}\n", cell.symmetry.translation(),
                   cell.symmetry.twist(), cell.symmetry.rotationOrder());
  for (int a = 0; a < cell.atomCount(); ++a)
    t += fmt::format("{} {:.17g} {:.17g} {:.17g}\n", cell.speciesOf(a), cell.positions(0, a),
                     cell.positions(1, a), cell.positions(2, a));
  t += "identity " + s.identity + "\n";
  return t;
}

// The cell as text: symmetry, then species and position of every atom (all digits).
std::string cellText(const ObjectiveCell& cell) {
  std::string t = fmt::format("symmetry {:.17g} {:.17g} {}\n", cell.symmetry.translation(),
                              cell.symmetry.twist(), cell.symmetry.rotationOrder());
  for (int a = 0; a < cell.atomCount(); ++a)
    t += fmt::format("{} {:.17g} {:.17g} {:.17g}\n", cell.speciesOf(a), cell.positions(0, a),
                     cell.positions(1, a), cell.positions(2, a));
  return t;
}

// The text of one setting value (all digits of a double; an enum by its number).
template <class T>
std::string valueText(const T& v) {
  if constexpr (std::is_same_v<T, bool>) return v ? "true" : "false";
  else if constexpr (std::is_enum_v<T>) return std::to_string(static_cast<long long>(v));
  else if constexpr (std::is_floating_point_v<T>) return fmt::format("{:.17g}", v);
  else if constexpr (std::is_integral_v<T>) return std::to_string(v);
  else if constexpr (std::is_same_v<T, std::string>) return v;
  else {
    std::string t;
    for (const auto& e : v) t += valueText(e) + " ";
    return t;
  }
}

// Every FieldRole::Result member of `s` (nested settings as "prefix.member") into `out`.
template <class S>
void collectSettings(const std::string& prefix, const S& s,
                     std::map<std::string, std::string>& out) {
  forEachField(s, [&](const char* name, const auto& v, FieldRole role) {
    using T = std::decay_t<decltype(v)>;
    if constexpr (VisitedSettings<T>) {
      if (role == FieldRole::Result) collectSettings(prefix + name + ".", v, out);
    } else if constexpr (std::is_invocable_v<T, int, double, double> ||
                         std::is_invocable_v<T, const ScanPoint&, int, int> ||
                         std::is_invocable_v<T, const RelaxProgress&> ||
                         std::is_same_v<T, std::shared_ptr<const ScanReference>> ||
                         std::is_same_v<T, std::shared_ptr<const RelaxProgress>>) {
      // a callback (progress, pointDone, snapshot), the given reference (checked on its own) or
      // a relaxation to resume: never a result setting
    } else {
      if (role == FieldRole::Result) out[prefix + name] = valueText(v);
    }
  });
}

// Long values (the parameter tables' contents, the atoms) are kept as their hash in the
// checkpoint, so it stays small while still telling which setting changed.
std::map<std::string, std::string> shortened(std::map<std::string, std::string> m) {
  for (auto& [key, value] : m)
    if (value.size() > 80) value = "fnv1a " + fnv1a(value);
  return m;
}

}  // namespace

std::map<std::string, std::string> scanIdentity(const ObjectiveCell& cell,
                                                const dftb::CalculatorSettings& c,
                                                const ScanSettings& s) {
  std::map<std::string, std::string> out;
  // The calculator settings as the cell file writes them (a scanned cell is never a ring).
  for (const dftb::SettingsTable& table : dftb::calculatorSettingsTables(c, false))
    for (const SettingEntry& e : table.entries)
      out["calculator." + table.name + "." + e.key] = tomlValueText(e.value);
  collectSettings("scan.", s, out);
  out["cell"] = cellText(cell);
  return shortened(std::move(out));
}

std::string scanInputHash(const ObjectiveCell& cell, const dftb::CalculatorSettings& c,
                          const ScanSettings& s) {
  std::string t = "mesochain-scan-4\n";
  for (const auto& [key, value] : scanIdentity(cell, c, s)) t += key + " " + value + "\n";
  return fnv1a(t);
}

std::vector<std::string> legacyScanInputHashes(const ObjectiveCell& cell,
                                               const dftb::CalculatorSettings& c,
                                               const ScanSettings& s) {
  return {fnv1a(legacyHashText(cell, c, s, true)), fnv1a(legacyHashText(cell, c, s, false))};
}

void requireCheckpointOfThisInput(const std::string& path, const ScanCheckpoint& old, const ObjectiveCell& cell,
                                  const dftb::CalculatorSettings& calculator, const ScanSettings& settings,
                                  const std::string& fix) {
  const std::string hash = scanInputHash(cell, calculator, settings);
  if (old.inputHash == hash) return;
  if (old.settings.empty()) {
    const std::vector<std::string> legacy = legacyScanInputHashes(cell, calculator, settings);
    const bool sameRecorded = std::find(legacy.begin(), legacy.end(), old.inputHash) != legacy.end();
    throw InputError(path, "key input_hash",
                     sameRecorded
                         ? "a checkpoint of an earlier mesochain that matches this input in the "
                           "settings it recorded, but did not record the [scc] settings, the "
                           "dispersion summation or the tables' angular momenta"
                         : fmt::format("a checkpoint of another scan input (hash {}, this input "
                                       "{})", old.inputHash, hash),
                     "a checkpoint of this scan with the same settings: " + fix);
  }
  if (old.settings.count("calculator.band.helical_kpoints"))
    throw InputError(path, "key settings",
                     "a checkpoint of an earlier mesochain (format 3), which named the calculator "
                     "settings by their members (calculator.band.*) rather than by the cell file's "
                     "tables (calculator.kpoints.*), so its points cannot be matched to this input",
                     "a checkpoint of this version: " + fix);
  const std::string list = settingChanges(old.settings, scanIdentity(cell, calculator, settings), "checkpoint");
  throw InputError(path, "key settings",
                   fmt::format("a checkpoint of another scan input, changed: {}",
                               list.empty() ? "hash " + old.inputHash : list),
                   "the checkpoint of this scan (same settings; the deformation list may "
                   "differ): " + fix);
}

}  // namespace mesochain::objective
