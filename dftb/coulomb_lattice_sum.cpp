#include "dftb/coulomb_lattice_sum.hpp"

#include <limits>

#include "common/errors.hpp"
#include "dftb/image_pair_sum.hpp"
#include "ewald/helical_lattice_sum.hpp"

namespace mesochain::dftb {

namespace {
void requireRing(const objective::ObjectiveCell& cell) {
  if (!cell.symmetry.isRing())
    throw InputError("the calculator settings", "scc.enabled with the cell's symmetry",
                     "a screw cell (T > 0) with SCC: its 1/r sum needs the helical Ewald sum, "
                     "which this build does not have yet",
                     "a closed ring or molecule (T = 0), or [scc] enabled = false");
}
void coulomb(int, int, double r, double& v, double& dv) {
  v = 1.0 / r;
  dv = -v / r;
}
// Every image of a ring: the cutoff is infinite (the ring enumerates c = 0..N_a-1 only).
objective::ImageList allRingImages(const objective::ObjectiveCell& cell) {
  return objective::ImageList(cell, std::numeric_limits<double>::infinity());
}
}  // namespace

Eigen::MatrixXd DirectRingCoulombSum::matrix(const objective::ObjectiveCell& cell) const {
  requireRing(cell);
  return imagePairMatrix(cell, allRingImages(cell), coulomb);
}

LatticeSumDerivatives DirectRingCoulombSum::derivatives(const objective::ObjectiveCell& cell,
                                                        const Eigen::MatrixXd& weights) const {
  requireRing(cell);
  return imagePairDerivatives(cell, allRingImages(cell), weights, coulomb);
}

struct HelicalEwaldCoulombSum::Impl {
  ewald::HelicalLatticeSum sum;
};

HelicalEwaldCoulombSum::HelicalEwaldCoulombSum(double tolerance)
    : impl_(std::make_unique<Impl>(Impl{ewald::HelicalLatticeSum(
          ewald::Kernel::Coulomb, ewald::LatticeSumSettings{tolerance, std::nullopt})})) {}

HelicalEwaldCoulombSum::~HelicalEwaldCoulombSum() = default;

Eigen::MatrixXd HelicalEwaldCoulombSum::matrix(const objective::ObjectiveCell& cell) const {
  return impl_->sum.matrix(cell);
}

LatticeSumDerivatives HelicalEwaldCoulombSum::derivatives(const objective::ObjectiveCell& cell,
                                                          const Eigen::MatrixXd& weights) const {
  const auto d = impl_->sum.derivatives(cell, weights);
  LatticeSumDerivatives out;
  out.energy = d.energy;
  out.gradient = d.gradient;
  out.dTranslation = d.dTranslation;
  out.dTwist = d.dTwist;
  return out;
}

std::unique_ptr<CoulombLatticeSum> makeCoulombLatticeSum(double tolerance) {
  return std::make_unique<HelicalEwaldCoulombSum>(tolerance);
}

}  // namespace mesochain::dftb
