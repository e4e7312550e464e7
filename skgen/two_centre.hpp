#pragma once
// Two-centre Slater-Koster integrals of numerical atomic orbitals: overlap S and Hamiltonian H
// for every (l_a, l_b, m) with m <= min(l_a, l_b) (s and p: ss σ, sp σ, ps σ, pp σ, pp π).
//
// Geometry: atom A at the origin, atom B at z = d; orbitals real, quantised along A→B, so
// ⟨s_A|p_B σ⟩ < 0 at bonding distances (the .skf convention). Quadrature in prolate spheroidal
// coordinates ξ = (r_A + r_B)/d ∈ [1,∞), η = (r_A − r_B)/d ∈ [−1,1], dV = (d/2)³ (ξ² − η²) dξ dη dφ:
// the volume element cancels the nuclear 1/r and the orbital cusps are smooth in (ξ, η).
// Gauss-Legendre in η and in t with (d/2)(ξ − 1) = c (e^{αt} − 1), t ∈ [0,1] (points dense near
// the nuclei and sparse far out); the φ integral is done analytically (2π for σ, π for π).
//
// Hamiltonian with the density-superposition potential (Eschrig; Porezag et al. PRB 51, 12947):
//   H_ab = ⟨a| T + V_A + V_B + v_xc[n_A + n_B] |b⟩,   V_X = −Z_X/r_X + v_H[n_X],
// with T φ_b = (ε_b − v_b − v_conf,b) φ_b from the radial equation φ_b solves. GGA: the xc matrix
// element in the weak form ∫ (∂e/∂n) φ_a φ_b + 2 (∂e/∂σ) ∇n·∇(φ_a φ_b).
// Or with the potential superposition (Eschrig's other choice; e.g. Koskinen & Mäkinen, Comput.
// Mater. Sci. 47, 237 (2009)): H_ab = ⟨a| T + V_A + V_B + v_xc[n_A] + v_xc[n_B] |b⟩, each
// atom's own Kohn-Sham potential (radial, GGA in the strong form with its divergence term).
// Nuclear and Hartree parts are linear in the density, so the two differ only by the
// non-linearity of exchange-correlation (identical without it).
#include <vector>

#include "skgen/radial_grid.hpp"
#include "skgen/slater_basis.hpp"
#include "skgen/xc_functional.hpp"

namespace mesochain::skgen {

// A basis function R(r) Y_lm on an atom, with the radial equation it solves.
struct TwoCentreOrbital {
  int l = 0;
  double energy = 0.0;             // ε of the radial equation
  LogGrid grid;
  std::vector<double> radial;      // R(r) = u(r)/r
  std::vector<double> potential;   // v + v_conf the orbital was solved in (for T φ)
  // Slater back-end: R as a sum of Slater terms; then R, ∇R and T φ are evaluated analytically
  // (T φ = −½∇²φ, exact for a basis function that is not an exact eigenfunction of `potential`)
  // and grid/radial/potential are not used by the integrals.
  std::vector<SlaterTerm> slater;
};

// The density (and its neutral-atom potential) an atom contributes to the superposition.
struct TwoCentreAtom {
  double z = 0.0;
  LogGrid grid;
  std::vector<double> density;  // total spherical density n(r)
  std::vector<double> hartree;  // v_H[n](r)
  std::vector<double> xc;       // v_xc[n](r) of the atom's own density (potential superposition)
};

enum class Superposition { Density, Potential };

struct TwoCentreQuadrature {
  int nXi = 64;
  int nEta = 64;
  double rMax = 25.0;  // extent in (r_A + r_B − d)/2, Bohr
  double clustering = 0.2;  // c of the ξ map (Bohr)
  // (not a quadrature setting, but carried with it to every caller of the integrals)
  Superposition superposition = Superposition::Density;
};

struct SkIntegral {
  int la = 0, lb = 0, m = 0;  // shells on A and on B, |m| (0 σ, 1 π)
  int a = 0, b = 0;           // indices into the orbital lists
  double s = 0.0, h = 0.0;
};

// Overlap (and, when `atomA`/`atomB`/`xc` are given, Hamiltonian) integrals at distance d > 0.
std::vector<SkIntegral> twoCentreIntegrals(const std::vector<TwoCentreOrbital>& orbA,
                                           const std::vector<TwoCentreOrbital>& orbB,
                                           const TwoCentreAtom* atomA, const TwoCentreAtom* atomB,
                                           const XcFunctional* xc, double d,
                                           const TwoCentreQuadrature& q);

// Gauss-Legendre nodes and weights on [−1, 1].
void gaussLegendre(int n, std::vector<double>& x, std::vector<double>& w);

}  // namespace mesochain::skgen
