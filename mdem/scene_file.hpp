#pragma once
// Scene files (TOML, format = 1) and model files; every key is documented in
// docs/scene-file.md. Unknown keys, missing files, out-of-range values and references to
// missing elements or types are InputErrors naming the file and the key.
#include <string>

#include "common/toml_table.hpp"
#include "mdem/scene.hpp"

namespace mesochain::mdem {

// Reads a scene; a `model = "file.toml"` key is resolved relative to the scene's folder.
Scene loadScene(const std::string& path);

// Reads element_types / bond_types (from a model file or a scene) into `scene`.
void readModelTables(const TomlTable& root, Scene& scene);

}  // namespace mesochain::mdem
