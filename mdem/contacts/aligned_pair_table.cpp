#include "mdem/contacts/aligned_pair_table.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace mesochain::mdem {

namespace {
// Prefix integrals along one table row h: C_k(u) = \int_{-U}^{u} v^k F(v) dv for the row functions
// F of `RowSample`, exact for the cubic rows of the D interpolant times v^2 (3-point Gauss-Legendre
// per grid cell, degree 5).
struct RowPrefix {
  static constexpr int kFunctions = 3;  // D, D_h, g_x = D_h / (2 h)
  static constexpr int kPowers = 3;     // v^0, v^1, v^2
  const SegmentLineTable* table = nullptr;
  double h = 0.0, gxScale = 0.0, step = 0.0, u0 = 0.0;  // u0 = -U
  int cells = 0;
  std::vector<double> prefix;  // (cells + 1) x kFunctions x kPowers

  void sample(double v, double w, double* acc) const {
    double dh, du;
    const double d = table->eval(h, std::abs(v), &dh, &du);  // D is even in u
    const double f[kFunctions] = {d, dh, dh * gxScale};
    for (int a = 0; a < kFunctions; ++a) {
      double p = w * f[a];
      for (int k = 0; k < kPowers; ++k, p *= v) acc[a * kPowers + k] += p;
    }
  }
  // Adds the integral over [lo, hi] (inside one cell) to acc.
  void cellIntegral(double lo, double hi, double* acc) const {
    static const double x[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)};
    static const double w[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    for (int q = 0; q < 3; ++q) sample(lo + (hi - lo) * x[q], (hi - lo) * w[q], acc);
  }
  void build(const SegmentLineTable& t, double rowH, double gxH, double halfRange) {
    table = &t, h = rowH, gxScale = 0.5 / gxH, step = t.step();
    cells = 2 * static_cast<int>(std::ceil(halfRange / step));
    u0 = -0.5 * cells * step;
    prefix.assign(static_cast<std::size_t>(cells + 1) * kFunctions * kPowers, 0.0);
    for (int m = 0; m < cells; ++m) {
      double* next = &prefix[(m + 1) * kFunctions * kPowers];
      for (int k = 0; k < kFunctions * kPowers; ++k) next[k] = next[k - kFunctions * kPowers];
      cellIntegral(u0 + m * step, u0 + (m + 1) * step, next);
    }
  }
  // All C_k(u), u inside [-U, U].
  std::array<double, kFunctions * kPowers> at(double u) const {
    const int m = std::clamp(static_cast<int>(std::floor((u - u0) / step)), 0, cells - 1);
    std::array<double, kFunctions * kPowers> c;
    for (int k = 0; k < kFunctions * kPowers; ++k) c[k] = prefix[m * kFunctions * kPowers + k];
    const double lo = u0 + m * step;
    if (u > lo) cellIntegral(lo, u, c.data());
    return c;
  }
};

enum Fn { kG0, kK1, kK2, kK3, kG4, kFnCount };
}  // namespace

AlignedPairTable::AlignedPairTable(const SegmentLineTable& d, double la, double zeroBeyond) : la_(la) {
  const double step = d.step();
  // Rows and columns reach a few steps past the support of D (h < d_c, |u0| < lb + d_c) so that the
  // last two of each carry zero node data: beyond them every table is exactly zero.
  const int nh = static_cast<int>(std::ceil(d.hCut() / step)) + 6;
  const int nd = static_cast<int>(std::ceil((la + d.uCut()) / step)) + 6;
  hMax_ = (nh - 1) * step, deltaMax_ = (nd - 1) * step;
  // Node values on rows -1..nh and columns -1..nd (the extra ones for central differences).
  const int rows = nh + 2, cols = nd + 2;
  auto at = [cols](int i, int j) { return static_cast<std::size_t>(i + 1) * cols + (j + 1); };
  std::vector<std::array<double, kFnCount>> value(static_cast<std::size_t>(rows) * cols);
  std::vector<std::array<double, 3>> g0Slopes(value.size());  // exact dG0/dh, dG0/dDelta, cross
  RowPrefix row;
  for (int i = 0; i <= nh; ++i) {
    // Row 0 (h = 0): g_x = D_h / 2h has the limit D_hh / 2; the values of row 1 stand in for it.
    const double h = i * step, gxH = std::max(h, step);
    row.build(d, i == 0 ? step : h, gxH, deltaMax_ + 2 * step + la + 2 * step);
    RowPrefix exactRow;  // G0 and G4 on row 0 itself (no division there)
    if (i == 0) exactRow.build(d, 0.0, step, deltaMax_ + 2 * step + la + 2 * step);
    for (int j = -1; j <= nd; ++j) {
      const double delta = j * step;
      const auto hi = row.at(delta + la), lo = row.at(delta - la);
      auto diff = [&](int fn, int k) { return hi[fn * 3 + k] - lo[fn * 3 + k]; };
      std::array<double, kFnCount>& v = value[at(i, j)];
      // \int (u - Delta)^k F du from the prefix sums of u^k F.
      v[kK1] = diff(2, 1) - delta * diff(2, 0);
      v[kK2] = diff(2, 2) - 2.0 * delta * diff(2, 1) + delta * delta * diff(2, 0);
      const auto &eh = i == 0 ? exactRow.at(delta + la) : hi, &el = i == 0 ? exactRow.at(delta - la) : lo;
      v[kG0] = eh[0] - el[0];
      double dhP, duP, dhM, duM;
      const double dPlus = d.eval(h, std::abs(delta + la), &dhP, &duP);
      const double dMinus = d.eval(h, std::abs(delta - la), &dhM, &duM);
      v[kG4] = la * (dPlus + dMinus) - v[kG0];
      g0Slopes[at(i, j)] = {eh[3] - el[3], dPlus - dMinus, dhP - dhM};
      v[kK3] = 0.0;
    }
  }
  // K3 = dK2/dx = (dK2/dh) / 2h by central differences across rows (row 0 takes row 1's).
  for (int i = 1; i < nh; ++i)
    for (int j = -1; j <= nd; ++j)
      value[at(i, j)][kK3] = (value[at(i + 1, j)][kK2] - value[at(i - 1, j)][kK2]) / (4.0 * step * i * step);
  for (int j = -1; j <= nd; ++j) value[at(0, j)][kK3] = value[at(1, j)][kK3];
  // Every function is even in h: row -1 mirrors row 1.
  for (int j = -1; j <= nd; ++j) value[at(-1, j)] = value[at(1, j)];

  step_ = step, invStep_ = 1.0 / step, nh_ = nh, nd_ = nd;
  data_.assign(static_cast<std::size_t>(nh) * nd * kTables * 4, 0.0);
  const double reach = la + d.halfLength();
  for (int i = 0; i < nh; ++i)
    for (int j = 0; j < nd; ++j) {
      const double beyond = std::max(j * step - reach, 0.0);
      if (std::hypot(i * step, beyond) >= zeroBeyond) continue;  // node data stay zero
      const std::array<double, 3>& s0 = g0Slopes[at(i, j)];
      set(kG0, i, j, value[at(i, j)][kG0], s0[0], s0[1], s0[2]);
      for (int fn = kK1; fn < kFnCount; ++fn) {
        auto v = [&](int a, int b) { return value[at(a, b)][fn]; };
        set(fn, i, j, v(i, j), (v(i + 1, j) - v(i - 1, j)) / (2 * step), (v(i, j + 1) - v(i, j - 1)) / (2 * step),
            (v(i + 1, j + 1) - v(i + 1, j - 1) - v(i - 1, j + 1) + v(i - 1, j - 1)) / (4 * step * step));
      }
    }
}

void AlignedPairTable::set(int table, int i, int j, double f, double fh, double fd, double fhd) {
  double* p = &data_[(static_cast<std::size_t>(i) * nd_ + j) * kTables * 4 + 4 * table];
  p[0] = f, p[1] = fh * step_, p[2] = fd * step_, p[3] = fhd * step_ * step_;
}

AlignedEnergy AlignedPairTable::evaluate(double h0, double delta, double hB, double hC, double eps) const {
  // Tables over |Delta|: G0, K2, K3, G4 are even in Delta, K1 is odd.
  const double a = std::abs(delta), sg = delta < 0.0 ? -1.0 : 1.0;
  AlignedEnergy e;
  if (h0 >= hMax_ || a >= deltaMax_) return e;  // every table is zero there
  // The cubic Hermite basis in both directions (as BicubicTable::eval): b = values, d = slopes.
  double t = h0 * invStep_, s = a * invStep_;
  const int i = std::min(static_cast<int>(t), nh_ - 2), j = std::min(static_cast<int>(s), nd_ - 2);
  t -= i, s -= j;
  const double tm = t - 1.0, sm = s - 1.0, t2 = t * t, s2 = s * s;
  const double b1t = t2 * (3.0 - 2.0 * t), b2t = t * tm * tm, b3t = t2 * tm, b0t = 1.0 - b1t;
  const double d1t = -6.0 * t * tm, d2t = tm * (3.0 * t - 1.0), d3t = t * (3.0 * t - 2.0);
  const double b1s = s2 * (3.0 - 2.0 * s), b2s = s * sm * sm, b3s = s2 * sm, b0s = 1.0 - b1s;
  const double d1s = -6.0 * s * sm, d2s = sm * (3.0 * s - 1.0), d3s = s * (3.0 * s - 2.0);
  constexpr int kNode = kTables * 4;
  const double* row0 = &data_[(static_cast<std::size_t>(i) * nd_ + j) * kNode];
  const double* row1 = row0 + static_cast<std::size_t>(nd_) * kNode;
  double f[kTables], fh[kTables], fa[kTables];
  for (int k = 0; k < kTables; ++k) {
    // Along Delta on the rows i and i + 1 (nodes j, j + 1): value part and h-slope part, each with
    // its Delta-derivative.
    const double *p = row0 + 4 * k, *q = row1 + 4 * k, *pn = p + kNode, *qn = q + kNode;
    const double vp = p[0] * b0s + pn[0] * b1s + p[2] * b2s + pn[2] * b3s;
    const double xp = p[1] * b0s + pn[1] * b1s + p[3] * b2s + pn[3] * b3s;
    const double vq = q[0] * b0s + qn[0] * b1s + q[2] * b2s + qn[2] * b3s;
    const double xq = q[1] * b0s + qn[1] * b1s + q[3] * b2s + qn[3] * b3s;
    const double vpS = (pn[0] - p[0]) * d1s + p[2] * d2s + pn[2] * d3s;
    const double xpS = (pn[1] - p[1]) * d1s + p[3] * d2s + pn[3] * d3s;
    const double vqS = (qn[0] - q[0]) * d1s + q[2] * d2s + qn[2] * d3s;
    const double xqS = (qn[1] - q[1]) * d1s + q[3] * d2s + qn[3] * d3s;
    fh[k] = ((vq - vp) * d1t + xp * d2t + xq * d3t) * invStep_;
    fa[k] = (vpS * b0t + vqS * b1t + xpS * b2t + xqS * b3t) * invStep_;
    f[k] = vp * b0t + vq * b1t + xp * b2t + xq * b3t;
  }
  const double k1 = sg * f[kK1], hB2 = 0.5 * hB * hB;
  e.energy = f[kG0] + hB * k1 + hC * f[kK2] + hB2 * f[kK3] + eps * f[kG4];
  e.dH0 = fh[kG0] + sg * hB * fh[kK1] + hC * fh[kK2] + hB2 * fh[kK3] + eps * fh[kG4];
  e.dDelta = sg * (fa[kG0] + hC * fa[kK2] + hB2 * fa[kK3] + eps * fa[kG4]) + hB * fa[kK1];
  e.dHB = k1 + hB * f[kK3], e.dHC = f[kK2], e.dEps = f[kG4];
  return e;
}

}  // namespace mesochain::mdem
