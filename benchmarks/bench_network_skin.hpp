#pragma once
// `mesochain-bench network --skins 0.1,0.3,0.6`: what the neighbour list's Verlet skin
// ([contacts] skin_nm, docs/mdem-contacts.md "Neighbour search") costs. The skin changes no
// result (a listed pair beyond the kernels' reach contributes exact zeros), only the time: a
// small skin rebuilds the list often, a large one tests more pairs every step. Per skin: listed
// pairs per element, list builds per 1000 steps, element-steps per second, the neighbour
// search's share of the step, and whether a run of `checkSteps` from the same state ends in the
// same bits as the first skin's (docs/benchmarks.md, "The Verlet skin").
#include <vector>

#include "mdem/scene.hpp"

namespace mesochain::app {

// Returns 0; 1 when a skin's trajectory differs from the first skin's (a bug: the skin must not
// change results).
int printSkinCurve(const mdem::Scene& scene, const std::vector<double>& skins, double seconds, int threads,
                   long checkSteps);

}  // namespace mesochain::app
