#include "dftb/term_registry.hpp"

#include <algorithm>
#include <stdexcept>

namespace mesochain::dftb {

namespace {
// Function-local static: registrations run during static initialisation of other files.
std::vector<TermRegistration>& registry() {
  static std::vector<TermRegistration> r;
  return r;
}
}  // namespace

bool registerTerm(TermRegistration r) {
  for (const TermRegistration& o : registry())
    if (o.name == r.name) throw std::logic_error("dftb term '" + r.name + "' registered twice");
  if (!r.wanted || (r.needsCharges ? !r.makeInteraction || r.make : !r.make || r.makeInteraction))
    throw std::logic_error("dftb term '" + r.name + "' registered without wanted(), or without "
                           "exactly the factory of its kind (make, or makeInteraction when it "
                           "needs the charges)");
  registry().push_back(std::move(r));
  return true;
}

std::vector<const TermRegistration*> registeredTerms() {
  std::vector<const TermRegistration*> out;
  for (const TermRegistration& r : registry()) out.push_back(&r);
  std::sort(out.begin(), out.end(), [](const TermRegistration* a, const TermRegistration* b) {
    return a->order != b->order ? a->order < b->order : a->name < b->name;
  });
  return out;
}

const TermRegistration* findTerm(std::string_view name) {
  for (const TermRegistration& r : registry())
    if (r.name == name) return &r;
  return nullptr;
}

}  // namespace mesochain::dftb
