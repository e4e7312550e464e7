#include "common/toml_table.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "common/toml_file.hpp"

namespace mesochain {

std::string typeName(const toml::value& v) {
  switch (v.type()) {
    case toml::value_t::boolean:
      return "a boolean";
    case toml::value_t::integer:
      return "an integer";
    case toml::value_t::floating:
      return "a float";
    case toml::value_t::string:
      return "a string";
    case toml::value_t::array:
      return "an array";
    case toml::value_t::table:
      return "a table";
    case toml::value_t::offset_datetime:
    case toml::value_t::local_datetime:
    case toml::value_t::local_date:
    case toml::value_t::local_time:
      return "a date or time";
    default:
      return "an empty value";
  }
}

std::string describe(const toml::value& v) {
  switch (v.type()) {
    case toml::value_t::boolean:
      return fmt::format("{} ({})", typeName(v), v.as_boolean());
    case toml::value_t::integer:
      return fmt::format("{} ({})", typeName(v), v.as_integer());
    case toml::value_t::floating:
      return fmt::format("{} ({})", typeName(v), v.as_floating());
    case toml::value_t::string: {
      const std::string s = v.as_string().str;
      return s.size() <= 60 ? fmt::format("{} (\"{}\")", typeName(v), s) : typeName(v);
    }
    default:
      return typeName(v);
  }
}

std::optional<double> asNumber(const toml::value& v) {
  if (v.is_floating()) return v.as_floating();
  if (v.is_integer()) return static_cast<double>(v.as_integer());
  return std::nullopt;
}

// A value built in memory (not parsed from a file) has no line: toml11 reports line 1 of
// "unknown file" for it.
int lineOf(const toml::value& v) {
  const toml::source_location loc = v.location();
  return loc.file_name() == "unknown file" ? 0 : static_cast<int>(loc.line());
}

// " (line N)", " (set by --set ...)" for a value given on the command line, "" in memory.
std::string lineSuffix(const toml::value& v) {
  return lineOf(v) > 0 ? " (" + tomlWhere(v) + ")" : std::string();
}

TomlTable::TomlTable(std::string source, const toml::value& table, std::string name)
    : source_(std::move(source)), table_(&table), name_(std::move(name)) {}

bool TomlTable::has(const std::string& key) const { return table_->as_table().count(key) > 0; }

const toml::value& TomlTable::at(const std::string& key) const {
  const auto& t = table_->as_table();
  auto it = t.find(key);
  if (it == t.end()) missing(key, "a value");
  return it->second;
}

std::vector<std::string> TomlTable::keys() const {
  std::vector<std::string> out;
  for (const auto& kv : table_->as_table()) out.push_back(kv.first);
  std::sort(out.begin(), out.end());
  return out;
}

std::string TomlTable::dotted(const std::string& key) const {
  return name_.empty() ? key : name_ + "." + key;
}

int TomlTable::line(const std::string& key) const {
  if (has(key)) return lineOf(at(key));
  return name_.empty() ? 0 : lineOf(*table_);
}

std::string TomlTable::where(const std::string& key) const {
  if (has(key)) return fmt::format("key {}{}", dotted(key), lineSuffix(at(key)));
  if (name_.empty() || lineOf(*table_) == 0) return fmt::format("key {}", dotted(key));
  return fmt::format("key {} (table [{}] at line {})", dotted(key), name_, lineOf(*table_));
}

void TomlTable::fail(const std::string& key, const std::string& found,
                     const std::string& expected) const {
  throw InputError(source_, where(key), found, expected);
}

void TomlTable::missing(const std::string& key, const std::string& expected) const {
  throw InputError(source_, where(key), "no such key (it is required)", expected);
}

void TomlTable::allowOnly(const std::vector<std::string>& allowed) const {
  for (const std::string& k : keys())
    if (std::find(allowed.begin(), allowed.end(), k) == allowed.end()) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
      throw InputError(
          source_, where(k), "an unknown key '" + k + "'",
          (name_.empty() ? "top-level keys or tables: " : "one of the keys of [" + name_ + "]: ") +
              list);
    }
}

double TomlTable::number(const std::string& key, const std::string& expected) const {
  if (!has(key)) missing(key, expected);
  const toml::value& v = at(key);
  const auto x = asNumber(v);
  if (!x) fail(key, describe(v), expected);
  if (!std::isfinite(*x)) fail(key, "a non-finite number", expected);
  return *x;
}

long TomlTable::integer(const std::string& key, const std::string& expected) const {
  if (!has(key)) missing(key, expected);
  const toml::value& v = at(key);
  if (!v.is_integer()) fail(key, describe(v), expected);
  return static_cast<long>(v.as_integer());
}

std::string TomlTable::string(const std::string& key, const std::string& expected) const {
  if (!has(key)) missing(key, expected);
  const toml::value& v = at(key);
  if (!v.is_string()) fail(key, describe(v), expected);
  return v.as_string().str;
}

bool TomlTable::boolean(const std::string& key, const std::string& expected) const {
  if (!has(key)) missing(key, expected);
  const toml::value& v = at(key);
  if (!v.is_boolean()) fail(key, describe(v), expected);
  return v.as_boolean();
}

std::optional<TomlTable> TomlTable::table(const std::string& key) const {
  if (!has(key)) return std::nullopt;
  const toml::value& v = at(key);
  if (!v.is_table()) fail(key, describe(v), "a table [" + dotted(key) + "]");
  return TomlTable(source_, v, dotted(key));
}

}  // namespace mesochain
