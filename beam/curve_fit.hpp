#pragma once
// Stiffness of an energy curve in its linear (quadratic-energy) regime, found automatically.
//
// Model inside a window |x| <= X around the reference x = 0:
//   U(x) = U0 + b x + 1/2 k x^2            (b only when FitOptions::linearTerm)
// U0 is fitted, or (FitOptions::anchorEnergy, bends) anchored at the energy of the undeformed
// reference: then U(0) is not a free parameter, the points at x = 0 (the reference itself) are
// left out, and an offset cannot absorb a drift of the curve (docs/beam.md).
// k is the stiffness: C (stretch, x = strain), K (twist, x = rad per cell) or D (bend,
// x = 1/R in 1/Bohr), U in Hartree per cell.
//
// Window search (docs/beam.md): points are sorted by |x|; nested windows take all points up to
// the next distinct |x| (so a symmetric pair enters together). Starting from the smallest window
// with one more point than parameters, a window is accepted when
//   (a) k > 0 (convex), and
//   (b) its stiffness agrees with every smaller accepted window: |k_m - k_j| <= tol k_j, or the
//       difference is within t(zScore, dof) combined standard errors (noise, not curvature), and
//   (c) where the window has a point to spare for it, a fit with the next even term
//       (+ c x^4, and + d x^3 with the linear term) does not find that term both beyond the
//       tolerance, |c| X^2 / (k/2) > tol (or |d| X / (k/2) > tol), and significant,
//       |c| / sigma_c > t(zScore, dof).
// t(z, dof) is Student's critical value at the level of the normal z-score (small windows know
// their noise poorly). The window grows until the first rejection. The curve is refused
// (InputError naming the source) when it has too few points, when the smallest window is not
// convex or fails (c), or when the second window already disagrees with the smallest (no
// quadratic regime).
//
// Uncertainty: sqrt(stat^2 + trunc^2) with stat the least-squares standard error of k
// (residual variance times (A^T A)^-1) and trunc the truncation bias estimated from the change
// of k when the next term is added, trunc^2 = max(0, (k - k_ext)^2 - (sigma_ext^2 - stat^2))
// (the noise part of that change removed). The window-to-window spread |k - k_previous| is
// reported beside it.
#include <optional>
#include <string>
#include <vector>

namespace mesochain::beam {

struct CurvePoint {
  double x = 0.0;       // deformation (strain, rad per cell, or 1/Bohr)
  double energy = 0.0;  // Hartree per cell
};

struct FitOptions {
  bool linearTerm = false;         // fit b x as well (reference not exactly at the minimum)
  // U(0) fixed at this energy (Hartree per cell) instead of fitted; points at x = 0 are dropped.
  std::optional<double> anchorEnergy;
  // Anchored fits without the linear term only: standard deviation of one point's energy (Hartree; 0: exact). A window
  // is also refused when the secant 2 (U - U(0)) / x^2 of its edge point leaves that of its
  // innermost point by more than the tolerance and 3 of their combined noise (criterion (d),
  // docs/beam.md): a residual-based noise estimate cannot tell a smooth drift from noise in
  // small windows, the anchor can.
  double energyNoise = 0.0;
  double relativeTolerance = 0.02; // tol above
  // Normal z-score of "within noise"; converted to Student's t for the degrees of freedom of
  // each window (small windows know their noise poorly).
  double zScore = 3.0;
  std::string source = "<curve>";  // file name, for messages
  std::string quantity = "k";      // "C", "K", "D_s", ... for messages
};

// One nested window as tried by the search.
struct WindowFit {
  double halfWidth = 0.0;      // X = largest |x| in the window
  int points = 0;
  double stiffness = 0.0;      // k
  double standardError = 0.0;  // stat
  bool hasExtended = false;    // the x^4 (x^3) fit was possible
  double anharmonicity = 0.0;  // |c| X^2 / (k/2) (max with |d| X / (k/2))
  double anharmonicZ = 0.0;    // significance of the largest higher-order term
  bool anharmonicTooLarge = false;  // a higher term both beyond tol and significant
  double extendedStiffness = 0.0;  // k of the extended fit
  double extendedError = 0.0;
  bool accepted = false;
  std::string rejection;       // why the window was not accepted ("" when accepted)
};

struct QuadraticFit {
  double stiffness = 0.0;          // k, energy per x^2
  double uncertainty = 0.0;        // sqrt(stat^2 + trunc^2)
  double statisticalError = 0.0;
  double truncationError = 0.0;
  double windowSpread = 0.0;       // |k - k of the previous accepted window| (0 if none)
  double slope = 0.0;              // b (0 when not fitted)
  double slopeError = 0.0;
  double energy0 = 0.0;            // U0, Hartree (the anchor when anchored)
  bool anchored = false;           // U0 fixed at FitOptions::anchorEnergy
  int referencePointsDropped = 0;  // points at x = 0 left out because U(0) is anchored
  double windowHalfWidth = 0.0;    // X of the chosen window
  int pointsUsed = 0;
  int pointsTotal = 0;
  bool regimeVerified = false;     // at least two nested windows were compared
  std::vector<WindowFit> windows;  // every window tried, smallest first
  std::string note;                // e.g. why the window stopped growing
};

// Fits the quadratic regime; throws InputError(options.source, ...) when the curve is refused.
QuadraticFit fitQuadraticRegime(std::vector<CurvePoint> points, const FitOptions& options);

}  // namespace mesochain::beam
