#pragma once
// The Kolmogorov-Crespi registry-dependent interlayer potential ("kolmogorov_crespi",
// registered in dispersion_kc.cpp; `[dispersion] model = "kc"`, instead of the Lennard-Jones
// term): A. N. Kolmogorov and V. H. Crespi, Phys. Rev. B 71, 235415 (2005):
//   E = 1/2 sum_{(i, j, g)} Tap(r) V_ij,      d = g(x_j) - x_i, r = |d|,
//   V_ij = e^{-lambda (r - z0)} [C + f(rho_ij) + f(rho_ji)] - A (z0 / r)^6,
//   rho_ij^2 = r^2 - (n_i . d)^2,  rho_ji^2 = r^2 - (n_j^g . d)^2,
//   f(rho) = e^{-(rho/delta)^2} sum_{k=0..2} C_2k (rho/delta)^2k,
// with n_i the local unit normal of atom i: the normal of the plane through its three bonded
// neighbours, n = (y2 - y1) x (y3 - y1) / |...| (its sign does not enter). The normal of an
// image is the cell atom's normal rotated by the image's group element, n_j^g = R(g) n_j (never
// recomputed from the image's positions); the normals' dependence on the neighbours' positions
// (and through their images on T and gamma) is in the gradient and the strain derivatives.
//
// Which pairs: the bond graph joins atoms (and images) closer than `bondCutoff`; a pair whose
// graph distance is at most kExcludedBondDistance = 3 bonds gets nothing from this term (the
// covalent neighbours are the band structure's), every other pair within the cutoff (farther
// apart in the graph, or not connected) gets V. No layer labels: the two faces of a collapsed
// tube are one sheet and still interact. Under the objective group the graph is invariant: the
// graph distance of (i, g(j)) is found once by a breadth-first search over images
// (i, zeta, c) from each cell atom, composing group elements (the group is abelian:
// g(zeta1, c1) g(zeta2, c2) = g(zeta1 + zeta2, c1 + c2 mod N_a)). In-sheet pairs more than 3
// bonds apart do interact (as every pair does in the Lennard-Jones term); f(rho) has decayed
// there (rho >= 3.7 Angstrom, e^{-41}), leaving the isotropic e^{-lambda r} C - A (z0/r)^6.
//
// Smooth cutoff: Tap(r) = 20 x^7 - 70 x^6 + 84 x^5 - 35 x^4 + 1 with x = (r - r_on)/(r_c - r_on)
// clamped to [0, 1] (Tap = 1 below r_on, 0 beyond r_c; value and first three derivatives
// continuous). r_on = 0 is the taper of Ouyang et al. (below), with which their parameters were
// fitted; the 2005 parameters were fitted without one, so their default switches only over the
// last shell [20, 25] Angstrom (dropping about 0.03 meV/atom of the r^-6 tail of a sheet).
//
// Every atom must have exactly three bonded neighbours (sp2 carbon): anything else is an
// InputError naming the atom, its neighbour count and the bond cutoff.
#include <memory>
#include <string>

#include "dftb/energy_term.hpp"

namespace mesochain::dftb {

// One parameter set, in atomic units (Hartree, Bohr).
struct KolmogorovCrespiParameters {
  std::string name;
  double z0 = 0, c0 = 0, c2 = 0, c4 = 0, c = 0, delta = 0, lambda = 0, a = 0;
  double cutoff = 0;       // r_c, Bohr
  double taperStart = 0;   // r_on, Bohr
  // Kolmogorov & Crespi 2005 (as distributed, citing it, in LAMMPS potentials/CC.KC): z0 = 3.34 A,
  // C0 = 15.71, C2 = 12.29, C4 = 4.933, C = 3.030 meV, delta = 0.578 A, lambda = 3.629 1/A,
  // A = 10.238 meV; default switch [20, 25] A.
  static KolmogorovCrespiParameters kc2005();
  // The refit of W. Ouyang, D. Mandelli, M. Urbakh and O. Hod, Nano Lett. 18, 6009 (2018),
  // for use with their taper at 16 A (LAMMPS's potentials/CH_taper.KC, C-C line):
  // z0 = 3.416084 A, C0 = 20.021583, C2 = 10.9055107, C4 = 4.2756354, C = 1.0010836e-2 meV,
  // delta = 0.8447122 A, lambda = 2.9360584 1/A, A = 14.3132588 meV; taper r_on = 0, r_c = 16 A.
  static KolmogorovCrespiParameters ouyang2018();
  // "kc2005" or "ouyang2018"; InputError (source, key) otherwise.
  static KolmogorovCrespiParameters byName(const std::string& name, const std::string& source,
                                           const std::string& key);
};

inline constexpr int kExcludedBondDistance = 3;  // bonds; pairs at most this far apart: no KC

struct KolmogorovCrespiSettings {
  bool enabled = false;
  std::string parameters = "kc2005";  // "kc2005" | "ouyang2018"
  double cutoff = 0.0;                // r_c, Bohr (0: the parameter set's)
  double taperStart = -1.0;           // r_on, Bohr, in [0, r_c) (< 0: the parameter set's)
  double bondCutoff = 0.0;            // Bohr: the bond graph's covalent cutoff (> 0)

  bool operator==(const KolmogorovCrespiSettings&) const = default;
};

// InputError (source "the calculator settings", the key) for values outside the ranges above.
void validate(const KolmogorovCrespiSettings& settings);
// The parameters the settings select, with their cutoff and taper start applied.
KolmogorovCrespiParameters resolvedParameters(const KolmogorovCrespiSettings& settings);

// Tap of the header comment and its derivative with respect to r.
void kcTaper(double r, double taperStart, double cutoff, double& value, double& derivative);

// V_ij of one pair (no taper) and its derivatives with respect to d, n_i and m = n_j^g, for
// unit normals n_i and m. Exposed for the tests.
struct KcPair {
  double v = 0.0;
  Eigen::Vector3d dd = Eigen::Vector3d::Zero(), dni = Eigen::Vector3d::Zero(),
                  dnj = Eigen::Vector3d::Zero();
};
KcPair kcPair(const KolmogorovCrespiParameters& p, const Eigen::Vector3d& d,
              const Eigen::Vector3d& ni, const Eigen::Vector3d& nj);

class KolmogorovCrespiTerm final : public EnergyTerm {
 public:
  KolmogorovCrespiTerm(KolmogorovCrespiParameters parameters, double bondCutoff);
  std::string name() const override { return "kolmogorov_crespi"; }
  void evaluate(const objective::ObjectiveCell& cell, const EvaluationRequest& request,
                TermOutput& out) const override;
  const KolmogorovCrespiParameters& parameters() const { return p_; }

 private:
  KolmogorovCrespiParameters p_;
  double bondCutoff_;
};

}  // namespace mesochain::dftb
