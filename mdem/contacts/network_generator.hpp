#pragma once
// Random networks of tubes: a film of given size filled with N tubes of `elementsPerTube`
// elements (straight or wavy), without overlaps, reproducible from a seed (std::mt19937_64 and
// explicit transforms, so the random numbers are the same on every platform, and the directions
// through portable_math.hpp's sin and cos, not libm's).
//
// Each tube: a random start inside the film, a random in-plane direction (x-y plane) and, for a
// wavy tube, each next element turned by an angle uniform in [-waviness, waviness] in the plane.
// Element centres stay inside the film (z in [0, thickness]); a tube is rejected and redrawn
// when any of its elements comes closer than minimumGap (wall to wall) to an element of another
// tube. Consecutive elements are bonded (bond type `bondType`).
#include <cstdint>

#include "mdem/scene.hpp"

namespace mesochain::mdem {

struct NetworkSpec {
  int elementType = 0;
  int bondType = 0;
  int tubes = 0;
  int elementsPerTube = 0;
  Vec3 size = Vec3::Zero();     // film extent x, y, z (nm); z = thickness (>= 0)
  double waviness = 0.0;        // rad per element (0 = straight)
  double minimumGap = 0.3;      // nm, wall to wall between elements of different tubes
  std::uint64_t seed = 1;
  int attemptsPerTube = 2000;
};

// Appends the network's elements and bonds to `scene` (whose types must exist). Throws
// InputError naming `scene.source` when the requested density cannot be packed.
void generateNetwork(Scene& scene, const NetworkSpec& spec);

// Throws InputError when two elements of different filaments overlap (wall gap < minimumGap).
void checkNoOverlaps(const Scene& scene, double minimumGap);

}  // namespace mesochain::mdem
