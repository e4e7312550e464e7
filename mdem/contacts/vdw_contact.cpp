#include "mdem/contacts/vdw_contact.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <utility>


#include "mdem/contacts/vdw_kernel_isa.hpp"

namespace mesochain::mdem {

namespace {
// Early-out distance of the axis segments (segmentCutDistance): a quadrature point at distance
// rho from segment b evaluates cells whose node data come from rows within sqrt(5) steps of
// (h, u) (the cell corners and the central-difference slopes of H); beyond d_c those are all zero.
double farCut(const TubePairPotential& p) { return segmentCutDistance(p.cutoffDistance(), p.gridStep()); }

// The tolerance search stops here: against the 64-point reference, a larger rule is not checked.
constexpr int kMaxPoints = 48;

// Squared distance of the closest points of two axis segments from the scalars c = t_a.t_b,
// e = t_a.r0, f = t_b.r0, rr = |r0|^2 (r0 = x_a - x_b): the clamped alternation of closestPoints
// (contact_dashpot.hpp), |r0 + s t_a - u t_b|^2 expanded.
double closestDistance2(double c, double e, double f, double rr, double la, double lb) {
  const double sine2 = 1.0 - c * c;
  double s = sine2 > 1e-10 ? std::clamp((c * f - e) / sine2, -la, la)
                           : std::clamp(0.5 * (std::max(-e - lb, -la) + std::min(-e + lb, la)), -la, la);
  double u = std::clamp(f + s * c, -lb, lb);
  s = std::clamp(u * c - e, -la, la);
  u = std::clamp(f + s * c, -lb, lb);
  return std::max(0.0, rr + s * s + u * u + 2.0 * (s * e - u * f - s * u * c));
}

// E = sum_q w_q D(h_q, u0_q) along a, with rel_q = r0 + s_q t_a (r0 = x_a - x_b), u0 = rel . t_b,
// h = |rel - u0 t_b|. With dh/drel = (rel - u0 t_b)/h,
// dh/dt_b = -u0 rel/h, du0/drel = t_b, du0/dt_b = rel and alpha = D_h/h, beta = D_u0 - alpha u0:
//   dE/dr0 = sum w (alpha rel + beta t_b),  dE/dt_a = sum w s (alpha rel + beta t_b),
//   dE/dt_b = sum w beta rel,
// so the loop over the points carries five scalar sums and no vectors.
// `density(h, u0, &D_h, &D_u0)` returns D; points with h >= hCut or |u0| >= uCut add nothing.
template <class Density>
[[gnu::always_inline]] inline ContactPairResult segmentQuadrature(const QuadratureRule& rule, const Segment& a, const Segment& b, double hCut,
                                    double uCut, double farCutDistance, Density density) {
  ContactPairResult r;
  const Vec3 r0 = a.centre - b.centre;
  const Vec3 &ta = a.axis, &tb = b.axis;
  const double la = a.halfLength, lb = b.halfLength, rr = r0.squaredNorm();
  const double cut2 = farCutDistance * farCutDistance, reach = farCutDistance + la + lb;
  if (rr >= reach * reach) return r;  // centres too far apart for any two points to be within the cut
  const double c = ta.dot(tb), e = ta.dot(r0), f = tb.dot(r0);
  if (closestDistance2(c, e, f, rr, la, lb) >= cut2) return r;
  // h^2 = |r0_perp + s ta_perp|^2 with the parts normal to t_b formed once as vectors (no
  // cancellation between |rel|^2 and u0^2 when the axes nearly meet).
  const Vec3 r0Perp = r0 - f * tb, taPerp = ta - c * tb;
  const double hA = r0Perp.squaredNorm(), hB = 2.0 * r0Perp.dot(taPerp), hC = taPerp.squaredNorm();
  const double hCut2 = hCut * hCut;
  double energy = 0.0, sA = 0.0, sAs = 0.0, sB = 0.0, sBs = 0.0;
  const std::size_t n = rule.x.size();
  for (std::size_t q = 0; q < n; ++q) {
    const double s = la * rule.x[q], w = la * rule.w[q];
    const double u0 = f + s * c;
    const double h2 = hA + s * (hB + s * hC);
    if (h2 >= hCut2 || std::abs(u0) >= uCut) continue;
    // Beyond b's end: the point's distance from the segment is that from the end. At or beyond
    // the early-out distance every table cell its lookup touches has zero node data (as for the
    // whole pair above), so skipping it changes no bit of the sums.
    const double beyondEnd = std::abs(u0) - lb;
    if (beyondEnd > 0.0 && h2 + beyondEnd * beyondEnd >= cut2) continue;
    const double h = std::sqrt(std::max(h2, 0.0));
    double dh, du;
    const double d = density(h, u0, &dh, &du);
    const double alpha = h > 1e-12 ? dh / h : 0.0, beta = du - alpha * u0;
    energy += w * d;
    sA += w * alpha, sAs += (w * s) * alpha;
    sB += w * beta, sBs += (w * s) * beta;
  }
  r.energy = energy;
  const Vec3 gradR = sA * r0 + sAs * ta + sB * tb;
  r.forceA = -gradR;
  r.forceB = gradR;
  // torque = -t x dE/dt: the t_a part of dE/dt_a and the t_b part of dE/dt_b drop out.
  r.torqueA = -(sAs * ta.cross(r0) + sBs * ta.cross(tb));
  r.torqueB = -(sB * tb.cross(r0) + sBs * tb.cross(ta));
  return r;
}

[[gnu::always_inline]] inline ContactPairResult tableQuadratureBody(const SegmentLineTable& table,
                                                                     const QuadratureRule& rule, double farCutDistance,
                                                                     const Segment& a, const Segment& b) {
  return segmentQuadrature(rule, a, b, table.hCut(), table.uCut(), farCutDistance,
                           [&](double h, double u0, double* dh, double* du) {
                             const double d = table.eval(h, std::abs(u0), dh, du);  // D is even in u0
                             if (u0 < 0.0) *du = -*du;
                             return d;
                           });
}

// The kernel's loop compiled twice (vdw_kernel_isa.hpp): for the x86-64 baseline (SSE2), and for
// CPUs with AVX2, where the same SSE2 operations take their three-operand VEX forms (no register
// copies; no FMA, which -mavx2 does not imply), so both give the same results bit for bit.
ContactPairResult tableQuadratureBaseline(const SegmentLineTable& table, const QuadratureRule& rule,
                                          double farCutDistance, const Segment& a, const Segment& b) {
  return tableQuadratureBody(table, rule, farCutDistance, a, b);
}
#if MESOCHAIN_VDW_AVX2_CLONE
[[gnu::target("avx2")]] ContactPairResult tableQuadratureAvx2(const SegmentLineTable& table, const QuadratureRule& rule,
                                                              double farCutDistance, const Segment& a, const Segment& b) {
  return tableQuadratureBody(table, rule, farCutDistance, a, b);
}
const bool kCpuHasAvx2 = (__builtin_cpu_init(), __builtin_cpu_supports("avx2") != 0);
#else
constexpr bool kCpuHasAvx2 = false;
#endif
std::atomic<bool> baselineForced{false};

ContactPairResult tableQuadrature(const SegmentLineTable& table, const QuadratureRule& rule, double farCutDistance,
                                  const Segment& a, const Segment& b) {
#if MESOCHAIN_VDW_AVX2_CLONE
  if (kCpuHasAvx2 && !baselineForced.load(std::memory_order_relaxed))
    return tableQuadratureAvx2(table, rule, farCutDistance, a, b);
#endif
  return tableQuadratureBaseline(table, rule, farCutDistance, a, b);
}

// Weight 1 at v <= full, 0 at v >= zero: the quintic smoothstep (C2), and dweight/dv.
double ramp(double v, double full, double zero, double* derivative) {
  *derivative = 0.0;
  if (v <= full) return 1.0;
  if (v >= zero) return 0.0;
  const double t = (v - full) / (zero - full), t2 = t * t;
  *derivative = -30.0 * t2 * (1.0 - t) * (1.0 - t) / (zero - full);
  return 1.0 - t2 * t * (10.0 - 15.0 * t + 6.0 * t2);
}

// E = w E_aligned + (1 - w) E_rule with w = w(sin^2 theta) (AlignedWindow). Both energies are
// functions of the invariants rr = |r0|^2, e = t_a.r0, f = t_b.r0, c = t_a.t_b (the rule's through its
// own vector gradient), so the expansion's partials and the weight's are carried as
// dE/d(rr, e, f, c) and turned into forces and torques once:
//   dE/dr0 = 2 E_rr r0 + E_e t_a + E_f t_b,  dE/dt_a = E_e r0 + E_c t_b,  dE/dt_b = E_f r0 + E_c t_a.
// The tables vanish where the segments turned parallel would be farther apart than the early-out
// distance less la theta (enableAlignedPath), so a pair outside the neighbour list's reach gets
// exactly zero from both paths; and exactly parallel pairs all use the tables, whose sum along a
// straight chain is constant (no corrugation, as for the rule).
double angleWeight(const AnisotropicVdwKernel::AlignedWindow& win, double sine2, double* derivative) {
  return sine2 >= win.sine2Zero ? (*derivative = 0.0) : ramp(sine2, win.sine2Full, win.sine2Zero, derivative);
}

ContactPairResult alignedBlend(const AnisotropicVdwKernel& k, const Segment& a, const Segment& b, double farCutDistance) {
  const Vec3 &ta = a.axis, &tb = b.axis;
  const double c = ta.dot(tb), sine2 = 1.0 - c * c;
  double dwAngle;
  const double w = angleWeight(k.window, sine2, &dwAngle);
  if (w == 0.0) return tableQuadrature(k.table, k.rule, farCutDistance, a, b);
  const Vec3 r0 = a.centre - b.centre;
  const double f = tb.dot(r0);
  // The expansion's arguments (aligned_pair_table.hpp) and its partials by the invariants:
  // hA = rr - f^2, hB = 2 (e - f c), hC = 1 - c^2, Delta = sigma f, eps = sigma c - 1.
  const double sigma = c < 0.0 ? -1.0 : 1.0, e = ta.dot(r0), h0 = std::max((r0 - f * tb).norm(), 1e-12);
  const double hB = 2.0 * (e - f * c);
  const AlignedEnergy x = k.aligned->evaluate(h0, sigma * f, hB, sine2, sigma * c - 1.0);
  const double eHA = 0.5 * x.dH0 / h0;
  double gRR = eHA, gE = 2.0 * x.dHB, gF = -2.0 * f * eHA - 2.0 * c * x.dHB + sigma * x.dDelta;
  double gC = -2.0 * f * x.dHB - 2.0 * c * x.dHC + sigma * x.dEps;
  ContactPairResult r;
  r.energy = x.energy;
  if (w < 1.0) {
    const ContactPairResult q = tableQuadrature(k.table, k.rule, farCutDistance, a, b);
    const double gap = x.energy - q.energy, v = 1.0 - w;
    gRR *= w, gE *= w, gF *= w;
    gC = w * gC + gap * dwAngle * (-2.0 * c);  // d sin^2/d c = -2c
    r.energy = w * x.energy + v * q.energy;
    r.forceA = v * q.forceA, r.forceB = v * q.forceB, r.torqueA = v * q.torqueA, r.torqueB = v * q.torqueB;
  }
  const Vec3 gradR = 2.0 * gRR * r0 + gE * ta + gF * tb;
  r.forceA -= gradR;
  r.forceB += gradR;
  r.torqueA -= gE * ta.cross(r0) + gC * ta.cross(tb);
  r.torqueB -= gF * tb.cross(r0) + gC * tb.cross(ta);
  return r;
}

// E = w E_rule + (1 - w) E_crossing with w = w(sin^2 theta) (crossingWindow): the weight depends
// on c = t_a.t_b alone, so its gradient adds (E_rule - E_crossing) dw/dc to dE/dt_a (times t_b)
// and dE/dt_b (times t_a): torques only. `base` is the kernel's evaluation without the crossing
// rule (the aligned path or the rule); c = t_a.t_b.
template <class Base>
ContactPairResult crossingBlend(const AnisotropicVdwKernel& k, const Segment& a, const Segment& b, double farCutDistance,
                                double c, Base base) {
  double dw;
  const double w = ramp(1.0 - c * c, k.crossingWindow.sine2Full, k.crossingWindow.sine2Zero, &dw);
  if (w == 0.0) return tableQuadrature(k.table, k.crossingRule, farCutDistance, a, b);
  const ContactPairResult r = base();
  if (w == 1.0) return r;
  const ContactPairResult q = tableQuadrature(k.table, k.crossingRule, farCutDistance, a, b);
  const double v = 1.0 - w;
  const double gC = (r.energy - q.energy) * dw * (-2.0 * c);  // d sin^2/d c = -2c
  ContactPairResult out;
  out.energy = w * r.energy + v * q.energy;
  out.forceA = w * r.forceA + v * q.forceA, out.forceB = w * r.forceB + v * q.forceB;
  out.torqueA = w * r.torqueA + v * q.torqueA - gC * a.axis.cross(b.axis);
  out.torqueB = w * r.torqueB + v * q.torqueB - gC * b.axis.cross(a.axis);
  return out;
}
}  // namespace

ContactPairResult anisotropicVdw(const TubePairPotential& potential, const QuadratureRule& rule,
                                 const Segment& a, const Segment& b) {
  const double lb = b.halfLength, dc = potential.cutoffDistance();
  return segmentQuadrature(rule, a, b, dc, lb + dc, farCut(potential), [&](double h, double u0, double* dh, double* du) {
    // D = H(h, lo) - H(h, hi), lo = -lb - u0, hi = lb - u0 (d lo/d u0 = d hi/d u0 = -1).
    double hLo, uLo, hHi, uHi;
    const double d = potential.lineIntegral(h, -lb - u0, &hLo, &uLo) - potential.lineIntegral(h, lb - u0, &hHi, &uHi);
    *dh = hLo - hHi, *du = uHi - uLo;
    return d;
  });
}

AnisotropicVdwKernel::AnisotropicVdwKernel(const TubePairPotential& p, double halfLengthB, int quadraturePoints)
    : potential(&p), table(p, halfLengthB), rule(gaussLegendre(quadraturePoints)) {}

ContactPairResult anisotropicVdw(const AnisotropicVdwKernel& k, const Segment& a, const Segment& b) {
  if (b.halfLength != k.table.halfLength()) return anisotropicVdw(*k.potential, k.rule, a, b);
  const double cut = farCut(*k.potential);
  const auto base = [&] {
    if (k.aligned && a.halfLength == k.aligned->halfLengthA()) return alignedBlend(k, a, b, cut);
    return tableQuadrature(k.table, k.rule, cut, a, b);
  };
  if (!k.crossingRule.x.empty()) {
    const double c = a.axis.dot(b.axis);
    if (1.0 - c * c > k.crossingWindow.sine2Full) return crossingBlend(k, a, b, cut, c, base);
  }
  return base();
}

void AnisotropicVdwKernel::enableCrossingRule(int points) {
  crossingRule = points > 0 ? gaussLegendre(points) : QuadratureRule{};
  const double pi = 3.14159265358979323846, lo = kCrossingRampDegrees[0] * pi / 180.0, hi = kCrossingRampDegrees[1] * pi / 180.0;
  crossingWindow.sine2Full = std::sin(lo) * std::sin(lo);
  crossingWindow.sine2Zero = std::sin(hi) * std::sin(hi);
}

double alignedWeight(const AnisotropicVdwKernel& k, const Segment& a, const Segment& b) {
  if (!k.aligned || a.halfLength != k.aligned->halfLengthA() || b.halfLength != k.table.halfLength()) return 0.0;
  const double c = a.axis.dot(b.axis);
  double derivative;
  return angleWeight(k.window, 1.0 - c * c, &derivative);
}

void AnisotropicVdwKernel::enableAlignedPath(double la, double windowDegrees) {
  aligned.reset();
  if (windowDegrees <= 0.0) return;
  // At most the angle with la theta = 0.02 nm (1.15 degrees for 2-nm elements): beyond, the
  // expansion is far less accurate than the rule anyway (docs/mdem-contacts.md).
  const double theta = std::min(windowDegrees * 3.14159265358979323846 / 180.0, 0.02 / la);
  window.sine2Zero = std::sin(theta) * std::sin(theta);
  window.sine2Full = std::sin(0.5 * theta) * std::sin(0.5 * theta);
  // Turning a parallel to b about its centre moves its points by at most la theta: a pair whose
  // segments are beyond the early-out distance (and may be left out of the neighbour list) is
  // turned no closer than farCut - la theta, and the tables vanish beyond that less one cell
  // diagonal.
  const double step = table.step();
  aligned = std::make_shared<const AlignedPairTable>(table, la, farCut(*potential) - la * theta - std::sqrt(2.0) * step);
}

AnisotropicVdwKernel::AnisotropicVdwKernel(const TubePairPotential& p, double halfLengthA, double halfLengthB,
                                           double quadratureTolerance)
    : potential(&p), table(p, halfLengthB) {
  const QuadratureChoice c = quadraturePointsForTolerance(p, table, halfLengthA, quadratureTolerance);
  rule = gaussLegendre(c.points);
  sampledError = c.worstError;
}

QuadratureChoice quadraturePointsForTolerance(const TubePairPotential& potential, double la, double lb,
                                              double tolerance) {
  return quadraturePointsForTolerance(potential, SegmentLineTable(potential, lb), la, tolerance);
}

QuadratureChoice quadraturePointsForTolerance(const TubePairPotential& potential, const SegmentLineTable& table,
                                              double la, double tolerance) {
  const double lb = table.halfLength();
  const double cut = farCut(potential), scale = std::abs(potential.wellDepthPerLength()) * 2.0 * la;
  const double dEq = potential.equilibriumDistance(), pi = 3.14159265358979323846;
  // The sample: b crossing a (along x) at axis distance d (normal y), axis turned by t in the
  // x-z plane and tilted by psi towards a, shifted along a by xa and along its own axis by xb;
  // and b beyond a's end on a's line (end-on).
  std::vector<std::pair<Segment, Segment>> sample;
  const Segment a{Vec3::Zero(), Vec3::UnitX(), la};
  for (int deg = 0; deg <= 90; deg += 15)
    for (double psi : {0.0, 0.1})
      for (double gap : {-0.04, 0.0, 0.1, 0.3, 0.6})
        for (double xa : {0.0, 0.5, 1.0, 1.5})
          for (double xb : {0.0, 0.5, 1.0}) {
            const double t = deg * pi / 180.0;
            const Vec3 tb = Vec3(std::cos(t), std::sin(t) * std::sin(psi), std::sin(t) * std::cos(psi)).normalized();
            sample.emplace_back(a, Segment{Vec3(xa * la, dEq + gap, 0.0) + xb * lb * tb, tb, lb});
          }
  for (double end : {0.3, 0.6, 1.0}) sample.emplace_back(a, Segment{Vec3(la + end + lb, 0.0, 0.0), Vec3::UnitX(), lb});
  const QuadratureRule reference = gaussLegendre(64);
  std::vector<double> exact;
  for (const auto& [sa, sb] : sample) exact.push_back(tableQuadrature(table, reference, cut, sa, sb).energy);
  QuadratureChoice choice;
  for (int n = 2; n <= kMaxPoints; ++n) {
    const QuadratureRule rule = gaussLegendre(n);
    double worst = 0.0;
    for (std::size_t k = 0; k < sample.size(); ++k)
      worst = std::max(worst, std::abs(tableQuadrature(table, rule, cut, sample[k].first, sample[k].second).energy - exact[k]) /
                                  std::max(scale, std::abs(exact[k])));
    choice = {n, worst};
    if (choice.worstError <= tolerance) break;
  }
  return choice;
}

IsotropicVdw::IsotropicVdw(const TubePairPotential& potential, double la, double lb) {
  step_ = 0.005;
  rMax_ = potential.cutoffDistance();
  const int n = static_cast<int>(std::ceil(rMax_ / step_)) + 2;
  u_.assign(n, 0.0), du_.assign(n, 0.0);
  // U(r) = \int_{-la}^{la} ds [H(r, -lb - s) - H(r, lb - s)], composite Gauss-Legendre in s.
  const QuadratureRule gl = gaussLegendre(16);
  constexpr int kPanels = 16;
  for (int k = 0; k < n; ++k) {
    const double r = k * step_;
    double e = 0.0, de = 0.0;
    for (int p = 0; p < kPanels; ++p) {
      const double s0 = -la + 2.0 * la * p / kPanels, s1 = s0 + 2.0 * la / kPanels;
      for (std::size_t q = 0; q < gl.x.size(); ++q) {
        const double s = 0.5 * (s0 + s1) + 0.5 * (s1 - s0) * gl.x[q], w = 0.5 * (s1 - s0) * gl.w[q];
        double h0, u0, h1, u1;
        e += w * (potential.lineIntegral(r, -lb - s, &h0, &u0) - potential.lineIntegral(r, lb - s, &h1, &u1));
        de += w * (h0 - h1);
      }
    }
    u_[k] = e, du_[k] = de;
  }
}

double IsotropicVdw::energy(double r, double* derivative) const {
  if (r >= rMax_) return *derivative = 0.0, 0.0;
  const double x = r / step_;
  const int k = std::min(static_cast<int>(x), static_cast<int>(u_.size()) - 2);
  const double t = x - k, t2 = t * t, t3 = t2 * t;
  const double f0 = u_[k], f1 = u_[k + 1], m0 = du_[k] * step_, m1 = du_[k + 1] * step_;
  *derivative = ((6 * t2 - 6 * t) * f0 + (3 * t2 - 4 * t + 1) * m0 + (-6 * t2 + 6 * t) * f1 +
                 (3 * t2 - 2 * t) * m1) / step_;
  return (2 * t3 - 3 * t2 + 1) * f0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * f1 + (t3 - t2) * m1;
}

ContactPairResult IsotropicVdw::evaluate(const Vec3& centreA, const Vec3& centreB) const {
  ContactPairResult res;
  const Vec3 d = centreA - centreB;
  const double r = d.norm();
  if (r >= rMax_ || r < 1e-12) return res;
  double dU;
  res.energy = energy(r, &dU);
  res.forceA = -dU * d / r;
  res.forceB = -res.forceA;
  return res;
}

VdwKernelIsa vdwKernelIsa() {
  return kCpuHasAvx2 && !baselineForced.load(std::memory_order_relaxed) ? VdwKernelIsa::Avx2 : VdwKernelIsa::Baseline;
}

void forceBaselineVdwKernel(bool on) { baselineForced.store(on, std::memory_order_relaxed); }

}  // namespace mesochain::mdem
