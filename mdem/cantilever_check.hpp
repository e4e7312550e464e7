#pragma once
// The static cantilever of a scene against Euler-Bernoulli beam theory (issue 15, item 1: the
// chain's check that the bricks reproduce the fitted beam). The scene is a straight filament
// clamped at one element (all six DOFs fixed) and loaded by a moment at its tip (the scene of
// beam/mdem_export.hpp: `mesochain beam` and `mesochain chain` write it). It is relaxed to its
// static state by its own numerical damping (until the residual moment is 1e-8 of the load),
// and the tip's displacement and rotation are compared with the closed forms of a beam of
// length l (clamped centre to tip centre) under a tip moment M = M_b + T d (d the axis):
//   bending rotation  phi   = M_b l / (E I),
//   tip deflection    delta = M_b l^2 / (2 E I)   (uniform moment: no shear force, so no
//                                                  Timoshenko shear term),
//   twist             theta = T l / (G J)
// (e.g. Timoshenko & Gere, Mechanics of Materials, cantilever with an end couple). E I and G J
// come from the caller (the fitted constants), not from the bricks, so a brick of the wrong
// stiffness fails. Units of mdem (nm, pN, ag, ns; mdem/units.hpp).
#include <limits>
#include <string>

#include "mdem/scene.hpp"

namespace mesochain::mdem {

struct CantileverTheory {
  double bendingStiffness = 0.0;    // E I about the bending axis of the load, pN nm^2
  double massPerLength = 0.0;       // ag/nm (0: no frequency)
  double torsionalStiffness = 0.0;  // G J, pN nm^2 (0: the twist is not compared)
  double tolerance = 0.01;          // largest relative difference that passes
};

struct CantileverQuantity {
  std::string name;  // "tip deflection", "tip bending rotation", "tip twist"
  std::string unit;  // "nm" or "rad"
  double measured = 0.0, theory = 0.0;
  double relativeDifference() const { return measured / theory - 1.0; }
};

struct CantileverCheck {
  double length = 0.0;                      // l, nm
  double bendingMoment = 0.0, twistingMoment = 0.0;  // |M_b|, T, pN nm
  long steps = 0;                           // to the static state
  double residualMoment = 0.0;              // pN nm, at the end
  bool relaxed = false;                     // residual below 1e-8 of the load
  std::vector<CantileverQuantity> quantities;
  // The first bending frequency in the plane of the deflection (GHz): of the bricks (normal modes
  // about the rest state, mdem/normal_modes.hpp) and of Euler-Bernoulli theory for what the
  // bricks discretise. The N free bricks carry their masses at their centres: the trapezoidal
  // rule of a continuous beam of mass mu l, plus half a brick's mass beyond it at the tip (the
  // clamped brick's half does not move). So the theory is the cantilever with a tip mass
  // M = m/2: 1 + cos(bl) cosh(bl) + (M / mu l) bl (cos(bl) sinh(bl) - sin(bl) cosh(bl)) = 0,
  // f1 = (bl)^2 / (2 pi) sqrt(E I / (mu l^4)) (Blevins, Formulas for Natural Frequency and Mode
  // Shape, cantilever with a tip mass; bl = 1.8751 without it). Reported, not part of `passed`:
  // the bricks' rotary inertia and the lumping inside differ from it at O((L/l)^2).
  // NaN without massPerLength.
  double frequency = std::numeric_limits<double>::quiet_NaN();
  double frequencyTheory = std::numeric_limits<double>::quiet_NaN();
  double tolerance = 0.0;
  bool passed = false;                      // relaxed and every |relative difference| <= tolerance
};

// Throws InputError (naming scene.source) when the scene is not a clamped filament with one
// tip moment (no fixed element, no load, a force load, a zero moment).
CantileverCheck checkCantilever(const Scene& scene, const CantileverTheory& theory,
                                long maxSteps = 2000000);

}  // namespace mesochain::mdem
