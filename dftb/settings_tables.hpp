#pragma once
// The calculator settings serialised as the cell file's tables (docs/cell-file.md): each table's
// entries (common/setting_entries.hpp) come from the function that also writes that table, so
// the keys, units and order are listed once, beside the settings. The cell writer, the extended
// XYZ keys and the scan identity (objective/drivers/scan.cpp) render these entries; a member
// added to CalculatorSettings or to one of its structs stops the build in settings_tables.cpp
// until it is given its entries.
#include <string>
#include <vector>

#include "common/setting_entries.hpp"
#include "dftb/band_table.hpp"
#include "dftb/calculator.hpp"

namespace mesochain::dftb {

struct SettingsTable {
  std::string name;  // the cell file's table, e.g. "scc"
  SettingEntries entries;
};

// Every table of the calculator settings with every key (also [scc] with SCC off), in the cell
// file's order: kpoints, electrons, dispersion, scc. The eigenvector path of the band settings is
// not a setting of the results (every path gives the same results to rounding,
// tests/dftb/test_eigenvector_paths.cpp) and has no entry.
std::vector<SettingsTable> calculatorSettingsTables(const CalculatorSettings& c, bool ring);

}  // namespace mesochain::dftb
