#include "common/errors.hpp"

#include <cmath>

namespace mesochain {

namespace {
std::string compose(const std::string& source, const std::string& where, const std::string& found,
                    const std::string& expected) {
  std::string msg = source;
  if (!where.empty()) msg += ", " + where;
  msg += ": found " + found + "; expected " + expected;
  return msg;
}
}  // namespace

InputError::InputError(std::string source, std::string where, std::string found,
                       std::string expected)
    : std::runtime_error(compose(source, where, found, expected)),
      source_(std::move(source)),
      where_(std::move(where)) {}

InputError::InputError(std::string source, std::string message)
    : std::runtime_error(source + ": " + message), source_(std::move(source)) {}

void requireFinite(double x, const std::string& source, const std::string& what) {
  if (!std::isfinite(x)) throw InputError(source, what, "a non-finite number", "a finite number");
}

}  // namespace mesochain
