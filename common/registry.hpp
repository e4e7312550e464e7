#pragma once
// Self-registration, the part that dftb's term registry (dftb/term_registry.hpp) and mdem's
// effect registry (mdem/effect_registry.hpp) share, in the spirit of LAMMPS's
// BondStyle(name, Class): the file that implements a term or effect registers it at start-up
// with MESOCHAIN_REGISTER_AT_STARTUP; the engine builds, in order, whatever is registered.
//
// `Registration` is an aggregate with at least `std::string name` and `int order`; each side
// adds its own members (factories, when it is wanted) and its own checks. A library holding
// registrations is linked whole (WHOLE_ARCHIVE), or the linker drops them.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace mesochain {

template <class Registration>
class Registry {
 public:
  // `what` names a registration in messages ("dftb term", "mdem effect").
  explicit Registry(const char* what) : what_(what) {}

  // Two registrations of one name are a programming error (std::logic_error at start-up).
  void add(Registration r) {
    if (find(r.name)) throw std::logic_error(std::string(what_) + " '" + r.name + "' registered twice");
    entries_.push_back(std::move(r));
  }
  // Every registration, by order, then name.
  std::vector<const Registration*> ordered() const {
    std::vector<const Registration*> out;
    for (const Registration& r : entries_) out.push_back(&r);
    std::sort(out.begin(), out.end(), [](const Registration* a, const Registration* b) {
      return a->order != b->order ? a->order < b->order : a->name < b->name;
    });
    return out;
  }
  const Registration* find(std::string_view name) const {
    for (const Registration& r : entries_)
      if (r.name == name) return &r;
    return nullptr;
  }

 private:
  const char* what_;
  std::vector<Registration> entries_;
};

}  // namespace mesochain

#define MESOCHAIN_REGISTRY_CONCAT_(a, b) a##b
#define MESOCHAIN_REGISTRY_CONCAT(a, b) MESOCHAIN_REGISTRY_CONCAT_(a, b)
// MESOCHAIN_REGISTER_AT_STARTUP(call) at namespace scope: evaluates `call` (a registration
// function returning true) during static initialisation.
#define MESOCHAIN_REGISTER_AT_STARTUP(...)                                                  \
  namespace {                                                                               \
  [[maybe_unused]] const bool MESOCHAIN_REGISTRY_CONCAT(mesochainRegistered_, __LINE__) = \
      (__VA_ARGS__);                                                                        \
  }
