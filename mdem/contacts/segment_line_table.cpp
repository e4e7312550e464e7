#include "mdem/contacts/segment_line_table.hpp"

#include <cmath>

namespace mesochain::mdem {

SegmentLineTable::SegmentLineTable(const TubePairPotential& potential, double halfLengthB)
    : halfLength_(halfLengthB), step_(potential.gridStep()) {
  const double dc = potential.cutoffDistance(), lb = halfLengthB;
  hCut_ = dc, uCut_ = lb + dc;
  const int nh = static_cast<int>(std::ceil(hCut_ / step_)) + 2;
  const int nu = static_cast<int>(std::ceil(uCut_ / step_)) + 2;
  table_ = BicubicTable(nh, nu, 0.0, 0.0, step_, step_);
  for (int i = 0; i < nh; ++i) {
    const double h = i * step_;
    for (int j = 0; j < nu; ++j) {
      const double u0 = j * step_;
      // D = H(h, lo) - H(h, hi) with lo = -lb - u0, hi = lb - u0 (d lo/d u0 = d hi/d u0 = -1).
      double loH, loU, loHU, hiH, hiU, hiHU;
      const double lo = potential.lineIntegral(h, -lb - u0, &loH, &loU, &loHU);
      const double hi = potential.lineIntegral(h, lb - u0, &hiH, &hiU, &hiHU);
      table_.set(i, j, lo - hi, loH - hiH, hiU - loU, hiHU - loHU);
    }
  }
}

}  // namespace mesochain::mdem
