#pragma once
// Reading a TOML input file with errors a user can act on: a missing file, an unreadable one or
// a syntax error becomes a mesochain::InputError that names the file (and, for a syntax error,
// the line). Every input format of mesochain (cell, scan, scene, model, beam constants, plate,
// skgen) reads its file through this one function.
//
// Command-line overrides (`mesochain --set section.key=value` and `--unset section.key`,
// docs/command-line.md) are merged into the first TOML file a command reads (the input named on
// its command line) before the strict reader of that format sees it: an unknown key is then the
// reader's usual error, and a value set from the command line is reported as "set by --set ..."
// instead of a line. Removals are applied before the values, so `--unset relax --set
// relax.max_steps=10` replaces the whole table.
#include <string>
#include <vector>

#include <toml.hpp>

namespace mesochain {

// `kind` names what the file should be, e.g. "cell file" (used in the messages).
toml::value parseTomlFile(const std::string& path, const std::string& kind);

// One `--set section.key=value`: the dotted key path and the value as a TOML value (a text that
// is no TOML value, e.g. relax, is taken as the string "relax").
// One `--unset section.key` is the same with `remove` set and no value.
struct TomlOverride {
  std::string text;              // as given, for messages
  std::vector<std::string> key;  // "kpoints.helical" -> {"kpoints", "helical"}
  toml::value value;
  bool remove = false;           // --unset: delete the key (a value or a whole table)
};

// Parses "section.key=value"; InputError naming the option when it is not of that form.
TomlOverride parseTomlOverride(const std::string& text);
// Parses the "section.key" of `--unset`; InputError naming the option when it is not a dotted key.
TomlOverride parseTomlRemoval(const std::string& text);

// Merges `o` into `root` (tables on the path are created), or removes its key; InputError(source,
// ...) when a key on the path is a value that is not a table, or when a key to remove is not in
// the file (a misspelt --unset must not pass silently).
void applyTomlOverride(toml::value& root, const TomlOverride& o, const std::string& source);

// The overrides of this process (set once by main; removals first); parseTomlFile applies them
// to the first file it reads and marks them used.
void setTomlOverrides(std::vector<TomlOverride> overrides);
// True when overrides were given and no TOML file has been read yet (main warns).
bool tomlOverridesUnused();

// "line 12", or "set by --set kpoints.helical=4" for a value that came from the command line.
std::string tomlWhere(const toml::value& v);

}  // namespace mesochain
