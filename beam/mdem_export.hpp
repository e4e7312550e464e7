#pragma once
// mDEM files from a brick: a model file (element and bond types, docs/scene-file.md) and a
// ready cantilever scene that uses it. Written as TOML text in the units of the mDEM keys
// (nm, ag, MPa, pN nm; docs/mdem-units.md); beam/ does not link mdem/.
#include <string>

#include "beam/brick.hpp"

namespace mesochain::beam {

struct MdemExportOptions {
  std::string elementType = "beam_brick";
  std::string bondType = "beam_bond";
  std::string modelFile = "model.toml";        // as referenced by the scene (same folder)
  std::string outputDirectory = "cantilever-out";
  int elements = 11;                           // cantilever length in bricks (element 0 clamped)
  double tipRotation = 0.02;                   // rad: the tip moments twist and bend it this much
};

// The loads of the scene: a tip moment about y (soft bending, I_y) and about z (twist), each
// sized for `tipRotation` by beam theory, phi = M l / (E I) over l = (elements - 1) L.
struct CantileverLoads {
  double bendingMoment = 0.0;  // pN nm, about world y
  double twistingMoment = 0.0; // pN nm, about world z
  double length = 0.0;         // nm, clamped element to tip
};
CantileverLoads cantileverLoads(const Brick& brick, const MdemExportOptions& options);

std::string mdemModelToml(const Brick& brick, const MdemExportOptions& options,
                          const std::string& headerComment);
std::string cantileverSceneToml(const Brick& brick, const MdemExportOptions& options);

}  // namespace mesochain::beam
