#pragma once
// Warm start of the SCC loop across evaluations (relaxation steps, scan points): the last
// converged charge excesses dq of a calculator, handed out as the first input of the next loop
// when the cell has the same atoms (count and species, in order). A small mutable object owned
// by the Calculator through a shared_ptr, so the parameters and settings stay immutable and a
// const evaluate() may update it; a mutex makes concurrent evaluations safe (each then starts
// from whichever converged charges were stored last, any of which is a valid start).
#include <mutex>
#include <optional>
#include <vector>

#include <Eigen/Dense>

namespace mesochain::dftb {

class ChargeCache {
 public:
  // The stored dq if `species` (per atom) equals that of the stored charges, else nothing.
  std::optional<Eigen::VectorXd> lookup(const std::vector<int>& species) const;
  // The same, without counting a hit or a miss (a driver passing charges on).
  std::optional<Eigen::VectorXd> stored(const std::vector<int>& species) const;
  void store(const std::vector<int>& species, const Eigen::VectorXd& dq);
  void clear();
  // Evaluations that found (hits) or did not find (misses) matching charges, and the SCC
  // iterations of all loops that consulted this cache (recordLoop), for reports and benchmarks.
  long hits() const;
  long misses() const;
  void recordLoop(int iterations);
  long iterations() const;

 private:
  mutable std::mutex mutex_;
  std::vector<int> species_;
  Eigen::VectorXd dq_;
  mutable long hits_ = 0, misses_ = 0;
  long iterations_ = 0;
};

}  // namespace mesochain::dftb
