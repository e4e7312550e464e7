#include "mdem/normal_modes.hpp"

#include "common/errors.hpp"

namespace mesochain::mdem {

Eigen::MatrixXd assembleStiffness(const Bodies& s, const std::vector<Bond>& bonds) {
  const int n = 6 * s.size();
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
  for (const Bond& b : bonds) {
    const Eigen::Matrix<double, 12, 12> kb = linearStiffness(b, s);
    const int off[2] = {6 * b.a, 6 * b.b};
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) k.block<6, 6>(off[i], off[j]) += kb.block<6, 6>(6 * i, 6 * j);
  }
  return k;
}

Eigen::MatrixXd assembleMass(const Bodies& s) {
  const int n = 6 * s.size();
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < s.size(); ++i) {
    m.block<3, 3>(6 * i, 6 * i) = s.mass[i] * Mat3::Identity();
    const Mat3 r = toMatrix(s.orientation[i]);
    m.block<3, 3>(6 * i + 3, 6 * i + 3) = r * s.inertia[i].asDiagonal() * r.transpose();
  }
  return m;
}

Eigen::VectorXd eigenfrequencies(const Bodies& s, const std::vector<Bond>& bonds,
                                 const std::vector<bool>& freeDofs) {
  std::vector<int> keep;
  for (int i = 0; i < static_cast<int>(freeDofs.size()); ++i)
    if (freeDofs[i]) keep.push_back(i);
  const Eigen::MatrixXd k = assembleStiffness(s, bonds);
  const Eigen::MatrixXd m = assembleMass(s);
  const int f = static_cast<int>(keep.size());
  Eigen::MatrixXd kr(f, f), mr(f, f);
  for (int i = 0; i < f; ++i)
    for (int j = 0; j < f; ++j) kr(i, j) = k(keep[i], keep[j]), mr(i, j) = m(keep[i], keep[j]);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(kr, mr);
  if (solver.info() != Eigen::Success)
    throw NumericalError("normal modes: the generalized eigensolver did not converge");
  return solver.eigenvalues().cwiseMax(0.0).cwiseSqrt();
}

}  // namespace mesochain::mdem
