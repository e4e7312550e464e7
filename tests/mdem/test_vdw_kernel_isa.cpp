// The table kernel's two compiled versions (vdw_kernel_isa.hpp): the x86-64 baseline and the AVX2
// one the CPU selects must give the same energies, forces and torques bit for bit, for even and
// odd rules, crossed and nearly parallel pairs, on the wall, in the well, in the tail and with
// Gauss points beyond the cuts.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "contact_fixture.hpp"
#include "mdem/contacts/vdw_kernel_isa.hpp"

namespace mesochain::mdem {
namespace {

using namespace testing;

constexpr double kHalf = 0.5 * kSegmentLength;

std::uint64_t bits(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

std::vector<double> flatten(const ContactPairResult& r) {
  std::vector<double> out{r.energy};
  for (const Vec3* v : {&r.forceA, &r.torqueA, &r.forceB, &r.torqueB}) out.insert(out.end(), v->data(), v->data() + 3);
  return out;
}

std::vector<std::pair<Segment, Segment>> pairGeometries() {
  const double d = tubePotential().equilibriumDistance();
  std::vector<std::pair<Segment, Segment>> out;
  const Segment a{Vec3(0.1, -0.2, 0.3), Vec3(1.0, 0.2, -0.1).normalized(), kHalf};
  const Vec3 n = a.axis.unitOrthogonal(), m = a.axis.cross(n);
  for (double theta : {0.0, 0.02, 0.4, 1.1, 1.5708, 2.9})
    for (double extra : {-0.04, 0.0013, 0.3, 1.0})
      for (double shift : {0.0, 1.3, 2.9}) {
        const Vec3 tb = (std::cos(theta) * a.axis + std::sin(theta) * (0.8 * m + 0.2 * n).normalized()).normalized();
        out.emplace_back(a, Segment{a.centre + (d + extra) * n + shift * a.axis, tb, kHalf});
      }
  return out;
}

TEST(MdemVdwKernelIsa, BaselineAndCpuVersionsAgreeBitForBit) {
  AnisotropicVdwKernel kernel(tubePotential(), kHalf, 8);
  forceBaselineVdwKernel(false);
  const VdwKernelIsa cpu = vdwKernelIsa();
  std::printf("the CPU's version of the table kernel: %s\n", cpu == VdwKernelIsa::Avx2 ? "AVX2" : "baseline");
  int interacting = 0;
  for (int points : {3, 7, 8, 12}) {
    kernel.rule = gaussLegendre(points);
    for (const auto& [a, b] : pairGeometries()) {
      const std::vector<double> fast = flatten(anisotropicVdw(kernel, a, b));
      forceBaselineVdwKernel(true);
      EXPECT_EQ(vdwKernelIsa(), VdwKernelIsa::Baseline);
      const std::vector<double> base = flatten(anisotropicVdw(kernel, a, b));
      forceBaselineVdwKernel(false);
      interacting += base[0] != 0.0;
      for (std::size_t k = 0; k < base.size(); ++k) ASSERT_EQ(bits(fast[k]), bits(base[k])) << points << " points, entry " << k;
    }
  }
  EXPECT_EQ(vdwKernelIsa(), cpu);
  EXPECT_GT(interacting, 150);  // the comparison is not among zeros
}

}  // namespace
}  // namespace mesochain::mdem
