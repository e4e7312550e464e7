#pragma once
// `mesochain-bench network --scene FILM.toml --coarsen-to FILM4.toml [--coarsen-relaxed]`: the same film with elements
// twice as long (docs/benchmarks.md, "The element length"). Two deposited films of different
// element lengths are different random films (the generator draws per element), and a 150-nm
// specimen's stress-strain curve depends on its film more than on anything else (one tube
// bridging the grips), so the element length is compared on one film: each pair of consecutive
// bonded elements (2k, 2k + 1) of a filament becomes one element of FILM4's first element type,
// centred at their mean, its axis along the chord between their centres; consecutive new elements
// are bonded straight at rest (as rest_shape = "straight" of the deposition). The last element of
// a filament with an odd count is dropped (the count is printed).
#include <string>

#include "mdem/scene.hpp"

namespace mesochain::app {

// modelFile: a scene file (e.g. the 4-nm film) whose first element and bond types are used.
// Throws InputError (naming modelFile) when it has no element or bond type, when its
// element is not twice the scene's (one element type in the scene), or when the scene's bonds
// are not chains in index order.
mdem::Scene coarsenedFilm(const mdem::Scene& fine, const std::string& modelFile);

}  // namespace mesochain::app
