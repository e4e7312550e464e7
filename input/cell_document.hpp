#pragma once
// The cell-file reader on a TOML document that is already in memory (the Python module builds
// one from a dict): the same keys, units, defaults and errors as readCellFile. Relative paths
// ([geometry] file, [parameters] tables) are taken relative to the directory of `source`
// (the working folder when `source` has none, e.g. "<dict>").
#include <string>

#include <toml.hpp>

#include "input/cell_file.hpp"

namespace mesochain::objective {

// `name`: the dotted path of the document's table in its file ("" for a whole cell file; "cell"
// for the inline [cell] of a chain file), prefixed to the keys errors name.
CellInput readCellDocument(const toml::value& document, const std::string& source, const std::string& name = "");

}  // namespace mesochain::objective
