#pragma once
// [network] method = "deposition" (docs/scene-file.md): reads the keys, sets the scene's
// periodicity (periodic films) and lays the film (deposition.hpp).
#include "mdem/scene.hpp"
#include "common/toml_table.hpp"

namespace mesochain::mdem {

// `network` is root's [network] table. Checks [periodic] (root) against the film.
void readDepositionTable(const TomlTable& root, const TomlTable& network, Scene& s);

}  // namespace mesochain::mdem
