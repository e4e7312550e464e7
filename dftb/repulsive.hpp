#pragma once
// Repulsive pair potentials of a Slater-Koster table (DFTB+ .skf), Hartree and Bohr.
//
// Spline form (the "Spline" block at the end of an .skf file):
//   r < x_1:                 V = exp(-a1 r + a2) + a3
//   x_i <= r < x_{i+1}:      V = sum_{k=0..3} c_k (r - x_i)^k        (intervals 1 .. n-1)
//   x_n <= r < cutoff:       V = sum_{k=0..5} c_k (r - x_n)^k        (last interval, quintic)
//   r >= cutoff:             V = 0, with cutoff = end of the last interval.
// Polynomial form (on the mass line of the table):
//   V = sum_{i=2..9} c_i (rcut - r)^i for r < rcut, 0 beyond.
// Which form DFTB+ uses: the spline, unless the input asks for the polynomial for that pair
// (DFTB+ keyword Hamiltonian/PolynomialRepulsive, default none); with the default a table
// without a Spline block is an error in DFTB+ ("No spline repulsive found"), there is no
// automatic fallback to the polynomial (src/dftbp/dftbplus/parser.F90, readSKFiles, and
// src/dftbp/type/oldskdata.F90). The cutoff DFTB+ uses for the spline is the end of the last
// interval, not the number on the "nInt cutoff" line (oldskdata.F90, readSplineRep).
#include <array>
#include <vector>

#include "dftb/parameters.hpp"

namespace mesochain::dftb {

struct SplineRepulsiveData {
  double declaredCutoff = 0.0;             // second number of the "nInt cutoff" line
  std::array<double, 3> expHead{};         // a1, a2, a3
  std::vector<double> start, end;          // interval bounds (Bohr)
  std::vector<std::array<double, 6>> coeffs;  // c0..c5 (c4 = c5 = 0 except the last interval)
  double cutoff() const { return end.empty() ? 0.0 : end.back(); }
};

struct PolynomialRepulsiveData {
  std::array<double, 8> c{};  // c2 .. c9
  double cutoff = 0.0;        // rcut (Bohr)
};

class SplineRepulsive final : public RadialPotential {
 public:
  explicit SplineRepulsive(SplineRepulsiveData data);
  double cutoff() const override { return data_.cutoff(); }
  void evaluate(double r, double& value, double& derivative) const override;
  const SplineRepulsiveData& data() const { return data_; }

 private:
  SplineRepulsiveData data_;
};

class PolynomialRepulsive final : public RadialPotential {
 public:
  explicit PolynomialRepulsive(PolynomialRepulsiveData data) : data_(data) {}
  double cutoff() const override { return data_.cutoff; }
  void evaluate(double r, double& value, double& derivative) const override;

 private:
  PolynomialRepulsiveData data_;
};

}  // namespace mesochain::dftb
