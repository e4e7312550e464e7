#pragma once
// Strict reading of TOML tables (toml11 v3): every value is checked for type and range, and a
// key that the caller does not know is an error. Every failure is an InputError naming the
// file, the dotted key path and its line.
#include <initializer_list>
#include <string>
#include <vector>

#include <toml.hpp>

#include "common/toml_file.hpp"

#include "mdem/quaternion.hpp"

namespace mesochain::mdem {

class TomlTable {
 public:
  // `path` is the dotted key of this table ("" for the root), for messages.
  TomlTable(const toml::value& value, std::string source, std::string path);

  // Throws for any key not in `allowed`.
  void allowOnly(std::initializer_list<const char*> allowed) const;

  bool has(const std::string& key) const;
  bool isString(const std::string& key) const;  // present and a string
  // Dotted key path plus line, e.g. "key run.time_step_ns (line 12)".
  std::string where(const std::string& key) const;
  const std::string& source() const { return source_; }

  double number(const std::string& key) const;  // required; integers accepted
  double number(const std::string& key, double fallback) const;
  double positive(const std::string& key) const;  // required, > 0
  double nonNegative(const std::string& key, double fallback) const;
  long integer(const std::string& key) const;
  long integer(const std::string& key, long fallback) const;
  std::string string(const std::string& key) const;
  std::string string(const std::string& key, const std::string& fallback) const;
  Vec3 vec3(const std::string& key) const;
  Vec3 vec3(const std::string& key, const Vec3& fallback) const;
  std::vector<double> numbers(const std::string& key) const;
  std::vector<long> integers(const std::string& key) const;
  std::vector<std::string> strings(const std::string& key) const;
  TomlTable table(const std::string& key) const;
  std::vector<TomlTable> tables(const std::string& key) const;  // array of tables ([[key]])

  // Throws an InputError at `key` with what was found and what was expected.
  [[noreturn]] void fail(const std::string& key, const std::string& found,
                         const std::string& expected) const;

 private:
  const toml::value& at(const std::string& key) const;
  double toNumber(const toml::value& v, const std::string& key) const;

  const toml::value* value_;
  std::string source_;
  std::string path_;
};

// Index of the entry of `types` (anything with a `name`: element or bond types) that the string
// at `key` names; an InputError listing the defined names otherwise.
template <class Types>
int findNamed(const Types& types, const TomlTable& t, const std::string& key) {
  const std::string n = t.string(key);
  std::string list;
  for (std::size_t i = 0; i < types.size(); ++i) {
    if (types[i].name == n) return static_cast<int>(i);
    list += (list.empty() ? "" : ", ") + types[i].name;
  }
  t.fail(key, "\"" + n + "\"", list.empty() ? "a defined type (none is defined)" : "one of the defined types: " + list);
}

}  // namespace mesochain::mdem
