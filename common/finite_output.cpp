#include "common/finite_output.hpp"

#include <cmath>
#include <sstream>

#include <fmt/format.h>
#include <toml.hpp>

#include "common/errors.hpp"

namespace mesochain {

namespace {
[[noreturn]] void nonFinite(const std::string& output, const std::string& entry, double x) {
  throw NumericalError(fmt::format(
      "{}: entry {} would be written as {}: a non-finite result (an overflow or a failed "
      "computation from the inputs); nothing was written",
      output, entry, x));
}

void walkJson(const nlohmann::json& j, const std::string& pointer, const std::string& output) {
  if (j.is_number_float()) {
    const double x = j.get<double>();
    if (!std::isfinite(x)) nonFinite(output, pointer.empty() ? "/" : pointer, x);
  } else if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) walkJson(*it, pointer + "/" + it.key(), output);
  } else if (j.is_array()) {
    for (std::size_t k = 0; k < j.size(); ++k)
      walkJson(j[k], pointer + "/" + std::to_string(k), output);
  }
}

void walkToml(const toml::value& v, const std::string& key, const std::string& output) {
  if (v.is_floating()) {
    const double x = v.as_floating();
    if (!std::isfinite(x)) nonFinite(output, key, x);
  } else if (v.is_table()) {
    for (const auto& [k, e] : v.as_table()) walkToml(e, key.empty() ? k : key + "." + k, output);
  } else if (v.is_array()) {
    const auto& a = v.as_array();
    for (std::size_t k = 0; k < a.size(); ++k)
      walkToml(a[k], fmt::format("{}[{}]", key, k), output);
  }
}
}  // namespace

void requireFiniteJson(const nlohmann::json& j, const std::string& output) {
  walkJson(j, "", output);
}

void requireFiniteToml(const std::string& text, const std::string& output) {
  std::istringstream in(text);
  walkToml(toml::parse(in, output), "", output);
}

}  // namespace mesochain
