#pragma once
// The settings that produced an energy, on the comment line of an extended XYZ file (written by
// `mesochain run --structure`; read by the ASE calculator mesochain.ase, docs/python.md).
// Each key is `mesochain:` plus the dotted cell-file key, with the cell file's unit
// (docs/cell-file.md):
//   mesochain:kpoints.helical=64 (screw only)  mesochain:kpoints.angular=all | M
//   mesochain:electrons.temperature=300 (K)    mesochain:parameters.set=pbc-0-3
//   mesochain:parameters.C-H="/abs/C-H.skf" (tables not from the set)
//   mesochain:parameters.max_angular_momentum.C=p
//   mesochain:dispersion.model=lj  mesochain:dispersion.epsilon=... (kcal/mol) r0, cutoff (Å)
//   summation, ewald_tolerance;  mesochain:scc.enabled=T and the other [scc] keys when on.
// Booleans are T / F (the extxyz convention). The mesochain C++ readers accept these keys and
// take only atoms and symmetry from an .xyz geometry (a cell file states its own settings).
#include <string>

#include "input/cell_file.hpp"

namespace mesochain::objective {

// " key=value key=value ..." (with a leading blank), for the comment line.
std::string xyzSettingsKeys(const CellInput& input);
// True for a key of the form above (mesochain:<section>.<key> of one of the settings tables).
bool isXyzSettingsKey(const std::string& key);

}  // namespace mesochain::objective
