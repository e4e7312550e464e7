#pragma once
// Self-consistent Kohn-Sham solution of a spherical, non-relativistic atom on a logarithmic
// radial grid (the exact "numerical grid" back-end of the table generator).
//
// Each iteration: density -> Hartree potential (radial Poisson by cumulative integrals),
// exchange-correlation potential (libxc, with the GGA divergence term) -> radial states
// (Numerov, skgen/radial_schrodinger.hpp) -> output density; the input densities of the next
// iteration come from Anderson (Pulay) mixing of the last few input/output pairs.
// Total energy: E = Σ f ε − ∫ Σ_s n_s (v_s + v_conf) + E_nuc + E_H + E_xc (confinement energy
// not included).
#include <array>
#include <string>
#include <vector>

#include "skgen/confinement.hpp"
#include "skgen/radial_grid.hpp"
#include "skgen/slater_basis.hpp"
#include "skgen/xc_functional.hpp"

namespace mesochain::skgen {

struct AtomShell {
  int n = 1;
  int l = 0;
  std::array<double, 2> occupation{0.0, 0.0};  // spin up, down (unpolarised: their sum is used)
};

struct AtomSettings {
  std::string name = "atom";  // for messages
  double z = 1.0;
  std::vector<AtomShell> shells;
  XcKind xc = XcKind::LdaPw92;
  bool polarised = false;
  Confinement confinement;  // applied to every shell during this SCF run
  SlaterBasis slater;        // non-empty: Slater-type-function back-end, else the Numerov grid
  // grid
  double rMinTimesZ = 1e-6;  // r_min = rMinTimesZ / Z
  double rMax = 50.0;        // Bohr
  double h = 0.004;          // step in ln r
  // SCF
  double mixing = 0.4;
  int history = 6;
  double tolerance = 1e-9;  // density residual, sqrt(∫ (n_out − n_in)² d³r)
  int maxIterations = 200;
  // Electrons by which a shell may exceed its capacity (2l+1 per spin polarised, 2(2l+1)
  // unpolarised): the finite-difference occupation derivatives of full shells (He 1s, Ne 2p)
  // step just beyond it, along the smooth continuation of the Kohn-Sham equations (Janak).
  double overfill = 1e-12;
};

struct ShellSolution {
  int n = 1, l = 0;
  std::array<double, 2> occupation{};
  std::array<double, 2> energy{};            // per spin (unpolarised: both equal)
  std::array<std::vector<double>, 2> u{};    // u = r R, per spin
  std::array<std::vector<SlaterTerm>, 2> terms{};  // Slater back-end: R as Slater terms, per spin
};

struct AtomEnergies {
  double total = 0.0, kinetic = 0.0, hartree = 0.0, nuclear = 0.0, xc = 0.0, confinement = 0.0;
};

struct AtomSolution {
  LogGrid grid;
  int spins = 1;
  std::vector<ShellSolution> shells;
  std::vector<std::vector<double>> density;    // per spin (unpolarised: total), electrons/bohr³
  std::vector<std::vector<double>> potential;  // v_nuc + v_H + v_xc per spin, no confinement
  std::vector<double> hartree;                 // v_H
  std::vector<std::vector<double>> xc;         // v_xc per spin (GGA: with the divergence term)
  AtomEnergies energies;
  int iterations = 0;
  double residual = 0.0;

  // Total density (sum over spins).
  std::vector<double> totalDensity() const;
  const ShellSolution& shell(int n, int l) const;
};

// Throws NumericalError naming the atom when the SCF does not converge in maxIterations (with
// the last residual), InputError for inconsistent settings (no electrons, l >= n, a confinement
// that pushes an occupied level to or above zero is reported by `requireBound`).
AtomSolution solveAtom(const AtomSettings& s);

// Throws InputError(source, key, ...) when the state (n, l) of `atom`, solved under
// `confinement`, is not bound by the atom: its level lies above the confining potential at r0
// (1 Ha for (r/r0)^n), i.e. the confinement, not the nucleus, holds the electron — the
// confinement radius is too small for a bound state. (Confined valence levels may be above
// zero: carbon 2s under (r/2.7)^2 is at +0.06 Ha.)
void requireBound(const AtomSolution& atom, const Confinement& confinement, int n, int l,
                  const std::string& source, const std::string& key);

}  // namespace mesochain::skgen
