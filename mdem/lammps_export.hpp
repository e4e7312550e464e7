#pragma once
// Export of an mDEM tube network for the LAMMPS peer of `mesochain-bench network`
// (bench/lammps/README.md): the same network as point particles with bonds, angles and a pair table.
#include <string>

#include "mdem/scene.hpp"

namespace mesochain::mdem {

// Writes PREFIX.data (atoms, bonds, angles), PREFIX.table (pair table "VDW") and
// PREFIX.settings (bond/angle/pair coefficients, skin, time step `timeStep` in ns).
void writeLammpsNetwork(const Scene& scene, double timeStep, const std::string& prefix);

}  // namespace mesochain::mdem
