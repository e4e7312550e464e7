#include "common/toml_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace mesochain {

namespace {
// The overrides given on the command line, applied to the first file parseTomlFile reads.
std::vector<TomlOverride>& overrides() {
  static std::vector<TomlOverride> o;
  return o;
}
bool& overridesApplied() {
  static bool applied = false;
  return applied;
}
const std::string kSetPrefix = "--set ";

bool isBareKey(const std::string& k) {
  if (k.empty()) return false;
  for (char c : k)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
  return true;
}
}  // namespace

toml::value parseTomlFile(const std::string& path, const std::string& kind) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path, "", "no such file (or not a regular file)", "an existing TOML " + kind);
  toml::value root;
  try {
    root = toml::parse(path);
  } catch (const toml::syntax_error& e) {
    throw InputError(path, fmt::format("line {}", e.location().line()), "invalid TOML syntax",
                     std::string("valid TOML (") + e.what() + ")");
  } catch (const std::exception& e) {
    throw InputError(path, "", std::string("a file that cannot be read as TOML: ") + e.what(),
                     "a readable TOML " + kind);
  }
  if (!overridesApplied()) {
    overridesApplied() = true;
    for (const TomlOverride& o : overrides()) applyTomlOverride(root, o, path);
  }
  return root;
}

namespace {
// "section.key" -> {"section", "key"}; InputError naming `option` when it is no dotted bare key.
std::vector<std::string> parseDottedKey(const std::string& keyText, const std::string& option) {
  const std::string where = "option " + option;
  std::vector<std::string> key;
  std::stringstream keys(keyText);
  for (std::string k; std::getline(keys, k, '.');) {
    if (!isBareKey(k))
      throw InputError("<command line>", where, "the key '" + keyText + "'",
                       "dotted bare TOML keys (letters, digits, _ and -), e.g. task.type");
    key.push_back(k);
  }
  if (key.empty() || keyText.back() == '.')
    throw InputError("<command line>", where, "the key '" + keyText + "'", "dotted bare TOML keys, e.g. task.type");
  return key;
}
}  // namespace

TomlOverride parseTomlOverride(const std::string& text) {
  const std::string where = "option --set " + text;
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("<command line>", where, "'" + text + "'",
                     "section.key=value (e.g. kpoints.helical=8; the parameter set of `build` is "
                     "--parameter-set)");
  TomlOverride o;
  o.text = text;
  o.key = parseDottedKey(text.substr(0, eq), "--set " + text);
  const std::string value = text.substr(eq + 1);
  if (value.empty())
    throw InputError("<command line>", where, "an empty value", "a TOML value (e.g. 8, 1.5, true, \"pbc-0-3\", [1, 2])");
  // Read as the TOML line `v = VALUE` from a source named after the option, so a value that
  // fails the reader's checks is reported as coming from --set.
  try {
    std::istringstream in("v = " + value + "\n");
    o.value = toml::parse(in, kSetPrefix + text).at("v");
  } catch (const std::exception&) {
    // A bare word (relax, pbc-0-3) is a string; anything that looks like an attempt at a typed
    // value (quotes, brackets, braces) must be valid TOML.
    if (value.find_first_of("\"'[]{}") != std::string::npos)
      throw InputError("<command line>", where, "'" + value + "', which is not a TOML value",
                       "a TOML value (e.g. 8, 1.5, true, \"text\", [1, 2])");
    std::istringstream in("v = " + toml::format(toml::value(value)) + "\n");
    o.value = toml::parse(in, kSetPrefix + text).at("v");
  }
  return o;
}

TomlOverride parseTomlRemoval(const std::string& text) {
  if (text.find('=') != std::string::npos)
    throw InputError("<command line>", "option --unset " + text, "'" + text + "'",
                     "a key without a value, e.g. --unset relax (to give a value, use --set)");
  TomlOverride o;
  o.text = text;
  o.key = parseDottedKey(text, "--unset " + text);
  o.remove = true;
  return o;
}

void applyTomlOverride(toml::value& root, const TomlOverride& o, const std::string& source) {
  const std::string option = (o.remove ? "--unset " : "--set ") + o.text;
  toml::value* t = &root;
  std::string path;
  for (std::size_t i = 0; i + 1 < o.key.size(); ++i) {
    path += (path.empty() ? "" : ".") + o.key[i];
    auto& table = t->as_table();
    auto it = table.find(o.key[i]);
    if (it == table.end()) {
      if (o.remove)
        throw InputError(source, "option " + option, "no table " + path + " in the file",
                         "a key that the file has (--unset removes keys; nothing to remove here)");
      std::istringstream in("v = {}\n");
      it = table.emplace(o.key[i], toml::parse(in, kSetPrefix + o.text).at("v")).first;
    }
    if (!it->second.is_table())
      throw InputError(source, "key " + path + " (" + tomlWhere(it->second) + ")",
                       "a value that is not a table, so option " + option + " cannot address a key in it",
                       "keys of tables ([section] key = value)");
    t = &it->second;
  }
  auto& table = t->as_table();
  if (!o.remove) {
    table[o.key.back()] = o.value;
    return;
  }
  if (table.erase(o.key.back()) == 0)
    throw InputError(source, "option " + option, "no key " + o.text + " in the file",
                     "a key that the file has (--unset removes keys; nothing to remove here)");
}

void setTomlOverrides(std::vector<TomlOverride> o) {
  // Removals first, each kind in the order given: `--unset relax --set relax.max_steps=10`
  // replaces the table.
  std::stable_partition(o.begin(), o.end(), [](const TomlOverride& x) { return x.remove; });
  overrides() = std::move(o);
  overridesApplied() = false;
}

bool tomlOverridesUnused() { return !overrides().empty() && !overridesApplied(); }

std::string tomlWhere(const toml::value& v) {
  const std::string name = v.location().file_name();
  if (name.rfind(kSetPrefix, 0) == 0) return "set by " + name;
  return fmt::format("line {}", v.location().line());
}

}  // namespace mesochain
