#pragma once
// The [kpoints] and [electrons] tables of the cell file (docs/cell-file.md) beside the band
// settings they fill (dftb/band_structure.hpp): read here and written back here, as the [scc]
// and [dispersion] tables are (dftb/scc_table.hpp, dftb/dispersion_table.hpp).
#include "common/setting_entries.hpp"
#include "common/toml_table.hpp"
#include "dftb/band_structure.hpp"

namespace mesochain::dftb {

// [kpoints] helical = N (1 .. 1e6; required for a screw, absent or 1 for a closed ring, which
// has no helical wave number) and angular = "all" | M (sampled angular quantum numbers).
void readKPointsTable(const TomlTable& t, bool ring, BandSettings& s);
// [electrons] temperature (K, within common/electronic_temperature.hpp's range).
void readElectronsTable(const TomlTable& t, BandSettings& s);

// The keys as they read back: [kpoints] helical (not for a ring) and angular (an integer or
// "all"); [electrons] temperature in K.
SettingEntries kpointsTableEntries(const BandSettings& s, bool ring);
SettingEntries electronsTableEntries(const BandSettings& s);

}  // namespace mesochain::dftb
