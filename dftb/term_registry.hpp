#pragma once
// dftb energy terms register themselves (in the spirit of LAMMPS's BondStyle(name, Class) and
// tblite's container list): the file that implements a term also registers it with its name,
// its place in the evaluation order, whether it needs the SCC charges, when the calculator
// settings ask for it, and a factory, through MESOCHAIN_DFTB_TERM. The calculator builds every
// registered term the settings want and sums whatever they report into its energy ledger;
// nothing else in the calculator lists terms.
//
// Two kinds of registration:
//   an energy term (needsCharges = false, `make`): evaluated on its own by the calculator;
//   a charge interaction (needsCharges = true, `makeInteraction`, dftb/charge_interaction.hpp):
//     built first and handed to every term's factory (TermBuild::chargeInteractions); the band
//     term then runs the self-consistency loop with their summed kernel (dftb/scc_term.hpp).
//
// Order: 100 the electronic (band-structure) terms, 150 charge interactions (SCC), 200 pair
// potentials of the tables (repulsive), 300 empirical corrections (dispersion).
//
// The dftb library is linked whole (dftb/CMakeLists.txt), so every registration in it is kept.
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "common/registry.hpp"
#include "dftb/energy_term.hpp"
#include "parallel/communicator.hpp"

namespace mesochain::dftb {

class ParameterSet;
class ChargeCache;
class ChargeInteraction;
struct CalculatorSettings;

// What a factory is given.
struct TermBuild {
  std::shared_ptr<const ParameterSet> params;
  const CalculatorSettings& settings;
  // Converged SCC charges kept between evaluations (terms that need the charges).
  std::shared_ptr<ChargeCache> chargeCache;
  // The charge interactions the settings want (empty: no SCC).
  std::vector<std::shared_ptr<const ChargeInteraction>> chargeInteractions;
  // The ranks that share the work of one evaluation (the band term's k-points).
  parallel::Communicator comm = parallel::Communicator::serial();
};

struct TermRegistration {
  std::string name;     // the term's name() (and its timing key time_<name>_total)
  int order = 100;      // see above
  std::string summary;  // one line, for messages and docs
  // True for a charge interaction: its energy depends on the self-consistent Mulliken charges
  // (built by makeInteraction, not make).
  bool needsCharges = false;
  // Whether `settings` ask for the term.
  std::function<bool(const CalculatorSettings&)> wanted;
  std::function<std::unique_ptr<EnergyTerm>(const TermBuild&)> make;
  std::function<std::shared_ptr<const ChargeInteraction>(const TermBuild&)> makeInteraction;
};

// Registers a term; returns true (for the static initialiser). Two terms of one name, or a term
// without wanted() or without exactly the factory of its kind, are a programming error
// (std::logic_error at start-up). The registry itself is common/registry.hpp.
bool registerTerm(TermRegistration registration);
// Every registered term, by order (then name).
std::vector<const TermRegistration*> registeredTerms();
const TermRegistration* findTerm(std::string_view name);

}  // namespace mesochain::dftb

// MESOCHAIN_DFTB_TERM(TermRegistration{...}) at namespace scope in the term's .cpp.
#define MESOCHAIN_DFTB_TERM(...) MESOCHAIN_REGISTER_AT_STARTUP(::mesochain::dftb::registerTerm(__VA_ARGS__))
