#include "dftb/charge_cache.hpp"

namespace mesochain::dftb {

std::optional<Eigen::VectorXd> ChargeCache::lookup(const std::vector<int>& species) const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (dq_.size() == 0 || species != species_) {
    ++misses_;
    return std::nullopt;
  }
  ++hits_;
  return dq_;
}

std::optional<Eigen::VectorXd> ChargeCache::stored(const std::vector<int>& species) const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (dq_.size() == 0 || species != species_) return std::nullopt;
  return dq_;
}

void ChargeCache::store(const std::vector<int>& species, const Eigen::VectorXd& dq) {
  std::lock_guard<std::mutex> lock(mutex_);
  species_ = species;
  dq_ = dq;
}

void ChargeCache::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  species_.clear();
  dq_.resize(0);
  hits_ = misses_ = iterations_ = 0;
}

long ChargeCache::hits() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return hits_;
}

long ChargeCache::misses() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return misses_;
}

void ChargeCache::recordLoop(int iterations) {
  std::lock_guard<std::mutex> lock(mutex_);
  iterations_ += iterations;
}

long ChargeCache::iterations() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return iterations_;
}

}  // namespace mesochain::dftb
