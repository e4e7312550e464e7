#pragma once
// Output writers (orchestration-free): CSV time series of energies and probes, extended XYZ
// trajectory with quaternion orientations, legacy VTK polydata frames.
#include <fstream>
#include <string>
#include <vector>

#include "mdem/append_file.hpp"
#include "mdem/effect.hpp"
#include "mdem/parallel_bond.hpp"
#include "mdem/scene.hpp"

namespace mesochain::mdem {

// Columns: step, time_ns, then the ledger's kinetic and potential entries in its order as
// NAME_zJ (kinetic_translational, kinetic_rotational, then each effect's: stretching, shearing,
// twisting, bending for bonds; vdw; load_potential), total_zJ, then the dissipated entries
// (contact_dissipated_zJ: work of the dashpots so far, not in the total), then for each probe
// element p: p<i>_ux_nm, _uy_nm, _uz_nm (displacement), p<i>_rx_rad, _ry_rad, _rz_rad
// (accumulated rotation, integral of omega dt). Only the effects a scene builds have columns.
class EnergyCsvWriter {
 public:
  // `layout`: a ledger of the run (its names and kinds fix the columns). resumeAt >= 0: append
  // to the file of an interrupted run, cut back to that length (append_file.hpp).
  EnergyCsvWriter(const std::string& path, const EnergyLedger& layout, std::vector<int> probes,
                  std::int64_t resumeAt = -1);
  void write(long step, double time, const EnergyLedger& e, const Bodies& b);
  std::int64_t bytes() const { return out_.bytes(); }

 private:
  AppendFile out_;
  std::vector<std::string> columns_;  // ledger entries in column order ("" = the total)
  std::vector<int> probes_;
};

// The ledger's entries in CSV column order: kinetic and potential entries, "" for the total,
// then the dissipated entries.
std::vector<std::string> energyColumns(const EnergyLedger& layout);

// Extended XYZ (one frame appended per call), readable by OVITO and ASE:
//   Properties=species:S:1:pos:R:3:orientation:R:4:aspherical_shape:R:3:velo:R:3
// orientation is the quaternion in OVITO's order (x, y, z, w); aspherical_shape is the half
// extents along the body axes (nm). Lengths in nm, velocities in nm/ns.
void writeXyzFrame(std::ostream& out, const Bodies& b, const std::vector<ElementType>& types,
                   double time, long step);

// Legacy VTK (ASCII POLYDATA) for ParaView / OVITO: points = element centres (nm), vertices,
// lines = bonds; point data: element id, type, quaternion (w, x, y, z), the body axes
// axis_x (thickness), axis_y (width), axis_z (length) as vectors, velocity, and (when given)
// each element's energy (zJ, its share of the bonds' and contacts' stored energy); cell data
// (when given; zero on the vertex cells): per bond normal_force_pN (tension > 0), shear_force_pN,
// bending_moment_pN_nm, twisting_moment_pN_nm. Written atomically.
struct VtkFields {
  std::vector<double> elementEnergy;  // per element, or empty
  std::vector<BondLoad> bondLoads;    // per bond, or empty
  // Per element, or empty: half extents in the body frame (nm; x thickness, y width, z length
  // for a brick; radius, radius, half length for a cylinder) and the shape (0 brick,
  // 1 cylinder), for ParaView glyphs (scale by half_extents_nm, orient by axis_z).
  std::vector<Vec3> halfExtents;
  std::vector<int> shape;
};
void writeVtkFrame(const std::string& path, const Bodies& b, const std::vector<Bond>& bonds,
                   double time, const VtkFields& fields = {});

// The ParaView series file PREFIX.pvd beside the frames PREFIX_NNNNNN.vtk: every frame with its
// time in ns (ParaView's time axis then is the simulation time, not the frame index), rewritten
// atomically after each frame. A resumed run starts from the frames already written, whose
// times are read back from their header lines.
class VtkSeries {
 public:
  VtkSeries(std::string prefix, long existingFrames);
  // Adds the frame just written and rewrites PREFIX.pvd.
  void add(const std::string& framePath, double time);
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::vector<std::pair<double, std::string>> frames_;  // time (ns), file name
};
// The time of a frame from its header line ("... time T ns ..."); InputError naming the file
// when it has none.
double vtkFrameTime(const std::string& path);

}  // namespace mesochain::mdem
