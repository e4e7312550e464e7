#include "mdem/effect_registry.hpp"

#include <algorithm>

#include "common/errors.hpp"
#include "mdem/scene.hpp"

namespace mesochain::mdem {

namespace {
// Function-local static: registrations run during static initialisation of other files.
Registry<EffectRegistration>& registry() {
  static Registry<EffectRegistration> r("mdem effect");
  return r;
}
}  // namespace

bool EffectBuild::named(std::string_view effect) const {
  return std::find(scene.effects.begin(), scene.effects.end(), effect) != scene.effects.end();
}

void Effect::addForces(State& state) {
  Bodies& s = state.bodies;
  if (hasPrepare()) prepare(state, state.time);
  computeItems(state, state.time, 0, itemCount());
  gather(state, state.time, 0, s.size(), s.force.data(), s.torque.data());
  if (hasFinish()) finish(state, state.time);
}

bool registerEffect(EffectRegistration r) {
  registry().add(std::move(r));
  return true;
}

std::vector<const EffectRegistration*> registeredEffects() { return registry().ordered(); }

const EffectRegistration* findEffect(std::string_view name) { return registry().find(name); }

void readEffectTables(const TomlTable& root, Scene& scene, const std::vector<std::string>& stageEffects) {
  for (const EffectRegistration* r : registeredEffects()) {
    const EffectTable& t = r->table;
    if (t.name.empty()) continue;
    const bool named = std::find(scene.effects.begin(), scene.effects.end(), r->name) != scene.effects.end() ||
                       std::find(stageEffects.begin(), stageEffects.end(), r->name) != stageEffects.end();
    if (root.has(t.name) && !named)
      root.fail(t.name, "parameters for an effect that is not listed", "\"" + r->name + "\" in effects");
    if (!root.has(t.name) && named && t.required)
      root.fail(t.name, "nothing", "a [" + t.name + "] table (docs/scene-file.md, docs/mdem-contacts.md)");
    if (root.has(t.name)) t.read(root.requireTable(t.name), scene);
  }
}

std::string stageableEffectNames() {
  std::string out;
  for (const EffectRegistration* r : registeredEffects())
    if (r->stageable) out += (out.empty() ? "\"" : " or \"") + r->name + "\"";
  return out;
}

std::vector<EffectPtr> buildEffects(const Scene& scene) {
  std::string known;
  for (const EffectRegistration* r : registeredEffects())
    if (r->listable) known += (known.empty() ? "\"" : ", \"") + r->name + "\"";
  for (std::size_t k = 0; k < scene.effects.size(); ++k) {
    const std::string& e = scene.effects[k];
    const EffectRegistration* r = findEffect(e);
    if (!r || !r->listable) throw InputError(scene.source, "key effects", "\"" + e + "\"", "one of " + known);
    if (std::find(scene.effects.begin(), scene.effects.begin() + k, e) != scene.effects.begin() + k)
      throw InputError(scene.source, "key effects", "\"" + e + "\" listed twice", "each effect once");
  }
  EffectBuild build(scene);
  std::vector<EffectPtr> effects;
  for (const EffectRegistration* r : registeredEffects()) {
    const bool wanted = r->implicit ? r->implicit(scene) : build.named(r->name);
    if (wanted) effects.push_back(r->make(build));
  }
  return effects;
}

}  // namespace mesochain::mdem
