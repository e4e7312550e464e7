#pragma once
// Axis tick placement: linear axes on the 1-2-5 rule (steps of 1, 2 or 5 times a power of ten,
// the axis widened to whole steps), log10 axes on whole decades; tick labels.
#include <string>
#include <vector>

namespace mesochain::plot {

struct AxisTicks {
  double lo = 0.0, hi = 1.0;         // axis range in data units (always lo < hi)
  std::vector<double> major;         // in data units, ascending, within [lo, hi]
  std::vector<std::string> labels;   // one per major tick (may carry ^{...} markup)
  std::vector<double> minor;         // unlabelled ticks
};

// Smallest number of the form {1, 2, 5} x 10^k that is >= raw (raw > 0).
double niceStep(double raw);

// Linear axis over [dataMin, dataMax] with about `target` intervals. An empty range is widened
// around its value (by 10% of it, or by 1 around zero).
AxisTicks linearTicks(double dataMin, double dataMax, int target);

// Log10 axis over [dataMin, dataMax] (both > 0): the data range widened by 5% of its span in
// decades, or, when that would show fewer than two powers of ten, whole decades around the data.
// Labels 10^{k} at every decade (every 2nd, 5th, ... when there are more than `target`), minor
// ticks at 2..9 x 10^k when every decade is labelled.
AxisTicks logTicks(double dataMin, double dataMax, int target);

// Label of a linear tick `value` on an axis whose step is `step`: enough significant digits to
// tell neighbours apart, exponents written like 1.5e-5; an exact 0 for values within
// rounding of zero.
std::string formatTick(double value, double step);

}  // namespace mesochain::plot
