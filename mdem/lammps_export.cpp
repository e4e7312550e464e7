// `mesochain-bench network --lammps PREFIX` writes the benchmark network as the input of its
// LAMMPS peer (bench/lammps/in.network, README.md there): point particles at the element centres
// (one per element, element mass), harmonic bonds along each tube and harmonic angles at each
// inner element, and a pair table U(r) between elements, the isotropic form of mesochain's
// tube-tube potential (vdw_contact.hpp: two parallel elements side by side at centre distance r).
// LAMMPS "units nano" are nm, ag, ns, ag nm^2/ns^2 = zJ: the mDEM units (docs/mdem-units.md), so
// every number is written as is. `mesochain-bench dem --lammps PREFIX` writes its bonded filaments
// for bench/lammps/in.chain-bpm (writeLammpsBpmChains below).
#include "mdem/lammps_export.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/atomic_file.hpp"
#include "mdem/contacts/vdw_contact.hpp"
#include "mdem/scene.hpp"
#include "mdem/units.hpp"

namespace mesochain::mdem {

namespace {
// Under mpirun the ranks other than 0 write to /dev/null (common/atomic_file.hpp).
std::ofstream openOut(const std::string& path) {
  std::ofstream f(fileOutputEnabled() ? path : "/dev/null");
  if (!f) throw std::runtime_error("cannot write " + path);
  return f;
}

// Types keyed by a rounded rest value (bond length to 1e-4 nm, angle to 0.01 degree), so a wavy
// tube keeps its rest shape with a modest number of LAMMPS types.
struct RestTypes {
  double quantum;
  std::map<long, int> index;
  std::vector<double> rest;
  int of(double value) {
    const long key = std::lround(value / quantum);
    auto [it, added] = index.emplace(key, static_cast<int>(rest.size()) + 1);
    if (added) rest.push_back(key * quantum);
    return it->second;
  }
};

// Molecule ids (from 1) along the element order: a new molecule wherever no bond joins i - 1 and i
// (tubes and filaments are laid out as consecutive elements). `count` receives the number.
std::vector<int> chainMolecules(const Scene& scene, int* count) {
  const int n = scene.bodies.size();
  std::vector<char> joinedToPrevious(n, 0);
  for (const Bond& bond : scene.bonds)
    if (std::abs(bond.a - bond.b) == 1) joinedToPrevious[std::max(bond.a, bond.b)] = 1;
  std::vector<int> molecule(n, 0);
  int molecules = 0;
  for (int i = 0; i < n; ++i) molecule[i] = joinedToPrevious[i] ? molecule[i - 1] : ++molecules;
  if (count) *count = molecules;
  return molecule;
}

// The element centres' bounding box widened by `pad` on every side, as LAMMPS data-file lines.
std::string boxLines(const Bodies& b, double pad) {
  Vec3 lo = b.position[0], hi = b.position[0];
  for (const Vec3& p : b.position) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  lo.array() -= pad, hi.array() += pad;
  std::string out;
  for (int k = 0; k < 3; ++k) out += fmt::format("{:.6f} {:.6f} {}lo {}hi\n", lo[k], hi[k], "xyz"[k], "xyz"[k]);
  return out;
}
}  // namespace

void writeLammpsNetwork(const Scene& scene, double timeStep, const std::string& prefix) {
  const Bodies& b = scene.bodies;
  const int n = b.size();
  const ElementType& type = scene.elementTypes.at(0);
  for (int i = 0; i < n; ++i)
    if (b.type[i] != 0) throw std::runtime_error("LAMMPS export: networks of one element type only");

  // Bonded neighbours along the tubes; molecules = tubes.
  std::vector<std::vector<int>> neighbours(n);
  for (const Bond& bond : scene.bonds) neighbours[bond.a].push_back(bond.b), neighbours[bond.b].push_back(bond.a);
  const std::vector<int> molecule = chainMolecules(scene, nullptr);

  // Stiffness of the parallel bond (parallel_bond.hpp) mapped onto point particles:
  //   stretching 1/2 k_n A (r - r0)^2    -> bond_style harmonic K = k_n A / 2,
  //   bending    1/2 k_n I theta^2       -> angle_style harmonic K = k_n I / 2, theta = pi - angle.
  RestTypes bondTypes{1e-4, {}, {}}, angleTypes{1e-2, {}, {}};
  std::vector<double> bondK, angleK;
  struct Term {
    int type, i, j, k;
  };
  std::vector<Term> bonds, angles;
  for (const Bond& bond : scene.bonds) {
    const int t = bondTypes.of(bond.restLength);
    if (t > static_cast<int>(bondK.size())) bondK.push_back(0.5 * bond.k.kn * bond.section.area);
    bonds.push_back({t, bond.a + 1, bond.b + 1, 0});
  }
  const Bond& first = scene.bonds.at(0);
  const double bendK = 0.5 * first.k.kn * first.section.ix;
  for (int i = 0; i < n; ++i) {
    if (neighbours[i].size() != 2) continue;
    const int a = neighbours[i][0], c = neighbours[i][1];
    const Vec3 u = b.position[a] - b.position[i], v = b.position[c] - b.position[i];
    const double angle = std::atan2(u.cross(v).norm(), u.dot(v)) * 180.0 / units::kPi;
    angles.push_back({angleTypes.of(angle), a + 1, i + 1, c + 1});
  }

  std::ofstream d = openOut(prefix + ".data");
  d << "LAMMPS data file: mesochain-bench network, " << n << " elements (bench/lammps/README.md)\n\n";
  d << fmt::format("{} atoms\n{} bonds\n{} angles\n1 atom types\n{} bond types\n{} angle types\n\n", n, bonds.size(),
                   angles.size(), bondTypes.rest.size(), angleTypes.rest.size());
  d << boxLines(b, 5.0);
  d << fmt::format("\nMasses\n\n1 {:.10g}\n\nAtoms # molecular\n\n", type.mass);
  for (int i = 0; i < n; ++i)
    d << fmt::format("{} {} 1 {:.9f} {:.9f} {:.9f}\n", i + 1, molecule[i], b.position[i].x(), b.position[i].y(),
                     b.position[i].z());
  d << "\nVelocities\n\n";
  for (int i = 0; i < n; ++i)
    d << fmt::format("{} {:.9g} {:.9g} {:.9g}\n", i + 1, b.velocity[i].x(), b.velocity[i].y(), b.velocity[i].z());
  d << "\nBonds\n\n";
  for (std::size_t k = 0; k < bonds.size(); ++k)
    d << fmt::format("{} {} {} {}\n", k + 1, bonds[k].type, bonds[k].i, bonds[k].j);
  d << "\nAngles\n\n";
  for (std::size_t k = 0; k < angles.size(); ++k)
    d << fmt::format("{} {} {} {} {}\n", k + 1, angles[k].type, angles[k].i, angles[k].j, angles[k].k);

  // U(r): two elements parallel and side by side (the isotropic form of the contact).
  TubePairSpec ps;
  ps.lj = scene.contacts.vdw.lj, ps.radiusA = ps.radiusB = type.radius;
  ps.switchGap = scene.contacts.vdw.switchGap, ps.cutoffGap = scene.contacts.vdw.cutoffGap;
  const TubePairPotential potential(ps);
  const IsotropicVdw isotropic(potential, 0.5 * type.length, 0.5 * type.length);
  const double rc = isotropic.cutoff(), r0 = 0.5;
  const int points = 2000;
  std::ofstream t = openOut(prefix + ".table");
  t << "# mesochain tube-tube contact, isotropic form U(r) between two " << type.length << " nm elements of radius "
    << type.radius << " nm; r nm, U zJ, F = -dU/dr pN\n\nVDW\n";
  t << fmt::format("N {} R {:.6f} {:.6f}\n\n", points, r0, rc);
  for (int k = 0; k < points; ++k) {
    const double r = r0 + (rc - r0) * k / (points - 1);
    double du = 0.0;
    const double u = isotropic.energy(r, &du);
    t << fmt::format("{} {:.9f} {:.12g} {:.12g}\n", k + 1, r, u, -du);
  }

  std::ofstream s = openOut(prefix + ".settings");
  s << "# mesochain-bench network: coefficients and time step (written by `mesochain-bench network --lammps`)\n";
  for (std::size_t k = 0; k < bondTypes.rest.size(); ++k)
    s << fmt::format("bond_coeff {} {:.9g} {:.6f}\n", k + 1, bondK[k], bondTypes.rest[k]);
  for (std::size_t k = 0; k < angleTypes.rest.size(); ++k)
    s << fmt::format("angle_coeff {} {:.9g} {:.4f}\n", k + 1, bendK, angleTypes.rest[k]);
  // The table file is looked up from LAMMPS's working directory: name it without the folder.
  const std::string tableName = prefix.substr(prefix.find_last_of('/') + 1) + ".table";
  s << fmt::format("pair_coeff 1 1 {} VDW {:.6f}\n", tableName, rc);
  s << fmt::format("neighbor {} bin\n", scene.contacts.skin);
  s << fmt::format("timestep {:.9g}\n", timeStep);
}

// bpm/rotational (LAMMPS BPM package; Wang 2009, Wang & Mora 2009) is a linear spring for the
// normal and the shear displacement and for the twist and bend angles, per bond:
//   k_r (force/distance), k_s (force/distance), k_t and k_b (force*distance/radian).
// A parallel bond of section A, I_x, I_y, J and stiffness k_n, k_s per unit area (parallel_bond.hpp,
// Potyondy & Cundall 2004) has, for small deformations, k_n A, k_s A, k_s J and k_n I: the BPM bond
// is isotropic in bending, so k_b takes the mean of k_n I_x and k_n I_y. Damping and breaking off
// (gammas 0, `break no`): the peer does the bond's elastic work only, as the bench's elements do
// without local damping (`mesochain-bench dem --bonds-only`).
void writeLammpsBpmChains(const Scene& scene, double timeStep, const std::string& prefix) {
  const Bodies& b = scene.bodies;
  const int n = b.size();
  if (scene.bonds.empty()) throw std::runtime_error("LAMMPS BPM export: the scene has no bonds");
  const Bond& first = scene.bonds.front();
  const BondSection& sec = first.section;
  for (const Bond& bond : scene.bonds)
    if (std::abs(bond.restLength - first.restLength) > 1e-9 * first.restLength || bond.k.kn != first.k.kn ||
        bond.k.ks != first.k.ks || bond.section.area != sec.area || bond.section.ix != sec.ix ||
        bond.section.iy != sec.iy || bond.section.j != sec.j)
      throw std::runtime_error("LAMMPS BPM export: bonds of one rest length, stiffness and section only");
  int chains = 0;
  const std::vector<int> molecule = chainMolecules(scene, &chains);
  const double diameter = first.restLength, radius = 0.5 * diameter;

  std::ofstream d = openOut(prefix + ".data");
  d << "LAMMPS data file: mesochain-bench dem, " << n << " elements in " << chains
    << " filaments as bpm/sphere (bench/lammps/README.md)\n\n";
  d << fmt::format("{} atoms\n{} bonds\n1 atom types\n1 bond types\n\n", n, scene.bonds.size());
  d << boxLines(b, 2.0 * diameter);
  // bpm/sphere data columns: id molecule type diameter density x y z.
  d << "\nAtoms # bpm/sphere\n\n";
  for (int i = 0; i < n; ++i) {
    const double density = b.mass[i] / (4.0 / 3.0 * units::kPi * radius * radius * radius);
    d << fmt::format("{} {} 1 {:.9g} {:.12g} {:.9f} {:.9f} {:.9f}\n", i + 1, molecule[i], diameter, density,
                     b.position[i].x(), b.position[i].y(), b.position[i].z());
  }
  d << "\nVelocities\n\n";
  for (int i = 0; i < n; ++i) {
    const Vec3 w = b.angularVelocityWorld(i);
    d << fmt::format("{} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g}\n", i + 1, b.velocity[i].x(), b.velocity[i].y(),
                     b.velocity[i].z(), w.x(), w.y(), w.z());
  }
  d << "\nBonds\n\n";
  for (std::size_t k = 0; k < scene.bonds.size(); ++k)
    d << fmt::format("{} 1 {} {}\n", k + 1, scene.bonds[k].a + 1, scene.bonds[k].b + 1);

  const double kr = first.k.kn * sec.area, ks = first.k.ks * sec.area, kt = first.k.ks * sec.j;
  const double kb = first.k.kn * 0.5 * (sec.ix + sec.iy);
  std::ofstream s = openOut(prefix + ".settings");
  s << "# mesochain-bench dem: bpm/rotational coefficients and time step (written by `mesochain-bench dem --lammps`)\n";
  s << "# k_r k_s (pN/nm) k_t k_b (pN nm/rad); critical forces and torques unused (break no); gammas 0\n";
  s << fmt::format("bond_coeff 1 {:.9g} {:.9g} {:.9g} {:.9g} 1 1 1 1 0 0 0 0\n", kr, ks, kt, kb);
  s << fmt::format("comm_modify vel yes cutoff {:.6f}\n", 1.5 * diameter);
  s << fmt::format("timestep {:.9g}\n", timeStep);
}

}  // namespace mesochain::mdem
