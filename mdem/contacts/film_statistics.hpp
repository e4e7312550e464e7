#pragma once
// The report of a generated film (docs/scene-file.md, "Film report"):
//   thickness t = z_max - z_min + 2 R_max: the span of the element centres plus one tube
//     diameter, the outer extent of the tube walls (the thickness [tensile] uses for the
//     cross-section of a film); also the uniform-slab thickness sqrt(12) sigma_z + 2 R_max (the
//     slab whose centre heights have the same variance: less sensitive to a few high tubes);
//   areal density m / A and density rho = m / (A t), A = x * y of the film;
//   porosity 1 - V / (A t), V = sum over elements of pi (R + shell)^2 L: the volume of the tubes
//     out to their van der Waals radius, shell = half the graphite interlayer spacing (0.17 nm),
//     so that two tubes in contact at that spacing just fill the space between them;
//   contacts per element: 2 x (pairs with wall gap < contactGap, pairs along one tube within
//     `excludeWithin` elements not counted) / elements;
//   the 2-D orientation tensor Q = <u u^T> of the in-plane unit directions u of the element
//     axes, its eigenvalues lambda_1 >= lambda_2 (sum 1), the order parameter S = lambda_1 -
//     lambda_2 (0 isotropic, 1 all parallel) and the director angle from x;
//   the bundle-size distribution (bundle_sizes.hpp): bundles of elements joined by contacts
//     (wall gap < contactGap) whose axes cross below alignedAngleDeg;
//   the pore-size distribution (pore_size.hpp): local pore diameter = the largest empty sphere
//     centred at a point of the void, over a grid within the film's thickness.
#include <string>

#include <Eigen/Dense>

#include "mdem/contacts/bundle_sizes.hpp"
#include "mdem/contacts/pore_size.hpp"
#include "mdem/scene.hpp"

namespace mesochain::mdem {

struct FilmStatisticsOptions {
  double contactGap = 0.5;   // nm
  double vdwShell = 0.17;    // nm, added to the tube radius for the porosity
  int excludeWithin = 3;     // elements along one tube not counted as contacts
  double alignedAngleDeg = 10.0;  // contacts crossing below it join bundles ([tensile] aligned_angle_deg's default)
  bool poreSizes = true;     // compute the pore-size distribution
  PoreSizeOptions pores;     // its shell is vdwShell
};

struct FilmStatistics {
  int elements = 0, filaments = 0;
  double area = 0.0;                 // nm^2
  double mass = 0.0;                 // ag
  double thickness = 0.0;            // nm (extent, above)
  double thicknessUniformSlab = 0.0; // nm
  double arealDensity = 0.0;         // ug/cm^2
  double density = 0.0;              // g/cm^3, over the extent thickness
  double porosity = 0.0;             // over the extent thickness
  double contactGap = 0.0, vdwShell = 0.0;
  long contactPairs = 0;
  double contactsPerElement = 0.0;
  Eigen::Matrix2d orientation = Eigen::Matrix2d::Zero();
  double lambda1 = 0.0, lambda2 = 0.0, orderParameter = 0.0, directorAngleDeg = 0.0;
  double alignedAngleDeg = 0.0;
  BundleSizeDistribution bundles;
  bool hasPores = false;
  PoreSizeDistribution pores;
};

// The film is scene.filmSize (x, y) with the scene's elements; periodic axes from scene.periodic.
FilmStatistics filmStatistics(const Scene& scene, const FilmStatisticsOptions& options = {});

// One paragraph for the terminal.
std::string formatFilmStatistics(const FilmStatistics& f);

// JSON with the quantities, their units and their definitions; written to a temporary file in the
// same folder and renamed over `path` (a kill never leaves a half-written report).
void writeFilmStatisticsJson(const FilmStatistics& f, const std::string& path);

}  // namespace mesochain::mdem
