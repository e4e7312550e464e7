#pragma once
// `mesochain-bench network --kernel-curve`: the anisotropic contact kernel's accuracy against its
// cost over the contact pairs of a network (docs/benchmarks.md, "The anisotropic contact kernel"):
// each rule's errors against the 64-point rule, overall and by crossing angle, the pairs of largest
// error, the aligned path's window, and the rules chosen from a quadrature tolerance.
#include <string>

#include "mdem/scene.hpp"

namespace mesochain::app {

struct KernelCurveOptions {
  int points = 0;              // > 0: only this rule, `repeat` times (for callgrind), and its energy sum
  int repeat = 20;
  std::string path = "table";  // "table" (one lookup of D per point) or "line" (three of H)
  double alignedWindow = -1.0; // > 0: with `points`, the aligned path's window (degrees)
  int crossingPoints = 0;      // > 0: with `points`, the crossing rule's points (table path)
  double seconds = 3.0;        // wall time per timed row (ns per pair)
};

// Over the contact list of `scene` (its first element type). Returns 0.
int printKernelCurve(const mdem::Scene& scene, const KernelCurveOptions& options);

}  // namespace mesochain::app
