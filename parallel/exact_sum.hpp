#pragma once
// parallel::ExactSum: sums of doubles that do not depend on the order of the terms, so that a
// sum split over threads and ranks in any way gives the same bits as the serial loop.
//
// Each term is cut once to a fixed-point grid of quantum 2^-90 (truncated toward zero; far
// below a double's resolution for the magnitudes summed here) and held as three 64-bit integer
// limbs of 40 bits (value = (l2 2^80 + l1 2^40 + l0) 2^-90); limbs are added as integers, which
// is exact and associative, with 23 bits of headroom per limb (up to 2^22 terms per element).
// This is the long-accumulator idea (Kulisch; cf. the reproducible summation of Demmel &
// Nguyen, IEEE Trans. Comput. 64, 2060 (2015)) in its simplest form. Terms must be finite and below 2^29 in
// magnitude; others are a NumericalError.
//
// Cost: a few flops per term, and 3 integers per element (Communicator::sumInPlace sums them
// over ranks).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mesochain::parallel {

class ExactSum {
 public:
  static constexpr int kMaxTermsPerElement = 1 << 22;

  ExactSum() = default;
  explicit ExactSum(std::size_t elements) { resize(elements); }
  void resize(std::size_t elements) { limbs_.assign(3 * elements, 0); }
  std::size_t size() const { return limbs_.size() / 3; }

  // Adds x[i] to element offset + i for i < count.
  void add(std::size_t offset, const double* x, std::size_t count);
  // Adds another accumulator of the same size (a thread's or a rank's partial sum).
  void add(const ExactSum& other);
  // The sums, rounded to doubles (deterministic: a function of the integer limbs alone).
  void values(double* out) const;
  double value(std::size_t element) const;

  std::vector<std::int64_t>& limbs() { return limbs_; }

 private:
  std::vector<std::int64_t> limbs_;  // element-major: 3 limbs per element, l0 l1 l2
};

}  // namespace mesochain::parallel
