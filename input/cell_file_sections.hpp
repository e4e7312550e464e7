#pragma once
// Parts of the cell-file reader (cell_file.cpp): the structure ([geometry] or [builder], and
// [symmetry]).
#include "input/cell_file.hpp"
#include "common/toml_table.hpp"

namespace mesochain::objective::detail {

// Fills in.cell (geometry and symmetry) from [geometry] + [symmetry] or [builder].
void readStructure(const TomlTable& root, CellInput& in);

}  // namespace mesochain::objective::detail
