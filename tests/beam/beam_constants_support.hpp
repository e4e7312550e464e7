#pragma once
// Beam constants of a collapsed-tube-like rectangle, shared by the brick and cantilever tests:
// h = 2.0, w = 40 Bohr, T0 = 4.65 Bohr, Y = 0.034, G = 0.013 Hartree / Bohr^3, i.e. the
// per-cell constants C = Y h w T0, K = G J / T0 (J = (h w^3 + w h^3)/12), D_s = Y w h^3/12 T0
// and D_h = Y h w^3/12 T0 of that section.
#include "beam/beam_model.hpp"

namespace mesochain::beam::testing {

// The section: T0, thickness h and width w (Bohr), Y and G (Hartree / Bohr^3).
inline constexpr double kT0 = 4.65, kH = 2.0, kW = 40.0, kY = 0.034, kG = 0.013;

inline BeamConstants collapsedTubeConstants() {
  const double y = kY, g = kG, h = kH, w = kW, t0 = kT0;
  BeamConstants c;
  c.cellLength = t0;
  c.stretch = y * h * w * t0;
  c.twist = g * (h * w * w * w + w * h * h * h) / 12.0 / t0;
  c.bendSoft = y * w * h * h * h / 12.0 * t0;
  c.bendHard = y * h * w * w * w / 12.0 * t0;
  return c;
}

}  // namespace mesochain::beam::testing
