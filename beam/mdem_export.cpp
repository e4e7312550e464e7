#include "beam/mdem_export.hpp"

#include <sstream>

#include <fmt/format.h>

#include "common/units.hpp"

namespace mesochain::beam {

namespace {

std::string commented(const std::string& text) {
  std::istringstream in(text);
  std::string line, out;
  while (std::getline(in, line)) out += "# " + line + "\n";
  return out;
}

}  // namespace

CantileverLoads cantileverLoads(const Brick& b, const MdemExportOptions& o) {
  const double nm4 = units::si::kBohrInNm * units::si::kBohrInNm * units::si::kBohrInNm * units::si::kBohrInNm;
  const double young = b.young * units::si::kHartreePerBohr3InMPa;   // MPa = pN / nm^2
  const double shear = b.shear * units::si::kHartreePerBohr3InMPa;
  CantileverLoads l;
  l.length = (o.elements - 1) * b.length * units::si::kBohrInNm;
  l.bendingMoment = o.tipRotation * young * b.section.iy * nm4 / l.length;
  l.twistingMoment = o.tipRotation * shear * b.section.polar * nm4 / l.length;
  return l;
}

std::string mdemModelToml(const Brick& b, const MdemExportOptions& o, const std::string& header) {
  std::string s = commented(header);
  s += "# Units are in the key names (docs/mdem-units.md). k_n = Y / L, k_s = G / L per unit area.\n";
  s += "format = 1\n\n[[element_types]]\n";
  s += fmt::format("name = \"{}\"\n", o.elementType);
  if (b.radius > 0.0) {
    s += "shape = \"cylinder\"\n";
    s += fmt::format("radius_nm = {:.17g}\n", b.radius * units::si::kBohrInNm);
  } else {
    s += "shape = \"brick\"\n";
    s += fmt::format("thickness_nm = {:.17g}   # h\n", b.thickness * units::si::kBohrInNm);
    s += fmt::format("width_nm = {:.17g}       # w\n", b.width * units::si::kBohrInNm);
  }
  s += fmt::format("length_nm = {:.17g}      # L = {} cells\n", b.length * units::si::kBohrInNm, b.cellsPerBrick);
  s += fmt::format("mass_ag = {:.17g}\n\n[[bond_types]]\n", b.mass * units::si::kDaltonInAttogram);
  s += fmt::format("name = \"{}\"\n", o.bondType);
  s += fmt::format("young_modulus_MPa = {:.17g}\n", b.young * units::si::kHartreePerBohr3InMPa);
  s += fmt::format("shear_modulus_MPa = {:.17g}\n", b.shear * units::si::kHartreePerBohr3InMPa);
  return s;
}

std::string cantileverSceneToml(const Brick& b, const MdemExportOptions& o) {
  const CantileverLoads l = cantileverLoads(b, o);
  // Work of the moments at the static state (zJ); the run stops when the kinetic energy is a
  // billionth of it.
  const double work = 0.5 * o.tipRotation * (l.bendingMoment + l.twistingMoment);
  std::string s;
  s += fmt::format(
      "# A cantilever of {} bricks (element 0 clamped), written by `mesochain beam`. The tip\n"
      "# moments bend it about y (soft, I_y) and twist it about z, each by {} rad by beam theory\n"
      "# (phi = M l / (E I), l = {:.6g} nm). Run: mesochain dem THIS_FILE\n",
      o.elements, o.tipRotation, l.length);
  s += "format = 1\n";
  s += fmt::format("model = \"{}\"\n", o.modelFile);
  s += "effects = [\"bonds\", \"local_damping\"]\n\n[[filaments]]\n";
  s += fmt::format("element_type = \"{}\"\nbond_type = \"{}\"\ncount = {}\n", o.elementType, o.bondType,
                   o.elements);
  s += "start_nm = [0.0, 0.0, 0.0]\ndirection = [0.0, 0.0, 1.0]\nthickness_axis = [1.0, 0.0, 0.0]\n\n";
  s += "[[fixed]]\nelement = 0\ndofs = [\"all\"]\n\n";
  s += "[[loads]]\nelement = -1\n";
  s += fmt::format("moment_pN_nm = [0.0, {:.17g}, {:.17g}]\n", l.bendingMoment, l.twistingMoment);
  s += "frame = \"fixed\"\n\n[local_damping]\nalpha = 0.7\n\n";
  s += "[run]\ntime_step_fraction = 0.5\nsteps = 400000\n";
  s += fmt::format("stop_kinetic_energy_zJ = {:.6g}\n", 1e-9 * work);
  s += "check_every = 100\nminimum_steps = 2000\n\n";
  s += fmt::format("[output]\ndirectory = \"{}\"\nenergies_csv = \"energies.csv\"\nenergies_every = 100\n",
                   o.outputDirectory);
  s += "xyz = \"trajectory.xyz\"\nframes_every = 1000\nprobes = [-1]\n";
  return s;
}

}  // namespace mesochain::beam
