#include "mdem/contacts/deposition_file.hpp"

#include <cmath>

#include <fmt/format.h>

#include "mdem/contacts/contact_file.hpp"
#include "mdem/contacts/deposition.hpp"
#include "mdem/units.hpp"

namespace mesochain::mdem {

namespace {
constexpr double kDeg = units::kPi / 180.0;

std::pair<double, double> readPair(const TomlTable& t, const char* key) {
  const std::vector<double> v = t.numbers(key);
  if (v.size() != 2 || !(v[0] > 0.0) || !(v[1] > 0.0))
    t.fail(key, fmt::format("{} numbers{}", v.size(), v.size() == 2 ? " not both positive" : ""),
           "[x, y]: two positive in-plane extents in nm (a deposited film's thickness is its outcome; thickness_nm sets a target or "
           "a limit)");
  return {v[0], v[1]};
}
}  // namespace

void readDepositionTable(const TomlTable& root, const TomlTable& t, Scene& s) {
  t.allowOnly({"method", "element_type", "bond_type", "size_nm", "tube_length_nm", "tubes", "areal_density_ug_per_cm2",
               "density_g_per_cm3", "thickness_nm", "boundary", "sheet_size_nm", "shape", "waviness_deg", "aligned_fraction",
               "alignment_axis", "alignment_angle_deg", "alignment_spread_deg", "drape_slope_deg", "drape_bend_deg",
               "minimum_gap_nm", "rest_shape", "seed"});
  DepositionSpec d;
  d.elementType = findNamed(s.elementTypes, t, "element_type");
  d.bondType = findNamed(s.bondTypes, t, "bond_type");
  const ElementType& e = s.elementTypes[d.elementType];
  std::tie(d.sizeX, d.sizeY) = readPair(t, "size_nm");
  d.elementsPerTube = elementsPerTube(t, e);
  const double tubeLength = d.elementsPerTube * e.length;

  const std::string boundary = t.stringOr("boundary", "periodic");
  if (boundary != "periodic" && boundary != "cut") t.fail("boundary", "\"" + boundary + "\"", "\"periodic\" or \"cut\"");
  d.boundary = boundary == "cut" ? FilmBoundary::Cut : FilmBoundary::Periodic;
  if (d.boundary == FilmBoundary::Cut) {
    // Default sheet: the film plus one tube length plus one clearance along each axis.
    const double margin = tubeLength + 2.0 * e.contactRadius() + t.nonNegativeOr("minimum_gap_nm", d.minimumGap);
    if (t.has("sheet_size_nm")) std::tie(d.sheetX, d.sheetY) = readPair(t, "sheet_size_nm");
    else d.sheetX = d.sizeX + margin, d.sheetY = d.sizeY + margin;
  } else if (t.has("sheet_size_nm")) {
    t.fail("sheet_size_nm", "a sheet for a periodic film", "boundary = \"cut\"");
  }
  const double px = d.boundary == FilmBoundary::Cut ? d.sheetX : d.sizeX, py = d.boundary == FilmBoundary::Cut ? d.sheetY : d.sizeY;

  // Stop: a count (tubes, areal density, density with thickness_nm) or a thickness.
  const int counts = t.has("tubes") + t.has("areal_density_ug_per_cm2") + t.has("density_g_per_cm3");
  if (counts > 1) t.fail("tubes", "more than one of tubes, areal_density_ug_per_cm2, density_g_per_cm3", "at most one");
  if (t.has("thickness_nm")) d.thickness = t.positive("thickness_nm");
  if (counts == 0 && !t.has("thickness_nm"))
    t.fail("tubes", "no stop", "one of tubes, areal_density_ug_per_cm2, density_g_per_cm3 (with thickness_nm), or thickness_nm alone");
  const double tubeMass = d.elementsPerTube * e.mass, area = px * py;
  auto countFrom = [&](double mass, const char* key) {
    const double k = std::round(mass / tubeMass);
    if (!(k >= 1.0) || k > 1e7)
      t.fail(key, fmt::format("{:.6g} tubes' worth over {:.6g} nm^2", mass / tubeMass, area), "a density giving 1 to 1e7 tubes on the film");
    d.countKey = t.where(key);
    return static_cast<int>(k);
  };
  if (t.has("tubes")) {
    const long k = t.integer("tubes");
    if (k < 1 || k > 10000000) t.fail("tubes", std::to_string(k), "a number of tubes in [1, 1e7]");
    d.tubes = static_cast<int>(k);
    d.countKey = t.where("tubes");
  } else if (t.has("areal_density_ug_per_cm2")) {
    d.tubes = countFrom(t.positive("areal_density_ug_per_cm2") * 1e-2 * area, "areal_density_ug_per_cm2");  // 1 ug/cm^2 = 0.01 ag/nm^2
  } else if (t.has("density_g_per_cm3")) {
    if (!t.has("thickness_nm")) t.fail("density_g_per_cm3", "a density without thickness_nm", "thickness_nm, the thickness it refers to");
    d.tubes = countFrom(t.positive("density_g_per_cm3") * 1e-3 * area * d.thickness, "density_g_per_cm3");  // 1 g/cm^3 = 1e-3 ag/nm^3
  }
  if (d.tubes == 0) d.countKey = t.where("thickness_nm");

  const std::string shape = t.stringOr("shape", "straight");
  if (shape != "straight" && shape != "wavy") t.fail("shape", "\"" + shape + "\"", "\"straight\" or \"wavy\"");
  if (shape == "straight" && t.has("waviness_deg")) t.fail("waviness_deg", "a waviness for straight tubes", "shape = \"wavy\"");
  d.waviness = shape == "wavy" ? t.numberOr("waviness_deg", 15.0) * kDeg : 0.0;
  if (d.waviness < 0.0 || d.waviness > units::kPi / 2)
    t.fail("waviness_deg", fmt::format("{}", t.number("waviness_deg")), "an angle per element in [0, 90] degrees");

  d.alignedFraction = t.nonNegativeOr("aligned_fraction", 0.0);
  if (d.alignedFraction > 1.0) t.fail("aligned_fraction", fmt::format("{}", d.alignedFraction), "a fraction in [0, 1]");
  if (t.has("alignment_axis") && t.has("alignment_angle_deg")) t.fail("alignment_axis", "both alignment_axis and alignment_angle_deg", "one of them");
  const std::string axis = t.stringOr("alignment_axis", "x");
  if (axis != "x" && axis != "y") t.fail("alignment_axis", "\"" + axis + "\"", "\"x\" or \"y\"");
  d.alignmentAngle = t.has("alignment_angle_deg") ? t.number("alignment_angle_deg") * kDeg : (axis == "y" ? 0.5 * units::kPi : 0.0);
  d.alignmentSpread = t.nonNegativeOr("alignment_spread_deg", 0.0) * kDeg;
  if (d.alignmentSpread > units::kPi) t.fail("alignment_spread_deg", fmt::format("{}", t.number("alignment_spread_deg")), "a spread in [0, 180] degrees");
  if (d.alignedFraction == 0.0)
    for (const char* k : {"alignment_axis", "alignment_angle_deg", "alignment_spread_deg"})
      if (t.has(k)) t.fail(k, "an alignment without aligned tubes", "aligned_fraction > 0");

  d.maxSlope = t.numberOr("drape_slope_deg", d.maxSlope / kDeg) * kDeg;
  if (!(d.maxSlope > 0.0 && d.maxSlope < 0.5 * units::kPi)) t.fail("drape_slope_deg", fmt::format("{}", d.maxSlope / kDeg), "an angle in (0, 90) degrees");
  d.bendPerElement = t.numberOr("drape_bend_deg", d.bendPerElement / kDeg) * kDeg;
  if (!(d.bendPerElement > 0.0 && d.bendPerElement <= 0.5 * units::kPi))
    t.fail("drape_bend_deg", fmt::format("{}", d.bendPerElement / kDeg), "an angle in (0, 90] degrees");
  d.minimumGap = t.nonNegativeOr("minimum_gap_nm", d.minimumGap);
  const std::string rest = t.stringOr("rest_shape", "straight");
  if (rest != "straight" && rest != "as_laid") t.fail("rest_shape", "\"" + rest + "\"", "\"straight\" or \"as_laid\"");
  d.restShape = rest == "straight" ? RestShape::Straight : RestShape::AsLaid;
  const long seed = t.integerOr("seed", 1);
  if (seed < 0) t.fail("seed", std::to_string(seed), "a seed >= 0");
  d.seed = static_cast<std::uint64_t>(seed);

  // Periodicity: a periodic film sets [periodic] x, y to its size (or checks a given one); a cut
  // specimen is not periodic in the plane.
  if (root.has("periodic")) {
    const TomlTable p = root.requireTable("periodic");
    const Vec3 lp = p.vec3("length_nm");
    const bool periodicFilm = d.boundary == FilmBoundary::Periodic;
    if ((periodicFilm && (std::abs(lp.x() - d.sizeX) > 1e-9 * d.sizeX || std::abs(lp.y() - d.sizeY) > 1e-9 * d.sizeY)) ||
        (!periodicFilm && (lp.x() != 0.0 || lp.y() != 0.0)) || lp.z() != 0.0)
      p.fail("length_nm", fmt::format("[{}, {}, {}]", lp.x(), lp.y(), lp.z()),
             periodicFilm ? fmt::format("the periodic deposited film: [{}, {}, 0] (or no [periodic] table: it is set)", d.sizeX, d.sizeY)
                          : std::string("[0, 0, 0] or no [periodic] table: a cut specimen is not periodic in the plane"));
  }
  if (d.boundary == FilmBoundary::Periodic) {
    s.periodic.periodic = {true, true, false};
    s.periodic.length = Vec3(d.sizeX, d.sizeY, 0.0);
  }
  depositFilm(s, d);
}

}  // namespace mesochain::mdem
