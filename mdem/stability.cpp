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
                                const KinematicMap& kinematics,
                                const std::vector<ContactStabilityTerms>& contactTerms, GershgorinFrame frame) {
  const int n = s.size();
  std::vector<double> rowSum(6 * static_cast<std::size_t>(n), 0.0);
  std::vector<char> active(n);
  for (int i = 0; i < n; ++i) active[i] = !fullyConstrained(kinematics, i);
  auto massOf = [&](int element, int dof) {
    return dof < 3 ? s.mass[element] : s.inertia[element][dof - 3];
  };
  for (const Bond& b : bonds) {
    const Eigen::Matrix<double, 12, 12> kw = linearStiffness(b, s);
    // Rotational DOFs to the principal frames: phi_world = R phi_body (translations too in the
    // body frame: u_world = R u_body).
    Eigen::Matrix<double, 12, 12> t = Eigen::Matrix<double, 12, 12>::Identity();
    const Mat3 ra = toMatrix(s.orientation[b.a]), rb = toMatrix(s.orientation[b.b]);
    t.block<3, 3>(3, 3) = ra;
    t.block<3, 3>(9, 9) = rb;
    if (frame == GershgorinFrame::Body) t.block<3, 3>(0, 0) = ra, t.block<3, 3>(6, 6) = rb;
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
  // Contact rows: stiffness (omega^2) and damping rate per DOF.
  std::vector<double> contactRow(rowSum.size(), 0.0), rate(rowSum.size(), 0.0);
  if (!contactTerms.empty()) {
    for (int i = 0; i < n; ++i) {
      if (!active[i]) continue;
      const ContactStabilityTerms& c = contactTerms[s.type[i]];
      for (int d = 0; d < 6; ++d) {
        const double k = d < 3 ? c.stiffness : c.rotationalStiffness[d - 3];
        const double g = d < 3 ? c.damping : c.rotationalDamping[d - 3];
        contactRow[6 * i + d] = k / massOf(i, d);
        rate[6 * i + d] = g / massOf(i, d);
      }
    }
  }
  StabilityLimit lim;
  lim.criticalTimeStep = std::numeric_limits<double>::infinity();
  double best = 0.0;
  for (std::size_t r = 0; r < rowSum.size(); ++r) {
    const double w2 = rowSum[r] + contactRow[r], beta = rate[r];
    best = std::max(best, w2);
    double h = std::numeric_limits<double>::infinity();
    if (w2 > 0.0) {
      const double w = std::sqrt(w2), zeta = beta / (2.0 * w);
      h = 2.0 / w * (std::sqrt(1.0 + zeta * zeta) - zeta);
    } else if (beta > 0.0) {
      h = 2.0 / beta;
    }
    if (h < lim.criticalTimeStep) {
      lim.criticalTimeStep = h;
      lim.element = static_cast<int>(r / 6);
      lim.rotational = (r % 6) >= 3;
      lim.omega = std::sqrt(w2);
      lim.dampingRate = beta;
      // The term that alone would give the shortest step names the limit.
      const double hb = rowSum[r] > 0.0 ? 2.0 / std::sqrt(rowSum[r]) : HUGE_VAL;
      const double hv = contactRow[r] > 0.0 ? 2.0 / std::sqrt(contactRow[r]) : HUGE_VAL;
      const double hd = beta > 0.0 ? 2.0 / beta : HUGE_VAL;
      lim.limitedBy = hd < hb && hd < hv ? "contact dashpots" : hv < hb ? "van der Waals contacts" : "bonds";
    }
  }
  lim.omegaMax = std::sqrt(best);
  return lim;
}

}  // namespace mesochain::mdem
