#pragma once
// Exports of the mDEM benchmarks' scenes for their LAMMPS peers (bench/lammps/README.md): the tube
// network of `mesochain-bench network` as point particles with bonds, angles and a pair table; the
// bonded filaments of `mesochain-bench dem` as BPM spheres with `bpm/rotational` bonds.
#include <string>

#include "mdem/scene.hpp"

namespace mesochain::mdem {

// Writes PREFIX.data (atoms, bonds, angles), PREFIX.table (pair table "VDW") and
// PREFIX.settings (bond/angle/pair coefficients, skin, time step `timeStep` in ns).
void writeLammpsNetwork(const Scene& scene, double timeStep, const std::string& prefix);

// Writes PREFIX.data (atom_style bpm/sphere: one sphere per element, the element's mass, diameter
// the bond's rest length; bonds as the scene's) and PREFIX.settings (bond_style bpm/rotational
// coefficients mapped from the parallel bonds, time step `timeStep` in ns) for
// bench/lammps/in.chain-bpm. Bonds of one rest length and stiffness only.
void writeLammpsBpmChains(const Scene& scene, double timeStep, const std::string& prefix);

}  // namespace mesochain::mdem
