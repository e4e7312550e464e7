#include "mdem/bond_spectrum.hpp"

#include <numeric>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "common/errors.hpp"

namespace mesochain::mdem {

namespace {
int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

bool fullyConstrained(const KinematicMap& k, int i) {
  if (k.prescribed[i]) return true;
  const FixedDofs* f = k.fixed[i];
  if (!f) return false;
  for (bool b : f->fixed)
    if (!b) return false;
  return true;
}
}  // namespace

BondSpectrum bondSpectrum(const Bodies& s, const std::vector<Bond>& bonds, const KinematicMap& kinematics,
                          int maxComponentElements) {
  const int n = s.size();
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (const Bond& b : bonds) parent[findRoot(parent, b.a)] = findRoot(parent, b.b);
  // Components in order of their lowest element; local index of each element in its component.
  std::vector<int> componentOf(n, -1), local(n), rootComponent(n, -1);
  std::vector<std::vector<int>> members;
  for (int i = 0; i < n; ++i) {
    const int r = findRoot(parent, i);
    if (rootComponent[r] < 0) rootComponent[r] = static_cast<int>(members.size()), members.emplace_back();
    componentOf[i] = rootComponent[r];
    local[i] = static_cast<int>(members[componentOf[i]].size());
    members[componentOf[i]].push_back(i);
  }
  std::vector<std::vector<const Bond*>> componentBonds(members.size());
  for (const Bond& b : bonds) componentBonds[componentOf[b.a]].push_back(&b);

  BondSpectrum out;
  for (std::size_t c = 0; c < members.size(); ++c) {
    if (componentBonds[c].empty()) continue;
    const std::vector<int>& el = members[c];
    const int m = static_cast<int>(el.size());
    if (m > maxComponentElements)
      throw NumericalError(fmt::format("bond spectrum: a bonded component of {} elements (at most {} are solved densely)",
                                       m, maxComponentElements));
    ++out.components;
    out.largestComponent = std::max(out.largestComponent, m);
    // Stiffness in the world frame (parallel_bond.hpp, linearStiffness), mass with the body
    // inertia rotated to the world frame (normal_modes.cpp).
    Eigen::MatrixXd k = Eigen::MatrixXd::Zero(6 * m, 6 * m), mass = Eigen::MatrixXd::Zero(6 * m, 6 * m);
    for (const Bond* b : componentBonds[c]) {
      const Eigen::Matrix<double, 12, 12> kb = linearStiffness(*b, s);
      const int off[2] = {6 * local[b->a], 6 * local[b->b]};
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) k.block<6, 6>(off[i], off[j]) += kb.block<6, 6>(6 * i, 6 * j);
    }
    for (int e = 0; e < m; ++e) {
      const int i = el[e];
      mass.block<3, 3>(6 * e, 6 * e) = s.mass[i] * Mat3::Identity();
      const Mat3 r = toMatrix(s.orientation[i]);
      mass.block<3, 3>(6 * e + 3, 6 * e + 3) = r * s.inertia[i].asDiagonal() * r.transpose();
    }
    std::vector<int> keep;
    for (int e = 0; e < m; ++e)
      if (!fullyConstrained(kinematics, el[e]))
        for (int d = 0; d < 6; ++d) keep.push_back(6 * e + d);
    if (keep.empty()) continue;
    const int f = static_cast<int>(keep.size());
    Eigen::MatrixXd kr(f, f), mr(f, f);
    for (int i = 0; i < f; ++i)
      for (int j = 0; j < f; ++j) kr(i, j) = k(keep[i], keep[j]), mr(i, j) = mass(keep[i], keep[j]);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(kr, mr);
    if (solver.info() != Eigen::Success) throw NumericalError("bond spectrum: the generalized eigensolver did not converge");
    const double w = std::sqrt(std::max(0.0, solver.eigenvalues()(f - 1)));
    if (w <= out.omegaMax) continue;
    out.omegaMax = w, out.component = static_cast<int>(c);
    // Kinetic-energy shares of the mode in each element's body frame.
    Eigen::VectorXd v = Eigen::VectorXd::Zero(6 * m);
    for (int i = 0; i < f; ++i) v(keep[i]) = solver.eigenvectors()(i, f - 1);
    ModeShares sh;
    for (int e = 0; e < m; ++e) {
      const int i = el[e];
      const Vec3 u = rotateInverse(s.orientation[i], Vec3(v.segment<3>(6 * e)));
      const Vec3 phi = rotateInverse(s.orientation[i], Vec3(v.segment<3>(6 * e + 3)));
      sh.axial += s.mass[i] * u.z() * u.z();
      sh.transverse += s.mass[i] * (u.x() * u.x() + u.y() * u.y());
      sh.torsion += s.inertia[i].z() * phi.z() * phi.z();
      sh.bendingRotation += s.inertia[i].x() * phi.x() * phi.x() + s.inertia[i].y() * phi.y() * phi.y();
    }
    const double total = sh.axial + sh.transverse + sh.torsion + sh.bendingRotation;
    sh.axial /= total, sh.transverse /= total, sh.torsion /= total, sh.bendingRotation /= total;
    out.mode = sh;
  }
  return out;
}

}  // namespace mesochain::mdem
