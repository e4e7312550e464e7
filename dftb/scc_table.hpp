#pragma once
// The [scc] table of the cell file (docs/cell-file.md) beside the SCC settings it fills
// (dftb/scc_term.hpp): its keys, ranges and defaults are read here and written back here, so
// the cell-file reader and writer, the extended XYZ settings keys and the Python dicts list no
// key of it.
#include "common/setting_entries.hpp"
#include "common/toml_table.hpp"
#include "dftb/scc_term.hpp"

namespace mesochain::dftb {

// Reads the keys present into `s` (an absent key keeps its value, the SccSettings default);
// strict: an unknown key, a wrong type or a value out of range is an InputError naming it.
void readSccTable(const TomlTable& t, SccSettings& s);

// Every key of the table, in order, as it reads back to `s` (the cell file writes the table only
// when SCC is on, the extended XYZ keys only enabled = F when it is off).
SettingEntries sccTableEntries(const SccSettings& s);

}  // namespace mesochain::dftb
