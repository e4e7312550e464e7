#pragma once
// Export of the `mesochain bench network` scene for its LAMMPS peer (bench/lammps/README.md).
#include <string>

#include "mdem/scene.hpp"

namespace mesochain::app {

// Writes PREFIX.data (atoms, bonds, angles), PREFIX.table (pair table "VDW") and
// PREFIX.settings (bond/angle/pair coefficients, skin, time step `timeStep` in ns).
void writeLammpsNetwork(const mdem::Scene& scene, double timeStep, const std::string& prefix);

}  // namespace mesochain::app
