#pragma once
// Beam idealisation of four per-cell stiffness constants (atomic units: Hartree, Bohr, rad).
//
// Energies per cell of length T0 (Euler-Bernoulli beam, Saint-Venant torsion with the polar
// moment as in the parallel bond of Potyondy & Cundall 2004 and mdem/parallel_bond.hpp):
//   stretch  U = 1/2 C eps^2        C   = Y A T0
//   twist    U = 1/2 K gamma^2      K   = G J / T0     (gamma: twist angle per cell)
//   bend     U = 1/2 D (1/R)^2      D_s = Y I_y T0, D_h = Y I_x T0
// Rectangle h x w (h = thickness along body x, w = width along body y, as an mDEM brick):
//   A = h w, I_y = w h^3 / 12 (soft: bending about the width axis), I_x = h w^3 / 12 (hard),
//   J = I_x + I_y.
// Solving: D_s / C = h^2 / 12 and D_h / C = w^2 / 12 fix h and w, then Y = C / (h w T0) and
// G = K T0 / J. Four equations, four unknowns: a homogeneous rectangle always meets all four
// (closure "four_constants"), but its h need not be the thickness the relaxed atoms show.
// With h given (closure "measured_thickness"), w and Y come from C and D_h, G from K, and the
// soft bending D_s = Y w h^3 T0 / 12 is what it is: its residual is reported.
// Round sections (C, K and one D): solid circle r^2 = 4 D / C ("circle"); annulus of given
// wall t about a mean radius R, with D / C = (R_o^2 + R_i^2) / 4 = R^2 / 2 + t^2 / 8
// ("annulus"); J = 2 I in both.
#include <string>

namespace mesochain::beam {

// The per-cell constants a scan measures.
struct BeamConstants {
  double cellLength = 0.0;  // T0, Bohr
  double stretch = 0.0;     // C, Hartree
  double twist = 0.0;       // K, Hartree / rad^2
  double bendSoft = 0.0;    // D_s, Hartree Bohr^2
  double bendHard = 0.0;    // D_h, Hartree Bohr^2
};

struct Section {
  double area = 0.0;  // A, Bohr^2
  double ix = 0.0;    // I_x (hard bending), Bohr^4
  double iy = 0.0;    // I_y (soft bending), Bohr^4
  double polar = 0.0; // J = I_x + I_y, Bohr^4
};

// Relative residual (model / target - 1) of each equation; 0 when met.
struct Residuals {
  double stretch = 0.0, twist = 0.0, bendSoft = 0.0, bendHard = 0.0;
};

struct Beam {
  std::string shape;        // "rectangle", "circle", "annulus"
  std::string closure;      // "four_constants", "measured_thickness", "circle", "annulus"
  double young = 0.0;       // Y, Hartree / Bohr^3
  double shear = 0.0;       // G, Hartree / Bohr^3
  double thickness = 0.0;   // rectangle h, Bohr
  double width = 0.0;       // rectangle w, Bohr
  double radius = 0.0;      // circle: radius; annulus: mean radius, Bohr
  double wall = 0.0;        // annulus wall thickness, Bohr
  double cellLength = 0.0;  // T0, Bohr
  Section section;
  Residuals residuals;
};

Section rectangleSection(double thickness, double width);
Section circleSection(double radius);
Section annulusSection(double meanRadius, double wall);

// The constants a beam gives back (C, K, D_s, D_h).
BeamConstants predictConstants(const Beam& beam);
Residuals residualsOf(const Beam& beam, const BeamConstants& target);

// Closures; every constant used must be > 0 and finite, else InputError(source, ...).
Beam rectangleFourConstants(const BeamConstants& c, const std::string& source);
Beam rectangleMeasuredThickness(const BeamConstants& c, double thickness, const std::string& source);
// Round sections take C, K and D = D_s (D_h is compared in the residuals).
Beam solidCircle(const BeamConstants& c, const std::string& source);
Beam annulus(const BeamConstants& c, double wall, const std::string& source);

}  // namespace mesochain::beam
