#pragma once
// Exponentially scaled modified Bessel functions of the first kind, Ie_l(x) = exp(-x) I_l(x),
// for all integer orders l = 0..lmax at one argument x >= 0 (docs/ewald.md, eq. (E9)).
//
// Miller's backward recurrence I_{l-1} = I_{l+1} + (2l/x) I_l (stable downwards), normalised by
// the exact sum rule exp(-x) [I_0 + 2 sum_{l>=1} I_l] = 1 (all terms positive: no cancellation).
// Works for any order and argument (no overflow: running rescaling), unlike std::cyl_bessel_i
// whose unscaled values overflow for x > ~700.
#include <vector>

namespace mesochain::ewald {

// Fills out[0..lmax] with Ie_l(x). x must be >= 0 and finite.
void scaledBesselISequence(double x, int lmax, std::vector<double>& out);

}  // namespace mesochain::ewald
