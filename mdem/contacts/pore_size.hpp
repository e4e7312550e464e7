#pragma once
// Pore-size distribution of a film (film report, docs/scene-file.md "Film report").
//
// Definition (geometric, in the spirit of Gelb & Gubbins, Langmuir 15, 305 (1999) and
// Bhattacharya & Gubbins, Langmuir 22, 7726 (2006)): the solid is the union of the elements'
// van der Waals cylinders, capsules of radius R + shell about each element's axis segment
// (shell as for the porosity, half the graphite interlayer spacing). At a point p of the void the
// local pore diameter is
//     D(p) = 2 d(p),  d(p) = min_i (|p - axis segment_i| - R_i - shell),
// the diameter of the largest empty sphere centred at p. (Bhattacharya and Gubbins assign to p
// the largest empty sphere that contains p, centred anywhere; D(p) is a pointwise lower bound of
// theirs, equal on the spheres' centres of the medial axis, and both have the same largest
// value, the largest empty sphere of the film.) The distribution is over the void volume of the
// film's thickness: a uniform cell-centred grid over the film's area (periodic axes by minimum
// image; a cut film's edges are open) and z from z_min - R_max to z_max + R_max of the element
// centres (the film report's thickness); each void grid point carries the same volume.
// Reported: void fraction of the grid, the volume fraction of the void in each bin of D
// (bin width binWidth), the cumulative fraction in pores of diameter >= each bin's lower edge,
// the volume-weighted mean and median D and the largest D.
//
// Closed form (test): a square lattice of parallel rods of radius a and spacing L (shell 0) has
// void fraction 1 - pi a^2 / L^2 and P(D >= 2r) = (L^2 - pi (a + r)^2) / (L^2 - pi a^2) for
// a + r <= L / 2.
#include <vector>

#include "mdem/scene.hpp"

namespace mesochain::mdem {

struct PoreSizeOptions {
  double shell = 0.17;          // nm, added to each radius (the porosity's van der Waals shell)
  double gridSpacing = 0.0;     // nm; 0: the finest of at least 0.5 nm within maxPoints
  long maxPoints = 1000000;     // grid points when gridSpacing = 0
  double binWidth = 1.0;        // nm, in pore diameter
  // z range of the grid; zHigh <= zLow: the film's thickness (above).
  double zLow = 0.0, zHigh = 0.0;
};

struct PoreSizeDistribution {
  double spacing[3] = {0.0, 0.0, 0.0};  // nm, of the grid along x, y, z
  long points = 0, voidPoints = 0;
  double zLow = 0.0, zHigh = 0.0;       // nm
  double voidFraction = 0.0;
  double binWidth = 0.0;                // nm
  std::vector<double> fraction;         // void volume fraction with D in [k w, (k + 1) w)
  std::vector<double> cumulative;       // void volume fraction with D >= k w
  double meanDiameter = 0.0, medianDiameter = 0.0, largestDiameter = 0.0;  // nm
};

// Over scene.filmSize (x, y in [0, size)) with the scene's elements; periodic axes from
// scene.periodic. Threads: OpenMP over the grid (the counts do not depend on them).
PoreSizeDistribution poreSizeDistribution(const Scene& scene, const PoreSizeOptions& options = {});

}  // namespace mesochain::mdem
