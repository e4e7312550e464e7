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

namespace {

// Typed views of one value: nullopt when it has another type.
std::optional<long> asInteger(const toml::value& v) {
  return v.is_integer() ? std::optional<long>(static_cast<long>(v.as_integer())) : std::nullopt;
}
std::optional<std::string> asString(const toml::value& v) {
  return v.is_string() ? std::optional<std::string>(v.as_string().str) : std::nullopt;
}
std::optional<bool> asBoolean(const toml::value& v) {
  return v.is_boolean() ? std::optional<bool>(v.as_boolean()) : std::nullopt;
}

// The value of a required key as `get` reads it; missing key or another type: the InputError
// naming what was found and `expected`.
template <class Get>
auto required(const TomlTable& t, const std::string& key, const std::string& expected, Get get) {
  if (!t.has(key)) t.missing(key, expected);
  const toml::value& v = t.at(key);
  const auto x = get(v);
  if (!x) t.fail(key, describe(v), expected);
  return *x;
}

// The same for every element of an array; a wrong element is named as "an array holding ...".
template <class Get>
auto requiredArray(const TomlTable& t, const std::string& key, const std::string& expected, Get get) {
  if (!t.has(key)) t.missing(key, expected);
  const toml::value& v = t.at(key);
  if (!v.is_array()) t.fail(key, describe(v), expected);
  std::vector<typename decltype(get(v))::value_type> out;
  for (const toml::value& e : v.as_array()) {
    const auto x = get(e);
    if (!x) t.fail(key, "an array holding " + describe(e), expected);
    out.push_back(*x);
  }
  return out;
}

}  // namespace

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
    if (std::find(allowed.begin(), allowed.end(), k) == allowed.end() &&
        std::find(allowed.begin(), allowed.end(), "[" + k + "]") == allowed.end()) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
      throw InputError(
          source_, where(k), "an unknown key '" + k + "'",
          (name_.empty() ? "top-level keys or tables: " : "one of the keys of [" + name_ + "]: ") +
              list);
    }
}

double TomlTable::number(const std::string& key, const std::string& expected) const {
  const double x = required(*this, key, expected, asNumber);
  if (!std::isfinite(x)) fail(key, "a non-finite number", expected);
  return x;
}

long TomlTable::integer(const std::string& key, const std::string& expected) const {
  return required(*this, key, expected, asInteger);
}

std::string TomlTable::string(const std::string& key, const std::string& expected) const {
  return required(*this, key, expected, asString);
}

bool TomlTable::boolean(const std::string& key, const std::string& expected) const {
  return required(*this, key, expected, asBoolean);
}

double TomlTable::positive(const std::string& key, const std::string& expected) const {
  const double x = number(key, expected);
  if (!(x > 0.0)) fail(key, describe(at(key)), expected);
  return x;
}

long TomlTable::integerIn(const std::string& key, long lo, long hi) const {
  const std::string expected = fmt::format("an integer from {} to {}", lo, hi);
  const long n = integer(key, expected);
  if (n < lo || n > hi) fail(key, describe(at(key)), expected);
  return n;
}

std::vector<double> TomlTable::numbers(const std::string& key, const std::string& expected) const {
  const std::vector<double> out = requiredArray(*this, key, expected, asNumber);
  for (double x : out)
    if (!std::isfinite(x)) fail(key, "an array holding a non-finite number", expected);
  return out;
}

std::vector<long> TomlTable::integers(const std::string& key, const std::string& expected) const {
  return requiredArray(*this, key, expected, asInteger);
}

std::vector<std::string> TomlTable::strings(const std::string& key, const std::string& expected) const {
  return requiredArray(*this, key, expected, asString);
}

std::vector<std::string> TomlTable::numbersOrStrings(const std::string& key, const std::string& expected) const {
  return requiredArray(*this, key, expected, [](const toml::value& e) -> std::optional<std::string> {
    if (e.is_string()) return e.as_string().str;
    if (e.is_integer()) return std::to_string(e.as_integer());
    if (e.is_floating() && std::isfinite(e.as_floating())) return fmt::format("{}", e.as_floating());
    return std::nullopt;
  });
}

std::optional<long> TomlTable::integerOrWord(const std::string& key, const std::string& word, long lo, long hi,
                                             const std::string& what) const {
  const std::string expected = fmt::format("\"{}\" or an integer from {} to {}{}", word, lo, hi, what.empty() ? "" : " (" + what + ")");
  if (!has(key)) missing(key, expected);
  const toml::value& v = at(key);
  if (v.is_string() && v.as_string().str == word) return std::nullopt;
  if (!v.is_integer() || v.as_integer() < lo || v.as_integer() > hi) fail(key, describe(v), expected);
  return static_cast<long>(v.as_integer());
}

std::vector<TomlRow> TomlTable::rows(const std::string& key, std::size_t width, const std::string& expected,
                                     const std::string& noun) const {
  if (!has(key)) missing(key, expected);
  const toml::value& v = at(key);
  if (!v.is_array() || v.as_array().empty()) fail(key, describe(v) + (v.is_array() ? " that is empty" : ""), expected);
  std::vector<TomlRow> out;
  const auto& list = v.as_array();
  for (std::size_t k = 0; k < list.size(); ++k) {
    const toml::value& e = list[k];
    out.emplace_back(source_, fmt::format("key {}, {} {}{}", dotted(key), noun, k + 1, lineSuffix(e)), e, expected);
    if (!e.is_array() || e.as_array().size() != width)
      out.back().fail(describe(e) + (e.is_array() ? fmt::format(" of {} entries, not {}", e.as_array().size(), width) : ""));
  }
  return out;
}

TomlRow::TomlRow(std::string source, std::string where, const toml::value& row, std::string expected)
    : source_(std::move(source)), where_(std::move(where)), row_(&row), expected_(std::move(expected)) {}

void TomlRow::fail(const std::string& found) const { fail(found, expected_); }

void TomlRow::fail(const std::string& found, const std::string& expected) const {
  throw InputError(source_, where_, found, expected);
}

double TomlRow::number(std::size_t i) const {
  const toml::value& e = row_->as_array().at(i);
  const auto x = asNumber(e);
  if (!x || !std::isfinite(*x)) fail(fmt::format("entry {}: {}", i + 1, describe(e)));
  return *x;
}

long TomlRow::integer(std::size_t i) const {
  const toml::value& e = row_->as_array().at(i);
  if (!e.is_integer()) fail(fmt::format("entry {}: {}", i + 1, describe(e)));
  return static_cast<long>(e.as_integer());
}

std::string TomlRow::string(std::size_t i) const {
  const toml::value& e = row_->as_array().at(i);
  if (!e.is_string()) fail(fmt::format("entry {}: {}", i + 1, describe(e)));
  return e.as_string().str;
}

std::string TomlTable::oneOf(const std::string& key, const std::vector<std::string>& options) const {
  std::string expected;
  for (std::size_t i = 0; i < options.size(); ++i)
    expected += (i == 0 ? "" : i + 1 == options.size() ? " or " : ", ") + ("\"" + options[i] + "\"");
  const std::string s = string(key, expected);
  if (std::find(options.begin(), options.end(), s) == options.end()) fail(key, describe(at(key)), expected);
  return s;
}

Eigen::Vector3d TomlTable::vec3(const std::string& key, const std::string& expected) const {
  if (!has(key)) missing(key, expected);
  if (!at(key).is_array()) fail(key, describe(at(key)), expected);
  const std::vector<double> x = numbers(key);
  if (x.size() != 3) fail(key, fmt::format("{} numbers", x.size()), expected);
  return {x[0], x[1], x[2]};
}

double TomlTable::numberOr(const std::string& key, double fallback, const std::string& expected) const {
  return has(key) ? number(key, expected) : fallback;
}

long TomlTable::integerOr(const std::string& key, long fallback, const std::string& expected) const {
  return has(key) ? integer(key, expected) : fallback;
}

std::string TomlTable::stringOr(const std::string& key, const std::string& fallback,
                                const std::string& expected) const {
  return has(key) ? string(key, expected) : fallback;
}

bool TomlTable::booleanOr(const std::string& key, bool fallback, const std::string& expected) const {
  return has(key) ? boolean(key, expected) : fallback;
}

double TomlTable::positiveOr(const std::string& key, double fallback, const std::string& expected) const {
  return has(key) ? positive(key, expected) : fallback;
}

std::string TomlTable::oneOfOr(const std::string& key, const std::vector<std::string>& options,
                               const std::string& fallback) const {
  return has(key) ? oneOf(key, options) : fallback;
}

double TomlTable::nonNegativeOr(const std::string& key, double fallback, const std::string& expected) const {
  if (!has(key)) return fallback;
  const double x = number(key, expected);
  if (x < 0.0) fail(key, describe(at(key)), expected);
  return x;
}

Eigen::Vector3d TomlTable::vec3Or(const std::string& key, const Eigen::Vector3d& fallback) const {
  return has(key) ? vec3(key) : fallback;
}

std::optional<double> TomlTable::quantity(const UnitKeys& units, const std::string& expected) const {
  std::optional<double> x;
  std::string given;
  for (const auto& [key, factor] : units) {
    if (!has(key)) continue;
    if (x) fail(key, "also " + given, "one key per quantity (one unit)");
    x = number(key, expected) * factor;
    given = key;
  }
  return x;
}

std::optional<double> TomlTable::positiveQuantity(const UnitKeys& units, const std::string& expected) const {
  for (const auto& [key, factor] : units)
    if (has(key)) positive(key, expected);
  return quantity(units, expected);
}

bool TomlTable::isString(const std::string& key) const { return has(key) && at(key).is_string(); }

TomlTable TomlTable::requireTable(const std::string& key, const std::string& expected) const {
  if (!has(key)) missing(key, expected.empty() ? "a table [" + dotted(key) + "]" : expected);
  return *table(key, expected);
}

std::vector<TomlTable> TomlTable::tables(const std::string& key) const {
  const std::string expected = "an array of tables [[" + dotted(key) + "]]";
  if (!has(key)) missing(key, expected);
  const toml::value& v = at(key);
  if (!v.is_array()) fail(key, describe(v), expected);
  std::vector<TomlTable> out;
  const auto& items = v.as_array();
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (!items[i].is_table()) fail(key, "an array holding " + describe(items[i]), expected);
    out.emplace_back(source_, items[i], fmt::format("{}[{}]", dotted(key), i));
  }
  return out;
}

std::optional<TomlTable> TomlTable::table(const std::string& key, const std::string& expected) const {
  if (!has(key)) return std::nullopt;
  const toml::value& v = at(key);
  if (!v.is_table()) fail(key, describe(v), expected.empty() ? "a table [" + dotted(key) + "]" : expected);
  return TomlTable(source_, v, dotted(key));
}

}  // namespace mesochain
