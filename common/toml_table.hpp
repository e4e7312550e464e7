#pragma once
// Strict access to one table of a TOML input (toml11 v3): every error is an InputError naming
// the file, the dotted key and its line, what was found and what was expected. The reader of the
// cell, scan and skgen formats (objective/core/cell_file*, objective/drivers/scan_file,
// skgen/skgen_job); the files themselves are read by common/toml_file.hpp. (mdem's scene and
// model files still have their own reader, mdem/toml_reader.hpp: issue 13 item 3.)
#include <optional>
#include <string>
#include <vector>

#include <toml.hpp>

namespace mesochain {

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

  // Throws for the first key (alphabetically) that is not listed, naming the allowed keys.
  void allowOnly(const std::vector<std::string>& allowed) const;
  [[noreturn]] void fail(const std::string& key, const std::string& found,
                         const std::string& expected) const;
  [[noreturn]] void missing(const std::string& key, const std::string& expected) const;

  // Typed access. A number may be written as an integer or a float; it must be finite.
  double number(const std::string& key, const std::string& expected) const;
  long integer(const std::string& key, const std::string& expected) const;
  std::string string(const std::string& key, const std::string& expected) const;
  bool boolean(const std::string& key, const std::string& expected) const;
  std::optional<TomlTable> table(const std::string& key) const;  // absent -> nullopt

 private:
  std::string source_;
  const toml::value* table_;
  std::string name_;
};

// "a string", "an integer", ... for messages; `describe` also shows short values.
std::string typeName(const toml::value& v);
std::string describe(const toml::value& v);
// A number (integer or float) or nullopt; non-finite numbers are returned as they are.
std::optional<double> asNumber(const toml::value& v);
// Line of a value (0 when unknown: a value built in memory); lineSuffix is " (line N)" or "".
int lineOf(const toml::value& v);
std::string lineSuffix(const toml::value& v);

}  // namespace mesochain
