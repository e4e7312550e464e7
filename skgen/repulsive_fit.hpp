#pragma once
// Repulsive potential of a pair from a reference dimer curve (e.g. from any DFT code):
//   E_rep(r) = [E_ref(r) − E_ref(r_c)] − [E_el(r) − E_el(r_c)],
// E_el the non-self-consistent DFTB electronic energy of the A-B dimer with the generated
// integrals (band energy Σ f ε, neutral atoms' valence electrons, degenerate levels filled
// equally), r_c the repulsive cutoff. The target is fitted by least squares with cubic
// B-splines on uniform knots over [r_min, r_c] (r_min the shortest reference distance), the
// three B-splines that do not vanish at r_c dropped, so E_rep, E_rep' and E_rep'' are zero at r_c
// (smooth cutoff). Written as the .skf spline block: the Taylor coefficients of every interval,
// the last interval in the block's fifth-order slot (c4 = c5 = 0), and the exponential head
// exp(−a1 r + a2) + a3 below r_min matching value, slope and curvature at r_min.
#include <string>
#include <vector>

#include "dftb/repulsive.hpp"
#include "skgen/element_basis.hpp"
#include "skgen/two_centre.hpp"

namespace mesochain::skgen {

struct DimerCurve {
  std::string source;  // file, for messages
  std::vector<double> r, energy;  // Bohr, Hartree; sorted by r
};

// CSV with the header "r_bohr,energy_hartree" and one pair per line; throws InputError naming
// the file and line for anything else (fewer than 4 points, unsorted or repeated distances).
DimerCurve readDimerCurve(const std::string& path);

// Non-SCC electronic energy of the dimer A at the origin, B at z = r.
double dimerElectronicEnergy(const ElementBasis& a, const ElementBasis& b, XcKind xc,
                             const TwoCentreQuadrature& q, double r);

// Least-squares spline through (r_i, y_i), r_i in [r_min, cutoff] (points beyond the cutoff are
// ignored), `intervals` uniform intervals. Throws InputError(source, key, ...) when there are
// too few points per interval or the fit is not repulsive at r_min (E' < 0 and E'' > 0 are
// needed for the exponential head).
dftb::SplineRepulsiveData fitRepulsiveSpline(const std::vector<double>& r,
                                             const std::vector<double>& y, double cutoff,
                                             int intervals, const std::string& source,
                                             const std::string& key);

// The whole fit for one pair: target from the curve and E_el, then the spline.
dftb::SplineRepulsiveData fitRepulsive(const ElementBasis& a, const ElementBasis& b, XcKind xc,
                                       const TwoCentreQuadrature& q, const DimerCurve& curve,
                                       double cutoff, int intervals, const std::string& key);

}  // namespace mesochain::skgen
