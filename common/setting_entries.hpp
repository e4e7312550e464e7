#pragma once
// A settings table as it is written back: its keys in order, each with a typed value (boolean,
// integer, float or string) and its unit. A settings struct's writer, beside its reader, returns
// one; each output renders it (the cell file, the mesochain: keys of extended XYZ, the Python
// dicts), so the keys of a table are listed once, beside the table's reader.
#include <string>
#include <vector>

#include <fmt/format.h>
#include <toml.hpp>

namespace mesochain {

struct SettingEntry {
  std::string key;      // the key of the table, e.g. "charge_tolerance"
  toml::value value;    // boolean, integer, floating or string
  std::string comment;  // the unit, e.g. "Ha" ("" for none)
};
using SettingEntries = std::vector<SettingEntry>;

// Shortest decimal form that reads back to the same double, always with a '.' or an exponent so
// that TOML reads a float.
inline std::string tomlRealText(double x) {
  std::string s = fmt::format("{}", x);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

// A TOML basic string.
inline std::string tomlStringText(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      out += fmt::format("\\u{:04X}", static_cast<int>(c));
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// The TOML text of an entry's value.
inline std::string tomlValueText(const toml::value& v) {
  if (v.is_boolean()) return v.as_boolean() ? "true" : "false";
  if (v.is_integer()) return std::to_string(v.as_integer());
  if (v.is_floating()) return tomlRealText(v.as_floating());
  return tomlStringText(v.as_string().str);
}

// The lines `key = value  # unit` of a table (without its [header]).
inline std::string tomlTableText(const SettingEntries& entries) {
  std::string out;
  for (const SettingEntry& e : entries)
    out += e.key + " = " + tomlValueText(e.value) + (e.comment.empty() ? "" : "  # " + e.comment) + "\n";
  return out;
}

}  // namespace mesochain
