#pragma once
// No non-finite number is ever written: the JSON and TOML outputs are checked before they are
// written (nlohmann::json writes NaN and inf as null, TOML as nan/inf, so a reader would take a
// failed computation for a result). The error names the output, the entry and the value.
#include <string>

#include <nlohmann/json.hpp>

namespace mesochain {

// Throws NumericalError naming `output` and the JSON pointer of the first non-finite number
// (explicit nulls, written on purpose for "not measured", pass).
void requireFiniteJson(const nlohmann::json& j, const std::string& output);
// The same for a TOML text about to be written (parsed, every float checked).
void requireFiniteToml(const std::string& text, const std::string& output);

}  // namespace mesochain
