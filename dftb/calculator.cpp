#include "dftb/calculator.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "common/errors.hpp"
#include "dftb/term_registry.hpp"

namespace mesochain::dftb {

Calculator::Calculator(std::shared_ptr<const ParameterSet> params, CalculatorSettings settings,
                       parallel::Communicator comm)
    : params_(std::move(params)), settings_(settings), comm_(std::move(comm)) {
  // Charge interactions first: the band term's factory decides on SCC by whether there are any.
  TermBuild build{params_, settings_, chargeCache_, {}, comm_};
  for (const TermRegistration* t : registeredTerms())
    if (t->needsCharges && t->wanted(settings_)) {
      build.chargeInteractions.push_back(t->makeInteraction(build));
      names_.push_back(t->name);
    }
  for (const TermRegistration* t : registeredTerms())
    if (!t->needsCharges && t->wanted(settings_)) {
      terms_.push_back(t->make(build));
      names_.push_back(t->name);
    }
  // In registration order.
  std::vector<std::string> ordered;
  for (const TermRegistration* t : registeredTerms())
    for (const std::string& n : names_)
      if (n == t->name) ordered.push_back(n);
  names_ = std::move(ordered);
}


namespace {
// The band term holds at least three complex N_o x N_o matrices (Hamiltonian, overlap,
// eigenvectors) of a k-point at a time: 48 N_o^2 bytes. A cell whose estimate exceeds the
// machine's memory is refused before the first allocation (a bare std::bad_alloc otherwise).
void requireBandMemory(const objective::ObjectiveCell& cell, const ParameterSet& params,
                       int kpoints) {
  double orbitals = 0;
  for (int a = 0; a < cell.atomCount(); ++a)
    orbitals += params.species(cell.species[a]).orbitalCount;
  const double bytes = 48.0 * orbitals * orbitals;
  const double memory = static_cast<double>(::sysconf(_SC_PHYS_PAGES)) *
                        static_cast<double>(::sysconf(_SC_PAGE_SIZE));
  if (memory > 0 && bytes > memory)
    throw InputError("<calculator>", "the cell's atoms",
                     fmt::format("{} atoms with {:.0f} orbitals: at least {:.3g} GB for the "
                                 "Hamiltonian, overlap and eigenvectors of one of the {} k-points",
                                 cell.atomCount(), orbitals, bytes * 1e-9, kpoints),
                     fmt::format("a cell that fits the {:.3g} GB of this machine", memory * 1e-9));
}
}  // namespace

Result Calculator::evaluate(const objective::ObjectiveCell& cell,
                            const EvaluationRequest& request) const {
  for (size_t s = 0; s < cell.speciesNames.size(); ++s)
    if (static_cast<int>(s) >= params_->speciesCount() ||
        params_->species(static_cast<int>(s)).name != cell.speciesNames[s])
      throw InputError("<calculator>", "species " + cell.speciesNames[s],
                       "a species order that differs from the parameter set",
                       "the parameter set loaded for this cell's species");
  requireBandMemory(cell, *params_, settings_.band.helicalKPoints);
  Result r;
  r.atoms = cell.atomCount();
  if (request.gradient) r.gradient = Eigen::Matrix3Xd::Zero(3, cell.atomCount());
  for (const auto& term : terms_) {
    TermOutput out;
    const auto t0 = std::chrono::steady_clock::now();
    term->evaluate(cell, request, out);
    r.extras["time_" + term->name() + "_total"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (request.gradient) r.gradient += out.gradient;
    r.dFdTranslation += out.dEdTranslation;
    r.dFdTwist += out.dEdTwist;
    r.energies.merge(out.energies);
    for (const auto& [k, v] : out.extras) r.extras[k] = v;
    for (auto& [k, v] : out.series) r.series[k] = std::move(v);
  }
  r.totalEnergy = r.energies.total();
  r.freeEnergy = r.energies.free();
  r.extrapolatedEnergy = r.energies.extrapolated();
  // A non-finite energy or force is never a result (it would be written as null, exit 0).
  for (const LedgerEntry& e : r.energies.entries())
    if (!std::isfinite(e.value))
      throw NumericalError(fmt::format("the calculator gave a non-finite {} energy ({}) for a cell "
                                       "of {} atoms", e.name, e.value, cell.atomCount()));
  const std::pair<const char*, double> strain[] = {{"dF/dT", r.dFdTranslation},
                                                   {"dF/dtwist", r.dFdTwist}};
  for (const auto& [name, value] : strain)
    if (!std::isfinite(value))
      throw NumericalError(fmt::format("the calculator gave a non-finite {} ({}) for a cell of {} "
                                       "atoms", name, value, cell.atomCount()));
  if (r.gradient.size() && !r.gradient.allFinite())
    throw NumericalError(fmt::format("the calculator gave non-finite forces for a cell of {} atoms",
                                     cell.atomCount()));
  return r;
}

}  // namespace mesochain::dftb
