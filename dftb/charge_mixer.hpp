#pragma once
// Charge mixers of the SCC loop: given the input charges q_in of an iteration and the output
// charges q_out they produced, propose the next input.
//  * SimpleMixer: q_next = q_in + alpha (q_out - q_in).
//  * BroydenMixer: the modified Broyden method of D. D. Johnson, Phys. Rev. B 38, 12807 (1988),
//    eqs. (13)-(15): with F = q_out - q_in and the normalised differences dF^k, dq^k of all
//    earlier iterations, u^k = alpha dF^k + dq^k, a_kl = w_k w_l dF^k.dF^l,
//    beta = (w0^2 + a)^-1, c_k = w_k dF^k.F, and
//      q_next = q_in + alpha F - sum_kl w_l c_k beta_kl u^l.
//    Weights w_k = clamp(0.01 / |F^k|, 1, 1e5) favour the later, smaller residuals; w0 = 0.01.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace mesochain::dftb {

class ChargeMixer {
 public:
  virtual ~ChargeMixer() = default;
  virtual std::string name() const = 0;
  virtual void reset() = 0;
  virtual Eigen::VectorXd next(const Eigen::VectorXd& in, const Eigen::VectorXd& out) = 0;
};

class SimpleMixer : public ChargeMixer {
 public:
  explicit SimpleMixer(double alpha) : alpha_(alpha) {}
  std::string name() const override { return "simple"; }
  void reset() override {}
  Eigen::VectorXd next(const Eigen::VectorXd& in, const Eigen::VectorXd& out) override {
    return in + alpha_ * (out - in);
  }

 private:
  double alpha_;
};

class BroydenMixer : public ChargeMixer {
 public:
  explicit BroydenMixer(double alpha) : alpha_(alpha) {}
  std::string name() const override { return "broyden"; }
  void reset() override;
  Eigen::VectorXd next(const Eigen::VectorXd& in, const Eigen::VectorXd& out) override;

 private:
  double alpha_;
  bool havePrevious_ = false;
  Eigen::VectorXd previousIn_, previousF_;
  std::vector<Eigen::VectorXd> dF_, u_;
  std::vector<double> w_;
};

// "broyden" or "simple"; alpha in (0, 1].
std::unique_ptr<ChargeMixer> makeChargeMixer(const std::string& name, double alpha);

}  // namespace mesochain::dftb
