#include "dftb/term_registry.hpp"

#include <stdexcept>

namespace mesochain::dftb {

namespace {
// Function-local static: registrations run during static initialisation of other files.
Registry<TermRegistration>& registry() {
  static Registry<TermRegistration> r("dftb term");
  return r;
}
}  // namespace

bool registerTerm(TermRegistration r) {
  if (!r.wanted || (r.needsCharges ? !r.makeInteraction || r.make : !r.make || r.makeInteraction))
    throw std::logic_error("dftb term '" + r.name + "' registered without wanted(), or without "
                           "exactly the factory of its kind (make, or makeInteraction when it "
                           "needs the charges)");
  registry().add(std::move(r));
  return true;
}

std::vector<const TermRegistration*> registeredTerms() { return registry().ordered(); }

const TermRegistration* findTerm(std::string_view name) { return registry().find(name); }

}  // namespace mesochain::dftb
