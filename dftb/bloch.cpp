#include "dftb/bloch.hpp"

#include <cmath>
#include <complex>

#include "objective/core/symmetry.hpp"

namespace mesochain::dftb {

using objective::GroupElement;
using objective::HelicalKGrid;
using objective::HelicalKPoint;
using objective::ImageList;
using objective::ImagePair;
using objective::ObjectiveCell;

OrbitalLayout::OrbitalLayout(const ObjectiveCell& cell, const ParameterSet& params) {
  const int n = cell.atomCount();
  offset.resize(n);
  count.resize(n);
  for (int a = 0; a < n; ++a) {
    offset[a] = total;
    count[a] = params.species(cell.species[a]).orbitalCount;
    total += count[a];
  }
}

OrbitalBlock orbitalRotation(const Eigen::Matrix3d& r) {
  OrbitalBlock d = OrbitalBlock::Zero();
  d(0, 0) = 1.0;
  d.bottomRightCorner<3, 3>() = r;
  return d;
}

void computeRealSpaceBlocks(const ObjectiveCell& cell, const ParameterSet& params,
                            const ImageList& images, std::vector<OrbitalBlock>& h,
                            std::vector<OrbitalBlock>& s) {
  const auto& pairs = images.pairs();
  h.resize(pairs.size());
  s.resize(pairs.size());
  OrbitalBlock b, o;
  for (size_t p = 0; p < pairs.size(); ++p) {
    const ImagePair& q = pairs[p];
    params.integrals(cell.species[q.i], cell.species[q.j]).blocks(q.d, b, o);
    const OrbitalBlock d = orbitalRotation(cell.symmetry.rotation(q.g));
    h[p].noalias() = b * d;
    s[p].noalias() = o * d;
  }
}

namespace {
template <class Matrix>
void addOnsite(const ObjectiveCell& cell, const ParameterSet& params, const OrbitalLayout& layout,
               const Eigen::VectorXd& shift, Matrix& hk, Matrix& sk) {
  for (int a = 0; a < cell.atomCount(); ++a) {
    const SpeciesData& sp = params.species(cell.species[a]);
    const int o = layout.offset[a];
    const double v = shift.size() > 0 ? shift[a] : 0.0;
    hk(o, o) += sp.onsiteS + v;
    sk(o, o) += 1.0;
    for (int m = 1; m < layout.count[a]; ++m) {
      hk(o + m, o + m) += sp.onsiteP + v;
      sk(o + m, o + m) += 1.0;
    }
  }
}
}  // namespace

namespace {
// H(k), S(k) from the real-space blocks: one loop for complex and real k-points; `phase` gives
// the Bloch factor of a group element (complex, or +-1 for a real k-point).
template <class Matrix, class Phase>
void assembleWith(const ObjectiveCell& cell, const ParameterSet& params,
                  const OrbitalLayout& layout, const ImageList& images,
                  const std::vector<OrbitalBlock>& h, const std::vector<OrbitalBlock>& s,
                  Phase phase, const Eigen::VectorXd& shift, Matrix& hk, Matrix& sk) {
  hk.setZero();
  sk.setZero();
  addOnsite(cell, params, layout, shift, hk, sk);
  const auto& pairs = images.pairs();
  for (size_t p = 0; p < pairs.size(); ++p) {
    const ImagePair& q = pairs[p];
    if (q.i < q.j) continue;  // strict upper triangle: LAPACK reads the lower one
    const auto f = phase(q.g);
    const int oi = layout.offset[q.i], oj = layout.offset[q.j];
    const int ni = layout.count[q.i], nj = layout.count[q.j];
    for (int b = 0; b < nj; ++b)
      for (int a = 0; a < ni; ++a) {
        hk(oi + a, oj + b) += f * h[p](a, b);
        sk(oi + a, oj + b) += f * s[p](a, b);
      }
  }
}
}  // namespace

void assembleBloch(const ObjectiveCell& cell, const ParameterSet& params,
                   const OrbitalLayout& layout, const ImageList& images,
                   const std::vector<OrbitalBlock>& h, const std::vector<OrbitalBlock>& s,
                   const HelicalKGrid& grid, const HelicalKPoint& k, ComplexMatrix& hk,
                   ComplexMatrix& sk, const Eigen::VectorXd& onsiteShift) {
  assembleWith(cell, params, layout, images, h, s,
               [&](const GroupElement& g) { return std::polar(1.0, grid.phase(k, g)); },
               onsiteShift, hk, sk);
}

void assembleBlochReal(const ObjectiveCell& cell, const ParameterSet& params,
                       const OrbitalLayout& layout, const ImageList& images,
                       const std::vector<OrbitalBlock>& h, const std::vector<OrbitalBlock>& s,
                       const HelicalKGrid& grid, const HelicalKPoint& k, Eigen::MatrixXd& hk,
                       Eigen::MatrixXd& sk, const Eigen::VectorXd& onsiteShift) {
  // Exactly +-1 for a real k-point.
  assembleWith(cell, params, layout, images, h, s,
               [&](const GroupElement& g) { return std::cos(grid.phase(k, g)); }, onsiteShift,
               hk, sk);
}

BandDerivatives contractDerivatives(const ObjectiveCell& cell, const ParameterSet& params,
                                    const ImageList& images, const std::vector<OrbitalBlock>& pm,
                                    const std::vector<OrbitalBlock>& wm, bool strain) {
  BandDerivatives out;
  out.gradient = Eigen::Matrix3Xd::Zero(3, cell.atomCount());
  const auto& pairs = images.pairs();
  const auto& sym = cell.symmetry;
  OrbitalBlock b, o, db[3], dso[3];
  for (size_t p = 0; p < pairs.size(); ++p) {
    const ImagePair& q = pairs[p];
    params.integrals(cell.species[q.i], cell.species[q.j])
        .blocksWithDerivatives(q.d, b, o, db, dso);
    const double phi = sym.angle(q.g);
    const Eigen::Matrix3d r = objective::rotationZ(phi);
    const OrbitalBlock d = orbitalRotation(r);
    // (X D) : P = X : (P D^T), so contract with the rotated P and W once per pair.
    const OrbitalBlock pd = pm[p] * d.transpose();
    const OrbitalBlock wd = wm[p] * d.transpose();
    Eigen::Vector3d v;
    for (int c = 0; c < 3; ++c) v[c] = (db[c].cwiseProduct(pd)).sum() - (dso[c].cwiseProduct(wd)).sum();
    // d = g(x_j) - x_i: dd/dx_i = -1, dd/dx_j = R(g).
    out.gradient.col(q.i) -= v;
    out.gradient.col(q.j) += r.transpose() * v;
    if (strain && !sym.isRing()) {
      const double zeta = static_cast<double>(q.g.zeta);
      // dd/dT = zeta e_z; dd/dgamma = zeta R'(phi) x_j; D depends on gamma through phi.
      out.dEdTranslation += zeta * v.z();
      const Eigen::Vector3d dd = zeta * objective::rotationZDerivative(phi) * cell.positions.col(q.j);
      OrbitalBlock dD = OrbitalBlock::Zero();
      dD.bottomRightCorner<3, 3>() = zeta * objective::rotationZDerivative(phi);
      out.dEdTwist += v.dot(dd) + (b * dD).cwiseProduct(pm[p]).sum() -
                      (o * dD).cwiseProduct(wm[p]).sum();
    }
  }
  return out;
}

}  // namespace mesochain::dftb
