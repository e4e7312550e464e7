#pragma once
// Output writers (orchestration-free): CSV time series of energies and probes, extended XYZ
// trajectory with quaternion orientations, legacy VTK polydata frames.
#include <fstream>
#include <string>
#include <vector>

#include "mdem/effect.hpp"
#include "mdem/parallel_bond.hpp"
#include "mdem/scene.hpp"

namespace mesochain::mdem {

// Columns: step, time_ns, kinetic_translational_zJ, kinetic_rotational_zJ, stretching_zJ,
// shearing_zJ, twisting_zJ, bending_zJ, load_potential_zJ, vdw_zJ, total_zJ,
// contact_dissipated_zJ (work of the dashpots so far, not in the total), then for each probe
// element p: p<i>_ux_nm, _uy_nm, _uz_nm (displacement), p<i>_rx_rad, _ry_rad, _rz_rad
// (accumulated rotation, integral of omega dt).
class EnergyCsvWriter {
 public:
  EnergyCsvWriter(const std::string& path, std::vector<int> probes);
  void write(long step, double time, const Energies& e, const Bodies& b);

 private:
  std::ofstream out_;
  std::vector<int> probes_;
};

// Extended XYZ (one frame appended per call), readable by OVITO and ASE:
//   Properties=species:S:1:pos:R:3:orientation:R:4:aspherical_shape:R:3:velo:R:3
// orientation is the quaternion in OVITO's order (x, y, z, w); aspherical_shape is the half
// extents along the body axes (nm). Lengths in nm, velocities in nm/ns.
void writeXyzFrame(std::ostream& out, const Bodies& b, const std::vector<ElementType>& types,
                   double time, long step);

// Legacy VTK (ASCII POLYDATA) for ParaView / OVITO: points = element centres (nm), vertices,
// lines = bonds; point data: element id, type, quaternion (w, x, y, z) and the body axes
// axis_x (thickness), axis_y (width), axis_z (length) as vectors; cell data none.
void writeVtkFrame(const std::string& path, const Bodies& b, const std::vector<Bond>& bonds,
                   double time);

}  // namespace mesochain::mdem
