#include "dftb/charge_mixer.hpp"

#include <algorithm>

#include "common/errors.hpp"

namespace mesochain::dftb {

void BroydenMixer::reset() {
  havePrevious_ = false;
  dF_.clear();
  u_.clear();
  w_.clear();
}

Eigen::VectorXd BroydenMixer::next(const Eigen::VectorXd& in, const Eigen::VectorXd& out) {
  const Eigen::VectorXd f = out - in;
  if (havePrevious_) {
    const Eigen::VectorXd df = f - previousF_;
    const double norm = df.norm();
    if (norm > 0) {
      dF_.push_back(df / norm);
      u_.push_back(alpha_ * dF_.back() + (in - previousIn_) / norm);
      const double fn = f.norm();
      w_.push_back(fn > 0 ? std::clamp(0.01 / fn, 1.0, 1e5) : 1e5);
    }
  }
  previousIn_ = in;
  previousF_ = f;
  havePrevious_ = true;
  Eigen::VectorXd next = in + alpha_ * f;
  const int m = static_cast<int>(dF_.size());
  if (m == 0) return next;
  const double w0 = 0.01;
  Eigen::MatrixXd a(m, m);
  Eigen::VectorXd c(m);
  for (int k = 0; k < m; ++k) {
    c[k] = w_[k] * dF_[k].dot(f);
    for (int l = 0; l < m; ++l) a(k, l) = w_[k] * w_[l] * dF_[k].dot(dF_[l]);
    a(k, k) += w0 * w0;
  }
  const Eigen::VectorXd g = a.ldlt().solve(c);  // gamma_l = sum_k c_k beta_kl (beta symmetric)
  for (int l = 0; l < m; ++l) next -= w_[l] * g[l] * u_[l];
  return next;
}

std::unique_ptr<ChargeMixer> makeChargeMixer(const std::string& name, double alpha) {
  if (!(alpha > 0.0 && alpha <= 1.0))
    throw InputError("the calculator settings", "scc.mixing", std::to_string(alpha), "a number in (0, 1]");
  if (name == "broyden") return std::make_unique<BroydenMixer>(alpha);
  if (name == "simple") return std::make_unique<SimpleMixer>(alpha);
  throw InputError("the calculator settings", "scc.mixer", "\"" + name + "\"", "\"broyden\" or \"simple\"");
}

}  // namespace mesochain::dftb
