#pragma once
// Scene-file tables of the contacts (docs/scene-file.md, docs/mdem-contacts.md):
// [vdw_contact], [contact_damping], [contacts] (neighbour search), [periodic].
#include "mdem/scene.hpp"
#include "common/toml_table.hpp"

namespace mesochain::mdem {

// The effects' own tables, registered with them (mdem/contacts/contact_effects.cpp; read by
// readEffectTables, mdem/effect_registry.hpp): [vdw_contact] and [contact_damping].
void readVdwContactTable(const TomlTable& t, Scene& s);
void readContactDampingTable(const TomlTable& t, Scene& s);

// [contacts] (neighbour search) and [periodic], then the range checks of every contact setting
// (after the effects' tables are read).
void readContactTables(const TomlTable& root, Scene& s);

// [network]: a random network of tubes (method = "random", network_generator.hpp) or a deposited
// film (method = "deposition", deposition_file.hpp) appended to the scene's elements; sets
// Scene::filmSize. Keys in docs/scene-file.md.
void readNetworkTable(const TomlTable& root, Scene& s);

// [network] tube_length_nm as a number of elements of type e (a whole number of lengths), for both
// network methods; InputError naming the key otherwise.
int elementsPerTube(const TomlTable& t, const ElementType& e);

// Range checks shared with scenes built in C++ (throws InputError naming `source` and the key).
void validateContactSpec(const Scene& s);

}  // namespace mesochain::mdem
