#include "mdem/stability.hpp"

#include <cmath>
#include <limits>

namespace mesochain::mdem {

namespace {
bool fullyConstrained(const KinematicMap& k, int i) {
  if (k.prescribed[i]) return true;
  const FixedDofs* f = k.fixed[i];
  if (!f) return false;
  for (bool b : f->fixed)
    if (!b) return false;
  return true;
}
}  // namespace

StabilityLimit criticalTimeStep(const Bodies& s, const std::vector<Bond>& bonds,
                                const KinematicMap& kinematics) {
  const int n = s.size();
  std::vector<double> rowSum(6 * static_cast<std::size_t>(n), 0.0);
  std::vector<char> active(n);
  for (int i = 0; i < n; ++i) active[i] = !fullyConstrained(kinematics, i);
  auto massOf = [&](int element, int dof) {
    return dof < 3 ? s.mass[element] : s.inertia[element][dof - 3];
  };
  for (const Bond& b : bonds) {
    const Eigen::Matrix<double, 12, 12> kw = linearStiffness(b, s);
    // Rotational DOFs to the principal frames: phi_world = R phi_body.
    Eigen::Matrix<double, 12, 12> t = Eigen::Matrix<double, 12, 12>::Identity();
    t.block<3, 3>(3, 3) = toMatrix(s.orientation[b.a]);
    t.block<3, 3>(9, 9) = toMatrix(s.orientation[b.b]);
    const Eigen::Matrix<double, 12, 12> k = t.transpose() * kw * t;
    const int el[2] = {b.a, b.b};
    for (int r = 0; r < 12; ++r) {
      const int er = el[r / 6];
      if (!active[er]) continue;
      const double mr = massOf(er, r % 6);
      for (int c = 0; c < 12; ++c) {
        const int ec = el[c / 6];
        if (!active[ec]) continue;
        rowSum[6 * er + r % 6] += std::abs(k(r, c)) / std::sqrt(mr * massOf(ec, c % 6));
      }
    }
  }
  StabilityLimit lim;
  double best = 0.0;
  for (std::size_t r = 0; r < rowSum.size(); ++r) {
    if (rowSum[r] > best) {
      best = rowSum[r];
      lim.element = static_cast<int>(r / 6);
      lim.rotational = (r % 6) >= 3;
    }
  }
  lim.omegaMax = std::sqrt(best);
  lim.criticalTimeStep =
      best > 0.0 ? 2.0 / lim.omegaMax : std::numeric_limits<double>::infinity();
  return lim;
}

}  // namespace mesochain::mdem
