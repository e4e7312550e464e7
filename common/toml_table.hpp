#pragma once
// Strict access to one table of a TOML input (toml11 v3): every error is an InputError naming
// the file, the dotted key and its line, what was found and what was expected. The one table
// reader of every TOML format (cell, scan, chain, skgen, mdem scene and model, beam constants,
// plate); the files themselves are read by common/toml_file.hpp.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <toml.hpp>

namespace mesochain {

class TomlRow;

class TomlTable {
 public:
  // `name` is the dotted path of the table ("" for the root).
  TomlTable(std::string source, const toml::value& table, std::string name);

  const std::string& source() const { return source_; }
  const std::string& name() const { return name_; }
  bool has(const std::string& key) const;
  const toml::value& at(const std::string& key) const;
  // The sorted keys present.
  std::vector<std::string> keys() const;
  // "key symmetry.twist (line 7)"; for a missing key, the line of the table header.
  std::string where(const std::string& key) const;
  std::string dotted(const std::string& key) const;
  int line(const std::string& key) const;  // 0 when unknown

  // Throws for the first key (alphabetically) that is not listed, naming the allowed keys. An
  // entry written "[name]" allows the key `name` and says in the message that it is a table.
  void allowOnly(const std::vector<std::string>& allowed) const;
  [[noreturn]] void fail(const std::string& key, const std::string& found,
                         const std::string& expected) const;
  [[noreturn]] void missing(const std::string& key, const std::string& expected) const;

  // Typed access to a required key; `expected` is what the message asks for. A number may be
  // written as an integer or a float; it must be finite.
  double number(const std::string& key, const std::string& expected = "a number") const;
  long integer(const std::string& key, const std::string& expected = "an integer") const;
  std::string string(const std::string& key, const std::string& expected = "a string") const;
  bool boolean(const std::string& key, const std::string& expected = "true or false") const;
  double positive(const std::string& key, const std::string& expected = "a positive number") const;
  long integerIn(const std::string& key, long lo, long hi) const;  // "an integer from lo to hi"
  // [x, y, z]: three finite numbers.
  Eigen::Vector3d vec3(const std::string& key, const std::string& expected = "3 numbers [x, y, z]") const;
  // An integer in [lo, hi] or the string `word` (e.g. angular = "all" | 12): nullopt for the
  // word; the message asks for "\"word\" or an integer from lo to hi" plus `what`.
  std::optional<long> integerOrWord(const std::string& key, const std::string& word, long lo, long hi,
                                    const std::string& what = "") const;
  // One of `options` (a string): "\"a\", \"b\" or \"c\"" is what the message asks for.
  std::string oneOf(const std::string& key, const std::vector<std::string>& options) const;
  // Arrays of one type (every element checked; an empty array is returned as it is).
  std::vector<double> numbers(const std::string& key, const std::string& expected = "an array of finite numbers") const;
  std::vector<long> integers(const std::string& key, const std::string& expected = "an array of integers") const;
  std::vector<std::string> strings(const std::string& key, const std::string& expected = "an array of strings") const;
  // An array whose elements are each a finite number or a string, as text: integers in decimal,
  // floats in the shortest form that reads back ("{}" of fmt: 0.5, 1e-05, 300), strings as they
  // are. For settings a command line would take as words (e.g. the chain file's [knobs]).
  std::vector<std::string> numbersOrStrings(
      const std::string& key, const std::string& expected = "an array of numbers or strings") const;

  // An array of arrays of `width` entries each (e.g. atoms = [["C", 0.0, 0.0, 0.0], ...] or
  // walls = [[5, 5], [10, 10]]); empty or not such an array: the InputError naming the key,
  // the entry (as `noun` k, counted from 1) and `expected`. Each row reads its entries by index
  // (TomlRow).
  std::vector<TomlRow> rows(const std::string& key, std::size_t width, const std::string& expected,
                            const std::string& noun = "entry") const;

  // The same for an optional key: `fallback` when it is absent.
  double numberOr(const std::string& key, double fallback, const std::string& expected = "a number") const;
  long integerOr(const std::string& key, long fallback, const std::string& expected = "an integer") const;
  std::string stringOr(const std::string& key, const std::string& fallback,
                       const std::string& expected = "a string") const;
  bool booleanOr(const std::string& key, bool fallback, const std::string& expected = "true or false") const;
  double positiveOr(const std::string& key, double fallback,
                    const std::string& expected = "a positive number") const;
  std::string oneOfOr(const std::string& key, const std::vector<std::string>& options,
                      const std::string& fallback) const;
  double nonNegativeOr(const std::string& key, double fallback,
                       const std::string& expected = "a number >= 0") const;
  Eigen::Vector3d vec3Or(const std::string& key, const Eigen::Vector3d& fallback) const;
  bool isString(const std::string& key) const;  // present and a string

  // A quantity that may be given in one of several units: {key, factor to the internal unit}
  // per unit. At most one of the keys may be present ("one key per quantity"); the value times
  // its factor, or nullopt when none is given. `positiveQuantity` also requires a value > 0.
  using UnitKeys = std::vector<std::pair<std::string, double>>;
  std::optional<double> quantity(const UnitKeys& units, const std::string& expected = "a number") const;
  std::optional<double> positiveQuantity(const UnitKeys& units, const std::string& expected = "a value > 0") const;

  // Sub-tables: `table` is nullopt when absent, `requireTable` fails then; `tables` reads an
  // array of tables ([[key]]), named key[0], key[1], ... in messages. `expected` defaults to
  // "a table [dotted.key]".
  std::optional<TomlTable> table(const std::string& key, const std::string& expected = "") const;
  TomlTable requireTable(const std::string& key, const std::string& expected = "") const;
  std::vector<TomlTable> tables(const std::string& key) const;

 private:
  std::string source_;
  const toml::value* table_;
  std::string name_;
};

// One row of TomlTable::rows: typed entries by index; errors name the key, the row (counted
// from 1) and its line: "key geometry.atoms, atom 2 (line 7)".
class TomlRow {
 public:
  TomlRow(std::string source, std::string where, const toml::value& row, std::string expected);
  std::size_t size() const { return row_->as_array().size(); }
  double number(std::size_t i) const;  // finite
  long integer(std::size_t i) const;
  std::string string(std::size_t i) const;
  [[noreturn]] void fail(const std::string& found) const;
  [[noreturn]] void fail(const std::string& found, const std::string& expected) const;

 private:
  std::string source_, where_;
  const toml::value* row_;
  std::string expected_;
};

// Index of the entry of `types` (anything with a `name`, e.g. mdem's element or bond types) that
// the string at `key` names; an InputError listing the defined names otherwise.
template <class Types>
int findNamed(const Types& types, const TomlTable& t, const std::string& key) {
  const std::string n = t.string(key);
  std::string list;
  for (std::size_t i = 0; i < types.size(); ++i) {
    if (types[i].name == n) return static_cast<int>(i);
    list += (list.empty() ? "" : ", ") + types[i].name;
  }
  t.fail(key, "\"" + n + "\"",
         list.empty() ? "a defined type (none is defined)" : "one of the defined types: " + list);
}

// "a string", "an integer", ... for messages; `describe` also shows short values.
std::string typeName(const toml::value& v);
std::string describe(const toml::value& v);
// A number (integer or float) or nullopt; non-finite numbers are returned as they are.
std::optional<double> asNumber(const toml::value& v);
// Line of a value (0 when unknown: a value built in memory); lineSuffix is " (line N)" or "".
int lineOf(const toml::value& v);
std::string lineSuffix(const toml::value& v);

}  // namespace mesochain
