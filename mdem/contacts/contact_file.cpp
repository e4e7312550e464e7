#include "mdem/contacts/contact_file.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "mdem/contacts/deposition_file.hpp"
#include "mdem/contacts/network_generator.hpp"
#include "mdem/units.hpp"

namespace mesochain::mdem {

namespace {
bool listed(const Scene& s, const char* e) {
  return std::find(s.effects.begin(), s.effects.end(), e) != s.effects.end();
}
void requireRange(const Scene& s, const char* key, double v, double lo, double hi, const char* unit) {
  if (!(v >= lo && v <= hi))
    throw InputError(s.source, fmt::format("key {}", key), fmt::format("{:.6g} {}", v, unit),
                     fmt::format("a value in [{:.6g}, {:.6g}] {}", lo, hi, unit));
}
}  // namespace

void validateContactSpec(const Scene& s) {
  const ContactSpec& c = s.contacts;
  if (listed(s, "vdw_contact")) {
    const VdwContactSpec& v = c.vdw;
    requireRange(s, "vdw_contact.epsilon_meV", v.lj.epsilon / units::kElectronvolt * 1e3, 1e-3, 100.0, "meV");
    requireRange(s, "vdw_contact.sigma_nm", v.lj.sigma, 0.1, 1.0, "nm");
    requireRange(s, "vdw_contact.surface_density_per_nm2", v.lj.surfaceDensity, 1.0, 100.0, "atoms/nm^2");
    // The well (LJ minimum at 2^(1/6) sigma) must lie below the switch.
    requireRange(s, "vdw_contact.switch_gap_nm", v.switchGap, 1.5 * v.lj.sigma, 5.0, "nm");
    requireRange(s, "vdw_contact.cutoff_gap_nm", v.cutoffGap, v.switchGap + 0.05, 6.0, "nm");
    requireRange(s, "vdw_contact.quadrature_points", v.quadraturePoints, 2, 64, "");
    if (v.quadratureTolerance != 0.0)
      requireRange(s, "vdw_contact.quadrature_tolerance", v.quadratureTolerance, 1e-4, 0.1,
                   "(fraction of the contact energy scale)");
    requireRange(s, "vdw_contact.aligned_window_deg", v.alignedWindowDegrees, 0.0, 10.0, "degrees");
    if (v.crossingQuadraturePoints != 0)
      requireRange(s, "vdw_contact.crossing_quadrature_points", v.crossingQuadraturePoints, 2, 64, "");
    requireRange(s, "vdw_contact.layer_spacing_nm", v.layerSpacing, 0.0, 2.0, "nm");
    requireRange(s, "vdw_contact.edge_width_nm", v.edgeWidth, 0.05, 5.0, "nm");
  }
  if (listed(s, "contact_damping")) {
    const ContactDampingSpec& d = c.damping;
    requireRange(s, "contact_damping.translational_pN_ns_per_nm2", d.translational, 0.0, 1e12, "pN ns/nm^2");
    requireRange(s, "contact_damping.rotational_pN_ns", d.rotational, 0.0, 1e12, "pN ns");
    requireRange(s, "contact_damping.full_gap_nm", d.fullGap, 0.0, 5.0, "nm");
    requireRange(s, "contact_damping.cutoff_gap_nm", d.cutoffGap, d.fullGap + 0.01, 6.0, "nm");
  }
  requireRange(s, "contacts.exclude_within_elements", c.excludeWithin, 1, 1000, "");
  requireRange(s, "contacts.skin_nm", c.skin, 1e-3, 10.0, "nm");
  for (int k = 0; k < 3; ++k)
    if (s.periodic.periodic[k]) requireRange(s, "periodic.length_nm", s.periodic.length[k], 1e-3, 1e9, "nm");
}

int elementsPerTube(const TomlTable& t, const ElementType& e) {
  const double tubeLength = t.positive("tube_length_nm");
  const long n = std::lround(tubeLength / e.length);
  if (n < 1 || n > 100000000 || std::abs(n * e.length - tubeLength) > 1e-6 * tubeLength)
    t.fail("tube_length_nm", fmt::format("{:.6g} nm", tubeLength),
           fmt::format("a whole number of elements of \"{}\" (length {:.6g} nm)", e.name, e.length));
  return static_cast<int>(n);
}

void readNetworkTable(const TomlTable& root, Scene& s) {
  if (!root.has("network")) return;
  const TomlTable t = root.requireTable("network");
  const std::string method = t.stringOr("method", "random");
  if (method != "random" && method != "deposition") t.fail("method", "\"" + method + "\"", "\"random\" or \"deposition\"");
  if (method == "deposition") return readDepositionTable(root, t, s);
  t.allowOnly({"method", "element_type", "bond_type", "size_nm", "tubes", "areal_density_ug_per_cm2", "tube_length_nm",
               "shape", "waviness_deg", "minimum_gap_nm", "seed"});
  NetworkSpec n;
  n.elementType = findNamed(s.elementTypes, t, "element_type");
  n.bondType = findNamed(s.bondTypes, t, "bond_type");
  const ElementType& e = s.elementTypes[n.elementType];
  n.size = t.vec3("size_nm");
  if (n.size.x() <= 0.0 || n.size.y() <= 0.0 || n.size.z() < 0.0)
    t.fail("size_nm", fmt::format("[{}, {}, {}]", n.size.x(), n.size.y(), n.size.z()),
           "positive film extents along x and y and a thickness >= 0 (nm)");
  n.elementsPerTube = elementsPerTube(t, e);
  if (t.has("tubes") == t.has("areal_density_ug_per_cm2"))
    t.fail("tubes", t.has("tubes") ? "both tubes and areal_density_ug_per_cm2" : "neither",
           "exactly one of tubes, areal_density_ug_per_cm2");
  if (t.has("tubes")) {
    const long k = t.integer("tubes");
    if (k < 1 || k > 10000000) t.fail("tubes", std::to_string(k), "a number of tubes in [1, 1e7]");
    n.tubes = static_cast<int>(k);
  } else {
    // 1 ug/cm^2 = 1e-5 kg/m^2 = 1e-2 ag/nm^2.
    const double areal = t.positive("areal_density_ug_per_cm2") * 1e-2;
    n.tubes = static_cast<int>(std::lround(areal * n.size.x() * n.size.y() / (n.elementsPerTube * e.mass)));
    if (n.tubes < 1)
      t.fail("areal_density_ug_per_cm2", fmt::format("{:.6g}", t.number("areal_density_ug_per_cm2")),
             "a density giving at least one tube in the film");
  }
  const std::string shape = t.stringOr("shape", "straight");
  if (shape != "straight" && shape != "wavy") t.fail("shape", "\"" + shape + "\"", "\"straight\" or \"wavy\"");
  if (shape == "straight" && t.has("waviness_deg")) t.fail("waviness_deg", "a waviness for straight tubes", "shape = \"wavy\"");
  n.waviness = shape == "wavy" ? t.numberOr("waviness_deg", 15.0) * units::kPi / 180.0 : 0.0;
  if (n.waviness < 0.0 || n.waviness > units::kPi / 2)
    t.fail("waviness_deg", fmt::format("{}", t.number("waviness_deg")), "an angle per element in [0, 90] degrees");
  n.minimumGap = t.nonNegativeOr("minimum_gap_nm", n.minimumGap);
  const long seed = t.integerOr("seed", 1);
  if (seed < 0) t.fail("seed", std::to_string(seed), "a seed >= 0");
  n.seed = static_cast<std::uint64_t>(seed);
  generateNetwork(s, n);
  s.filmSize = n.size;
}

void readVdwContactTable(const TomlTable& t, Scene& s) {
  t.allowOnly({"form", "epsilon_meV", "sigma_nm", "surface_density_per_nm2", "switch_gap_nm",
               "cutoff_gap_nm", "quadrature_points", "quadrature_tolerance", "aligned_window_deg", "crossing_quadrature_points",
               "layer_spacing_nm", "edge_width_nm"});
  VdwContactSpec& v = s.contacts.vdw;
  const std::string form = t.stringOr("form", "anisotropic");
  if (form != "anisotropic" && form != "isotropic") t.fail("form", "\"" + form + "\"", "\"anisotropic\" or \"isotropic\"");
  v.anisotropic = form == "anisotropic";
  v.lj.epsilon = t.positive("epsilon_meV") * 1e-3 * units::kElectronvolt;
  v.lj.sigma = t.positive("sigma_nm");
  v.lj.surfaceDensity = t.positive("surface_density_per_nm2");
  v.switchGap = t.numberOr("switch_gap_nm", v.switchGap);
  v.cutoffGap = t.numberOr("cutoff_gap_nm", v.cutoffGap);
  v.quadraturePoints = static_cast<int>(t.integerOr("quadrature_points", v.quadraturePoints));
  if (t.has("quadrature_tolerance")) {
    if (t.has("quadrature_points"))
      t.fail("quadrature_tolerance", "both quadrature_points and quadrature_tolerance",
             "one of them (the tolerance chooses the number of points)");
    v.quadratureTolerance = t.number("quadrature_tolerance");
    if (!(v.quadratureTolerance > 0.0))
      t.fail("quadrature_tolerance", fmt::format("{}", v.quadratureTolerance), "a fraction in [1e-4, 0.1]");
  }
  v.alignedWindowDegrees = t.numberOr("aligned_window_deg", v.alignedWindowDegrees);
  v.crossingQuadraturePoints = static_cast<int>(t.integerOr("crossing_quadrature_points", v.crossingQuadraturePoints));
  v.layerSpacing = t.numberOr("layer_spacing_nm", v.layerSpacing);
  v.edgeWidth = t.numberOr("edge_width_nm", v.edgeWidth);
}

void readContactDampingTable(const TomlTable& t, Scene& s) {
  t.allowOnly({"translational_pN_ns_per_nm2", "rotational_pN_ns", "full_gap_nm", "cutoff_gap_nm"});
  ContactDampingSpec& d = s.contacts.damping;
  d.translational = t.nonNegativeOr("translational_pN_ns_per_nm2", -1.0);
  if (d.translational < 0.0) t.fail("translational_pN_ns_per_nm2", "nothing", "a value >= 0");
  d.rotational = t.nonNegativeOr("rotational_pN_ns", 0.0);
  d.fullGap = t.numberOr("full_gap_nm", d.fullGap);
  d.cutoffGap = t.numberOr("cutoff_gap_nm", d.cutoffGap);
}

void readContactTables(const TomlTable& root, Scene& s) {
  if (root.has("contacts")) {
    const TomlTable t = root.requireTable("contacts");
    t.allowOnly({"exclude_within_elements", "skin_nm"});
    s.contacts.excludeWithin = static_cast<int>(t.integerOr("exclude_within_elements", s.contacts.excludeWithin));
    s.contacts.skin = t.numberOr("skin_nm", s.contacts.skin);
  }
  if (root.has("periodic")) {
    const TomlTable t = root.requireTable("periodic");
    t.allowOnly({"length_nm"});
    const Vec3 l = t.vec3("length_nm");
    for (int k = 0; k < 3; ++k) {
      if (l[k] < 0.0) t.fail("length_nm", fmt::format("{} along {}", l[k], "xyz"[k]), "0 (not periodic) or a positive box length");
      s.periodic.periodic[k] = l[k] > 0.0;
      s.periodic.length[k] = l[k];
    }
  }
  validateContactSpec(s);
}

}  // namespace mesochain::mdem
