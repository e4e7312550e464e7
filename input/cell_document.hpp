#pragma once
// The cell-file reader on a TOML document that is already in memory (the Python module builds
// one from a dict): the same keys, units, defaults and errors as readCellFile. Relative paths
// ([geometry] file, [parameters] tables) are taken relative to the directory of `source`
// (the working folder when `source` has none, e.g. "<dict>").
#include <string>

#include <toml.hpp>

#include "input/cell_file.hpp"

namespace mesochain::objective {

CellInput readCellDocument(const toml::value& document, const std::string& source);

}  // namespace mesochain::objective
