#pragma once
// From an element's settings to what the tables need: the free atom (on-site energies, U), the
// density-confined atom (density and potential for the superposition) and one
// wavefunction-confined atom per valence shell (the basis functions).
#include <string>
#include <vector>

#include "skgen/atom.hpp"
#include "skgen/atomic_data.hpp"
#include "skgen/elements.hpp"
#include "skgen/two_centre.hpp"

namespace mesochain::skgen {

struct ElementSettings {
  std::string symbol;
  XcKind xc = XcKind::Pbe;
  XcKind hubbardXc = XcKind::Pbe;  // functional of the U derivative (pbc-0-3 used LDA)
  Confinement density;
  std::vector<Confinement> shells;  // one per valence shell (order of Element::valence)
  SlaterBasis slater;  // non-empty: every atom of the element solved in this Slater basis
  double h = 0.004;
  double rMax = 40.0;
  std::string source = "<skgen>";  // file for error messages
};

struct ElementBasis {
  const Element* element = nullptr;
  AtomicData data;
  std::vector<TwoCentreOrbital> orbitals;  // valence shells in order s, p
  TwoCentreAtom atom;
};

ElementBasis buildElementBasis(const ElementSettings& s);

// The settings of the element's free (unconfined) atom with functional `xc`: ground-state
// occupations split equally over the spins, the element's basis and grid.
AtomSettings freeAtomSettings(const ElementSettings& s, XcKind xc);

// Fills b.data.spinConstants (W of the valence shells, skgen/atomic_data.hpp) and
// b.data.spinPolarisationEnergy from the free atom with the tables' functional s.xc. Separate
// from buildElementBasis because it solves 4 spin-polarised atoms per occupied valence shell.
void addSpinData(const ElementSettings& s, ElementBasis& b);

}  // namespace mesochain::skgen
