#pragma once
// The objective-cell settings from any input format mesochain reads: a DFTB+ input (a file
// ending in .hsd, input/hsd/dftb_input.hpp) or a cell file (TOML, input/cell_file.hpp).
#include <string>

#include "input/cell_file.hpp"

namespace mesochain::input {

bool isDftbInput(const std::string& path);
objective::CellInput readCellInputFile(const std::string& path);

}  // namespace mesochain::input
