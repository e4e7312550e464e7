#pragma once
// Bending beyond the quadratic regime: the stiffness of a bend curve against curvature
// (docs/beam.md, "Bending beyond the quadratic regime").
//
// With ΔU(κ) = U(κ) − U_ref the energy per cell above the straight reference (anchored: U_ref is
// the reference's energy, not a fitted offset):
//   secant stiffness   D_sec(κ) = 2 ΔU(κ) / κ²  (the constant of the quadratic law through the
//                                                 reference and the point),
//   bending moment     M(κ) = dU/dκ,  tangent stiffness D_tan(κ) = d²U/dκ² (against a small
//                                                 change of curvature at κ).
// M and D_tan are the derivatives of the interpolant ln ΔU, quadratic in ln κ, through the point
// and its two neighbours (the ends take the first or last three): exact for a power law
// ΔU = A κ^p (U grows as κ^1.5 where a collapsed tube's bulbs flatten), second order in the
// spacing of ln κ otherwise (first order at the two end rings, whose stencil is one-sided).
//
// Quadratic regime: the rings from the gentlest on whose secant stays within the tolerance of
// the gentlest ring's, |D_sec(κ) − D_sec(κ_1)| <= tol D_sec(κ_1) + 3 σ (σ from an optional energy
// noise per point: σ_sec = 2 σ_E / κ² each, combined). Verified when it holds two rings or more;
// otherwise the gentlest rings are already outside it (or only one ring is known) and the
// report warns. Its constant D_0 is the anchored least-squares ½ D κ² over its rings.
//
// Also reported: the anchored quartic law ΔU = ½ D κ² − c κ⁴ over all rings (D, c and their
// standard errors), the free-offset fit U0 + ½ D κ² over all rings (the offset U0 − U_ref in its
// standard errors: an offset that departs from the reference is a curve that is not quadratic),
// and optionally a constant over a curvature window (anchored ½ D κ² over the rings in it, with
// the secant range and a warning when the window leaves the quadratic regime).
#include <limits>

#include <Eigen/Dense>

#include <optional>
#include <string>
#include <vector>

namespace mesochain::beam {

inline constexpr double kNotMeasured = std::numeric_limits<double>::quiet_NaN();

struct BendSample {
  double curvature = 0.0;  // 1/Bohr, > 0
  double energy = 0.0;     // Hartree per cell (absolute, like the scan table)
  // Cross-section of the relaxed ring, when known (measureRingSection; Bohr, Bohr²).
  double radialExtent = kNotMeasured;
  double meanSquareRadialOffset = kNotMeasured;
  double axialExtent = kNotMeasured;
};

// The cross-section of a ring about z from its atoms (Bohr): with ρ the distance of an atom from
// the ring axis and u = ρ − mean ρ, the radial extent max u − min u, ⟨u²⟩, and the extent along
// z. For a soft bend the radial direction is the thickness (across the flat faces of a collapsed
// tube; a membrane bent in the ring stores ½ C ⟨u²⟩ κ² per cell), for a hard bend the width.
struct RingSection {
  double radialExtent = 0.0, meanSquareRadialOffset = 0.0, axialExtent = 0.0;
};
RingSection measureRingSection(const Eigen::Matrix3Xd& positions);

struct BendCurveOptions {
  double tolerance = 0.02;   // relative tolerance of the quadratic regime
  double energyNoise = 0.0;  // standard deviation of one point's energy, Hartree (0: exact)
  // Curvature window [lo, hi] (1/Bohr) for a constant beside the linear-regime one.
  std::optional<std::pair<double, double>> window;
  std::string source = "<bend curve>";
  std::string quantity = "D";
};

struct BendCurvePoint {
  BendSample sample;
  double energyAbove = 0.0;  // ΔU, Hartree
  double secant = 0.0;       // Hartree Bohr²
  double moment = 0.0;       // Hartree Bohr
  double tangent = 0.0;      // Hartree Bohr²
  bool quadratic = false;    // inside the quadratic regime
};

struct LeastSquaresConstant {
  double value = 0.0, error = 0.0;  // standard error (0 with a single point or an exact fit)
  int points = 0;
};

struct WindowConstant {
  double lo = 0.0, hi = 0.0;  // the window asked for (1/Bohr)
  LeastSquaresConstant stiffness;
  double secantMin = 0.0, secantMax = 0.0;
  bool quadratic = false;     // every ring of the window in the quadratic regime
};

struct BendCurve {
  double referenceEnergy = 0.0;
  std::vector<BendCurvePoint> points;  // rings, gentlest first
  int quadraticPoints = 0;             // the gentlest rings in the quadratic regime
  bool quadraticVerified = false;      // at least two of them
  double quadraticMaxCurvature = 0.0;  // κ of the tightest ring in the regime (0 if none)
  LeastSquaresConstant linear;         // D_0 over the quadratic regime (its gentlest ring if none)
  // Anchored quartic law over all rings (needs two rings).
  bool hasQuartic = false;
  LeastSquaresConstant quarticStiffness;  // D
  double quarticCoefficient = 0.0, quarticError = 0.0;  // c of −c κ⁴, Hartree Bohr⁴
  // Free-offset fit over all rings (needs three rings).
  bool hasFreeOffset = false;
  LeastSquaresConstant freeStiffness;
  double freeOffset = 0.0, freeOffsetError = 0.0;  // U0 − U_ref, Hartree
  std::optional<WindowConstant> window;
  std::vector<std::string> warnings;
};

// Throws InputError(options.source, ...) for no ring, non-positive or repeated curvatures,
// non-finite values or a window with lo > hi.
BendCurve analyseBendCurve(std::vector<BendSample> rings, double referenceEnergy, const BendCurveOptions& options);

}  // namespace mesochain::beam
