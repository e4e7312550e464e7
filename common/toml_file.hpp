#pragma once
// Reading a TOML input file with errors a user can act on: a missing file, an unreadable one or
// a syntax error becomes a mesochain::InputError that names the file (and, for a syntax error,
// the line). Every input format of mesochain (cell, scan, scene, model, beam constants, plate,
// skgen) reads its file through this one function.
#include <string>

#include <toml.hpp>

namespace mesochain {

// `kind` names what the file should be, e.g. "cell file" (used in the messages).
toml::value parseTomlFile(const std::string& path, const std::string& kind);

}  // namespace mesochain
