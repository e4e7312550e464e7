#include "dftb/pair_potential_term.hpp"

#include "objective/core/images.hpp"

namespace mesochain::dftb {

PairPotentialTerm::PairPotentialTerm(std::string name, PotentialLookup potential, double cutoff)
    : name_(std::move(name)), potential_(std::move(potential)), cutoff_(cutoff) {}

void PairPotentialTerm::evaluate(const objective::ObjectiveCell& cell,
                                 const EvaluationRequest& request, TermOutput& out) const {
  const objective::ImageList images(cell, cutoff_);
  const auto& sym = cell.symmetry;
  double energy = 0.0;
  if (request.gradient) out.gradient = Eigen::Matrix3Xd::Zero(3, cell.atomCount());
  out.dEdTranslation = out.dEdTwist = 0.0;
  for (const auto& q : images.pairs()) {
    double v = 0.0, dv = 0.0;
    potential_(cell.species[q.i], cell.species[q.j]).evaluate(q.r, v, dv);
    energy += 0.5 * v;
    if (!request.gradient && !request.strain) continue;
    // dE/dd for this ordered pair; each unordered pair appears twice, hence 1/2.
    const Eigen::Vector3d u = (0.5 * dv / q.r) * q.d;
    if (request.gradient) {
      out.gradient.col(q.i) -= u;
      out.gradient.col(q.j) += sym.rotation(q.g).transpose() * u;
    }
    if (request.strain && !sym.isRing()) {
      const double zeta = static_cast<double>(q.g.zeta);
      out.dEdTranslation += zeta * u.z();
      out.dEdTwist +=
          u.dot(zeta * objective::rotationZDerivative(sym.angle(q.g)) * cell.positions.col(q.j));
    }
  }
  out.energies.add(name_, EnergyKind::Energy, energy);
}

}  // namespace mesochain::dftb
