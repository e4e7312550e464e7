#include "mdem/toml_reader.hpp"

#include <cmath>
#include <filesystem>

#include "common/errors.hpp"
#include "common/toml_file.hpp"

namespace mesochain::mdem {

TomlTable::TomlTable(const toml::value& value, std::string source, std::string path)
    : value_(&value), source_(std::move(source)), path_(std::move(path)) {
  if (!value.is_table())
    throw InputError(source_, "key " + (path_.empty() ? std::string("<root>") : path_),
                     "a " + toml::stringize(value.type()), "a table");
}

std::string TomlTable::where(const std::string& key) const {
  const std::string full = path_.empty() ? key : path_ + "." + key;
  std::string w = "key " + full;
  if (has(key)) w += " (" + tomlWhere(value_->at(key)) + ")";
  return w;
}

void TomlTable::fail(const std::string& key, const std::string& found,
                     const std::string& expected) const {
  throw InputError(source_, where(key), found, expected);
}

void TomlTable::allowOnly(std::initializer_list<const char*> allowed) const {
  for (const auto& [key, v] : value_->as_table()) {
    bool ok = false;
    for (const char* a : allowed) ok = ok || key == a;
    if (ok) continue;
    std::string list;
    for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    fail(key, "an unknown key", "one of: " + list);
  }
}

bool TomlTable::has(const std::string& key) const { return value_->contains(key); }
bool TomlTable::isString(const std::string& key) const { return has(key) && value_->at(key).is_string(); }

const toml::value& TomlTable::at(const std::string& key) const {
  if (!has(key)) fail(key, "nothing", "this key (it is required)");
  return value_->at(key);
}

double TomlTable::toNumber(const toml::value& v, const std::string& key) const {
  double x;
  if (v.is_integer()) {
    x = static_cast<double>(v.as_integer());
  } else if (v.is_floating()) {
    x = v.as_floating();
  } else {
    fail(key, "a " + toml::stringize(v.type()), "a number");
  }
  if (!std::isfinite(x)) fail(key, "a non-finite number", "a finite number");
  return x;
}

double TomlTable::number(const std::string& key) const { return toNumber(at(key), key); }

double TomlTable::number(const std::string& key, double fallback) const {
  return has(key) ? number(key) : fallback;
}

double TomlTable::positive(const std::string& key) const {
  const double x = number(key);
  if (!(x > 0.0)) fail(key, std::to_string(x), "a positive number");
  return x;
}

double TomlTable::nonNegative(const std::string& key, double fallback) const {
  const double x = number(key, fallback);
  if (x < 0.0) fail(key, std::to_string(x), "a number >= 0");
  return x;
}

long TomlTable::integer(const std::string& key) const {
  const toml::value& v = at(key);
  if (!v.is_integer()) fail(key, "a " + toml::stringize(v.type()), "an integer");
  return static_cast<long>(v.as_integer());
}

long TomlTable::integer(const std::string& key, long fallback) const {
  return has(key) ? integer(key) : fallback;
}

std::string TomlTable::string(const std::string& key) const {
  const toml::value& v = at(key);
  if (!v.is_string()) fail(key, "a " + toml::stringize(v.type()), "a string");
  return v.as_string().str;
}

std::string TomlTable::string(const std::string& key, const std::string& fallback) const {
  return has(key) ? string(key) : fallback;
}

std::vector<double> TomlTable::numbers(const std::string& key) const {
  const toml::value& v = at(key);
  if (!v.is_array()) fail(key, "a " + toml::stringize(v.type()), "an array of numbers");
  std::vector<double> out;
  for (const toml::value& e : v.as_array()) out.push_back(toNumber(e, key));
  return out;
}

std::vector<long> TomlTable::integers(const std::string& key) const {
  const toml::value& v = at(key);
  if (!v.is_array()) fail(key, "a " + toml::stringize(v.type()), "an array of integers");
  std::vector<long> out;
  for (const toml::value& e : v.as_array()) {
    if (!e.is_integer()) fail(key, "an array holding a " + toml::stringize(e.type()), "integers");
    out.push_back(static_cast<long>(e.as_integer()));
  }
  return out;
}

Vec3 TomlTable::vec3(const std::string& key) const {
  const std::vector<double> x = numbers(key);
  if (x.size() != 3) fail(key, std::to_string(x.size()) + " numbers", "3 numbers [x, y, z]");
  return {x[0], x[1], x[2]};
}

Vec3 TomlTable::vec3(const std::string& key, const Vec3& fallback) const {
  return has(key) ? vec3(key) : fallback;
}

std::vector<std::string> TomlTable::strings(const std::string& key) const {
  const toml::value& v = at(key);
  if (!v.is_array()) fail(key, "a " + toml::stringize(v.type()), "an array of strings");
  std::vector<std::string> out;
  for (const toml::value& e : v.as_array()) {
    if (!e.is_string()) fail(key, "an array holding a " + toml::stringize(e.type()), "strings");
    out.push_back(e.as_string().str);
  }
  return out;
}

TomlTable TomlTable::table(const std::string& key) const {
  return TomlTable(at(key), source_, path_.empty() ? key : path_ + "." + key);
}

std::vector<TomlTable> TomlTable::tables(const std::string& key) const {
  const toml::value& v = at(key);
  if (!v.is_array()) fail(key, "a " + toml::stringize(v.type()), "an array of tables [[" + key + "]]");
  std::vector<TomlTable> out;
  const auto& arr = v.as_array();
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const std::string p = (path_.empty() ? key : path_ + "." + key) + "[" + std::to_string(i) + "]";
    out.emplace_back(arr[i], source_, p);
  }
  return out;
}

}  // namespace mesochain::mdem
