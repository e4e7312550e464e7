#pragma once
// Effects register themselves (in the spirit of LAMMPS's BondStyle(name, Class)): the file that
// implements an effect also registers it with its name, its place in the force order and a
// factory, through MESOCHAIN_MDEM_EFFECT. The simulation builds, in order, every registered
// effect the scene wants; nothing else in the engine lists effects.
//
// Order (the sum of forces per element runs in this order; damping must come after what it
// damps): 100 conservative interactions (bonds, contacts), 300 loads, 400 physical dissipation
// (dashpots), 500 numerical damping.
//
// The mdem library is linked whole (mdem/CMakeLists.txt), so every registration in it is kept.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "common/registry.hpp"
#include "common/toml_table.hpp"
#include "mdem/effect.hpp"

namespace mesochain::mdem {

struct Scene;

// What a factory is given: the scene, and a place where effects built for one scene share an
// object (e.g. the contact effects' neighbour list).
class EffectBuild {
 public:
  explicit EffectBuild(const Scene& scene) : scene(scene) {}
  const Scene& scene;
  bool named(std::string_view effect) const;
  // The shared object under `key`, made by `make` the first time it is asked for.
  template <class T>
  std::shared_ptr<T> shared(const std::string& key, const std::function<std::shared_ptr<T>()>& make) {
    std::shared_ptr<void>& p = shared_[key];
    if (!p) p = make();
    return std::static_pointer_cast<T>(p);
  }

 private:
  std::map<std::string, std::shared_ptr<void>> shared_;
};

// An effect's own table of the scene file ([vdw_contact], [local_damping], ...), read by the
// effect's file through common/toml_table (strict: unknown keys, types, ranges name the key).
struct EffectTable {
  std::string name;       // the table's name ("" for an effect without one)
  bool required = false;  // naming the effect without its table is an error
  std::function<void(const TomlTable&, Scene&)> read;
};

struct EffectRegistration {
  std::string name;     // as listed in a scene's `effects`
  int order = 100;      // see above
  std::string summary;  // one line, for messages and docs
  // Built when named in the scene's `effects` (listable), or, when `implicit` is set, whenever
  // it says so (loads: whenever the scene has loads; such effects are not listed by name).
  bool listable = true;
  std::function<bool(const Scene&)> implicit;
  std::function<EffectPtr(EffectBuild&)> make;
  EffectTable table;  // its scene table, if it has one
  // A stage may add it for that stage only ([[stages]] add_effects): no state that evolves over
  // the run (numerical damping); bonds and contacts are named for the whole run.
  bool stageable = false;
};

// Registers an effect; returns true (for the static initialiser). Two effects of one name are a
// programming error (std::logic_error at start-up). The registry itself is common/registry.hpp.
bool registerEffect(EffectRegistration registration);
// Every registered effect, by order (then name).
std::vector<const EffectRegistration*> registeredEffects();
const EffectRegistration* findEffect(std::string_view name);

// Reads the table of every registered effect that has one: refused when present for an effect
// that neither `effects` nor a stage's add_effects names (`stageEffects`), or absent for a named
// effect whose table is required.
void readEffectTables(const TomlTable& root, Scene& scene, const std::vector<std::string>& stageEffects);
// The names of the effects a stage may add, quoted, for messages.
std::string stageableEffectNames();

// Builds the effects `scene` wants, in order. Throws InputError (key effects) for a name that
// is not a registered, listable effect, or a name given twice.
std::vector<EffectPtr> buildEffects(const Scene& scene);

}  // namespace mesochain::mdem

// MESOCHAIN_MDEM_EFFECT(EffectRegistration{...}) at namespace scope in the effect's .cpp.
#define MESOCHAIN_MDEM_EFFECT(...) MESOCHAIN_REGISTER_AT_STARTUP(::mesochain::mdem::registerEffect(__VA_ARGS__))
