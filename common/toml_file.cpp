#include "common/toml_file.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "common/errors.hpp"

namespace mesochain {

toml::value parseTomlFile(const std::string& path, const std::string& kind) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path, "", "no such file (or not a regular file)", "an existing TOML " + kind);
  try {
    return toml::parse(path);
  } catch (const toml::syntax_error& e) {
    throw InputError(path, fmt::format("line {}", e.location().line()), "invalid TOML syntax",
                     std::string("valid TOML (") + e.what() + ")");
  } catch (const std::exception& e) {
    throw InputError(path, "", std::string("a file that cannot be read as TOML: ") + e.what(),
                     "a readable TOML " + kind);
  }
}

}  // namespace mesochain
