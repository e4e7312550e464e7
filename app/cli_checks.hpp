#pragma once
// Validators of command-line values (CLI11 ->check): a value out of range ends in a parse error
// that names the option, the value and the range, before any work. Integers are read as 64-bit
// from digits only, so 3000000000 or 3e9 for an int option is refused with its limit instead of
// wrapping.
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "common/atomic_file.hpp"
#include "common/errors.hpp"

namespace mesochain::app {

// An integer from lo to hi (inclusive); `why` says where the limit comes from.
inline CLI::Validator integerIn(long long lo, long long hi, const std::string& why = "") {
  return CLI::Validator(
      [lo, hi, why](std::string& text) -> std::string {
        errno = 0;
        char* end = nullptr;
        const long long v = std::strtoll(text.c_str(), &end, 10);
        const std::string range = fmt::format("an integer from {} to {}{}", lo, hi,
                                              why.empty() ? "" : " (" + why + ")");
        if (text.empty() || *end != '\0' || errno == ERANGE || v < lo || v > hi)
          return fmt::format("found {}; expected {}", text, range);
        return {};
      },
      fmt::format("INT in [{}, {}]", lo, hi));
}

// A finite number > 0 (or >= 0 with zero allowed), at most `hi`.
inline CLI::Validator finiteNumber(bool zeroAllowed, double hi = 1e300) {
  return CLI::Validator(
      [zeroAllowed, hi](std::string& text) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        const bool ok = !text.empty() && *end == '\0' && std::isfinite(v) &&
                        (zeroAllowed ? v >= 0 : v > 0) && v <= hi;
        if (!ok)
          return fmt::format("found {}; expected a finite number {} 0{}", text,
                             zeroAllowed ? ">=" : ">", hi < 1e300 ? fmt::format(", at most {:g}", hi) : "");
        return {};
      },
      zeroAllowed ? "NUMBER >= 0" : "NUMBER > 0");
}

// A path that is not empty (an empty --json "" would otherwise be silently ignored).
inline CLI::Validator nonEmptyPath() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return text.empty() ? std::string("found an empty path; expected a file path") : "";
      },
      "PATH");
}

// Makes the output folder `dir` (with its parents) and checks a file can be written in it,
// before the computation: InputError(source, where, ...) naming the folder otherwise.
inline void prepareOutputFolder(const std::string& dir, const std::string& source,
                                const std::string& where) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw InputError(source, where, "\"" + dir + "\", which cannot be created (" + ec.message() + ")",
                     "a folder that can be created or exists");
  requireWritableOutput((std::filesystem::path(dir) / "file").string(), source, where);
}

}  // namespace mesochain::app
