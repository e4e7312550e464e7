#pragma once
// The time LAPACK alone needs for the eigenpairs one band-structure evaluation uses (see
// bench_dftb_lapack.cpp), printed by `mesochain-bench dftb` beside the total.
#include "dftb/parameters.hpp"
#include "objective/core/cell.hpp"

namespace mesochain::app {

struct LapackReference {
  int orbitals = 0, kpoints = 0, vectorsUsed = 0;  // vectorsUsed: summed over k-points
  // Seconds summed over the k-points, one thread, best of the repeats per call:
  double allPairs = 0;        // zhegvd 'V', all pairs
  double usedPairs = 0;       // zhegvx 'V' for the pairs the density uses
  double best = 0;            // the faster of the two per k-point
  double choleskyFactor = 0;  // zpotrf of S(k)
};

LapackReference lapackReference(const objective::ObjectiveCell& cell,
                                const dftb::ParameterSet& params, int nKappa, double kT,
                                int repeats);

}  // namespace mesochain::app
