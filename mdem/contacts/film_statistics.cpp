#include "mdem/contacts/film_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "common/build_info.hpp"
#include "common/errors.hpp"
#include "mdem/contacts/element_pairs.hpp"
#include "mdem/contacts/neighbour_list.hpp"
#include "mdem/units.hpp"

namespace mesochain::mdem {

namespace {
}  // namespace

std::string formatFilmLine(const FilmStatistics& f);

FilmStatistics filmStatistics(const Scene& scene, const FilmStatisticsOptions& o) {
  const Bodies& b = scene.bodies;
  FilmStatistics f;
  f.elements = b.size();
  f.area = scene.filmSize.x() * scene.filmSize.y();
  f.contactGap = o.contactGap, f.vdwShell = o.vdwShell;
  if (f.elements == 0 || !(f.area > 0.0)) return f;
  f.filaments = static_cast<int>(buildTopology(b.size(), scene.bonds, 0, scene.contacts.closedFilaments).filamentSize.size());
  double rMax = 0.0, volume = 0.0, zMin = b.position[0].z(), zMax = zMin, zSum = 0.0;
  for (int i = 0; i < f.elements; ++i) {
    const ElementType& t = scene.elementTypes[b.type[i]];
    const double r = t.contactRadius();
    rMax = std::max(rMax, r);
    f.mass += t.mass;  // the true mass, also under [run] mass_scale
    volume += units::kPi * (r + o.vdwShell) * (r + o.vdwShell) * t.length;
    const double z = b.position[i].z();
    zMin = std::min(zMin, z), zMax = std::max(zMax, z), zSum += z;
    const Vec3 axis = rotate(b.orientation[i], Vec3::UnitZ());
    const double h = std::hypot(axis.x(), axis.y());
    if (h > 1e-12) {
      const Eigen::Vector2d u(axis.x() / h, axis.y() / h);
      f.orientation += u * u.transpose();
    }
  }
  f.orientation /= f.elements;
  double zVar = 0.0;
  const double zMean = zSum / f.elements;
  for (int i = 0; i < f.elements; ++i) zVar += (b.position[i].z() - zMean) * (b.position[i].z() - zMean);
  zVar /= f.elements;
  f.thickness = zMax - zMin + 2.0 * rMax;
  f.thicknessUniformSlab = std::sqrt(12.0 * zVar) + 2.0 * rMax;
  // 1 ag/nm^2 = 1e-18 g / 1e-14 cm^2 = 1e-4 g/cm^2 = 100 ug/cm^2.
  f.arealDensity = f.mass / f.area * 100.0;
  // 1 ag/nm^3 = 1e-18 g / 1e-21 cm^3 = 1e3 g/cm^3.
  f.density = f.mass / (f.area * f.thickness) * 1e3;
  f.porosity = 1.0 - volume / (f.area * f.thickness);
  const std::vector<ClosePair> contacts = closePairs(scene, o.contactGap, o.excludeWithin);
  f.contactPairs = static_cast<long>(contacts.size());
  f.alignedAngleDeg = o.alignedAngleDeg;
  f.bundles = bundleSizeDistribution(f.elements, alignedPairs(b, contacts, o.alignedAngleDeg * units::kPi / 180.0));
  f.contactsPerElement = 2.0 * f.contactPairs / f.elements;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(f.orientation);
  f.lambda1 = eig.eigenvalues()[1], f.lambda2 = eig.eigenvalues()[0];
  f.orderParameter = f.lambda1 - f.lambda2;
  const Eigen::Vector2d d = eig.eigenvectors().col(1);
  double angle = std::atan2(d.y(), d.x()) * 180.0 / units::kPi;
  if (angle < 0.0) angle += 180.0;
  if (angle >= 180.0) angle -= 180.0;
  f.directorAngleDeg = angle;
  if (o.poreSizes) {
    PoreSizeOptions po = o.pores;
    po.shell = o.vdwShell;
    f.pores = poreSizeDistribution(scene, po), f.hasPores = true;
  }
  return f;
}

std::string formatFilmStatistics(const FilmStatistics& f) {
  std::string pores;
  if (f.hasPores)
    pores = fmt::format("pores (largest empty sphere centred at each void point, grid {:.3g} nm): void fraction {:.4g}, "
                        "diameter mean {:.4g} nm, median {:.4g} nm, largest {:.4g} nm\n",
                        f.pores.spacing[0], f.pores.voidFraction, f.pores.meanDiameter, f.pores.medianDiameter,
                        f.pores.largestDiameter);
  const BundleSizeDistribution& d = f.bundles;
  const std::string bundles = fmt::format(
      "bundles (contacts aligned within {:.3g} deg): {}, holding {:.3g} of the elements; mean {:.4g}, largest {} elements\n",
      f.alignedAngleDeg, d.bundles, d.elements > 0 ? static_cast<double>(d.elementsInBundles) / d.elements : 0.0, d.mean,
      d.largest);
  return formatFilmLine(f) + bundles + pores;
}

std::string formatFilmLine(const FilmStatistics& f) {
  return fmt::format(
      "film: {} elements in {} filaments over {:.6g} nm^2; thickness {:.4g} nm (centre span + 2R; uniform slab {:.4g} nm), "
      "areal density {:.4g} ug/cm^2, density {:.4g} g/cm^3, porosity {:.4g} (vdW radius R + {:.3g} nm); "
      "{:.3g} contacts per element (wall gap < {:.3g} nm); orientation eigenvalues {:.4f}, {:.4f}, order parameter {:.4f}, "
      "director {:.1f} deg from x\n",
      f.elements, f.filaments, f.area, f.thickness, f.thicknessUniformSlab, f.arealDensity, f.density, f.porosity, f.vdwShell,
      f.contactsPerElement, f.contactGap, f.lambda1, f.lambda2, f.orderParameter, f.directorAngleDeg);
}

void writeFilmStatisticsJson(const FilmStatistics& f, const std::string& path) {
  nlohmann::ordered_json j;
  j["elements"] = f.elements;
  j["filaments"] = f.filaments;
  j["area_nm2"] = f.area;
  j["mass_ag"] = f.mass;
  j["thickness_nm"] = f.thickness;
  j["thickness_definition"] = "z_max - z_min of the element centres + 2 R_max (outer extent of the tube walls)";
  j["thickness_uniform_slab_nm"] = f.thicknessUniformSlab;
  j["areal_density_ug_per_cm2"] = f.arealDensity;
  j["density_g_per_cm3"] = f.density;
  j["density_definition"] = "mass / (area * thickness_nm)";
  j["porosity"] = f.porosity;
  j["porosity_definition"] = "1 - sum(pi (R + vdw_shell_nm)^2 L) / (area * thickness_nm)";
  j["vdw_shell_nm"] = f.vdwShell;
  j["contact_gap_nm"] = f.contactGap;
  j["contact_pairs"] = f.contactPairs;
  j["contacts_per_element"] = f.contactsPerElement;
  j["orientation_tensor"] = {{f.orientation(0, 0), f.orientation(0, 1)}, {f.orientation(1, 0), f.orientation(1, 1)}};
  j["orientation_eigenvalues"] = {f.lambda1, f.lambda2};
  j["order_parameter"] = f.orderParameter;
  j["director_angle_deg"] = f.directorAngleDeg;
  {
    nlohmann::ordered_json d;
    d["definition"] =
        "connected groups of elements joined by contacts (wall gap < contact_gap_nm) whose axes cross below aligned_angle_deg; "
        "sizes in elements, classes [from, to) with the bundles in each and the fraction of all elements they hold";
    d["aligned_angle_deg"] = f.alignedAngleDeg;
    d.update(bundleSizesJson(f.bundles));
    j["bundle_size_distribution"] = d;
  }
  if (f.hasPores) {
    const PoreSizeDistribution& p = f.pores;
    nlohmann::ordered_json q;
    q["definition"] =
        "local pore diameter D(p) = 2 min_i(|p - axis segment_i| - R_i - vdw_shell_nm): the largest empty sphere centred at a "
        "void point p (a pointwise lower bound of the Bhattacharya-Gubbins pore size, Langmuir 22, 7726 (2006)), over a "
        "cell-centred grid of the film's area and z_low_nm..z_high_nm, each void point the same volume";
    q["grid_spacing_nm"] = {p.spacing[0], p.spacing[1], p.spacing[2]};
    q["z_low_nm"] = p.zLow, q["z_high_nm"] = p.zHigh;
    q["grid_points"] = p.points, q["void_points"] = p.voidPoints;
    q["void_fraction"] = p.voidFraction;
    q["mean_diameter_nm"] = p.meanDiameter, q["median_diameter_nm"] = p.medianDiameter;
    q["largest_diameter_nm"] = p.largestDiameter;
    q["bin_width_nm"] = p.binWidth;
    q["bin_lower_edge_nm"] = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < p.fraction.size(); ++k) q["bin_lower_edge_nm"].push_back(k * p.binWidth);
    q["void_fraction_in_bin"] = p.fraction;
    q["void_fraction_at_least_lower_edge"] = p.cumulative;
    j["pore_size_distribution"] = q;
  }
  j["program"] = buildInfoJson();
  const std::filesystem::path target(path), tmp = target.string() + ".tmp";
  {
    std::ofstream out(tmp);
    out << j.dump(2) << "\n";
    if (!out) throw InputError(tmp.string(), "film report", "a file that cannot be written", "a writable output folder");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, target, ec);
  if (ec) throw InputError(target.string(), "film report", "rename failed: " + ec.message(), "a writable output folder");
}

}  // namespace mesochain::mdem
