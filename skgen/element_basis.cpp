#include "skgen/element_basis.hpp"

#include <fmt/format.h>

#include "common/errors.hpp"

namespace mesochain::skgen {

namespace {
AtomSettings atomSettings(const Element& e, const ElementSettings& s, XcKind xc,
                          const Confinement& c) {
  AtomSettings a;
  a.name = s.symbol;
  a.z = e.z;
  for (const auto& sh : e.shells)
    a.shells.push_back({sh.n, sh.l, {0.5 * sh.occupation, 0.5 * sh.occupation}});
  a.xc = xc;
  a.confinement = c;
  a.slater = s.slater;
  a.h = s.h;
  a.rMax = s.rMax;
  return a;
}
}  // namespace

AtomSettings freeAtomSettings(const ElementSettings& s, XcKind xc) {
  return atomSettings(findElement(s.symbol, s.source, "element"), s, xc, Confinement::none());
}

void addSpinData(const ElementSettings& s, ElementBasis& b) {
  const Element& e = findElement(s.symbol, s.source, "element");
  AtomSettings free = freeAtomSettings(s, s.xc);
  free.tolerance = 1e-10;
  b.data.spinConstants = occupationDerivatives(free, e.valence).w;
  b.data.spinPolarisationEnergy = spinPolarisationEnergy(free);
}

ElementBasis buildElementBasis(const ElementSettings& s) {
  ElementBasis b;
  b.element = &findElement(s.symbol, s.source, "element");
  const Element& e = *b.element;
  if (s.shells.size() != e.valence.size()) {
    throw InputError(s.source, s.symbol + ".shells", fmt::format("{} confinements", s.shells.size()),
                     fmt::format("one per valence shell ({})", e.valence.size()));
  }
  // free atom: on-site energies, occupations, U of the highest occupied valence shell
  const AtomSettings freeSet = atomSettings(e, s, s.xc, Confinement::none());
  const AtomSolution free = solveAtom(freeSet);
  int homo = -1;
  for (std::size_t k = 0; k < e.valence.size(); ++k) {
    const ShellOccupation& sh = e.shells[e.valence[k]];
    b.data.onsite[sh.l] = free.shell(sh.n, sh.l).energy[0];
    b.data.occupation[sh.l] = sh.occupation;
    if (sh.occupation > 0) homo = e.valence[k];
  }
  AtomSettings uSet = atomSettings(e, s, s.hubbardXc, Confinement::none());
  uSet.tolerance = 1e-10;
  const double u = hubbardU(uSet, e.shells[homo].n, e.shells[homo].l);
  for (std::size_t k = 0; k < e.valence.size(); ++k) b.data.hubbard[e.shells[e.valence[k]].l] = u;

  // density-confined atom
  const AtomSolution dens = solveAtom(atomSettings(e, s, s.xc, s.density));
  b.atom.z = e.z;
  b.atom.grid = dens.grid;
  b.atom.density = dens.totalDensity();
  b.atom.hartree = dens.hartree;
  b.atom.xc = dens.xc[0];

  // one wavefunction-confined atom per valence shell
  for (std::size_t k = 0; k < e.valence.size(); ++k) {
    const ShellOccupation& sh = e.shells[e.valence[k]];
    const AtomSolution wf = solveAtom(atomSettings(e, s, s.xc, s.shells[k]));
    requireBound(wf, s.shells[k], sh.n, sh.l, s.source, fmt::format("elements.{}.wavefunction (shell {}{})", s.symbol,
                                                       sh.n, "spdf"[sh.l]));
    TwoCentreOrbital o;
    o.l = sh.l;
    const ShellSolution& ss = wf.shell(sh.n, sh.l);
    o.energy = ss.energy[0];
    o.slater = ss.terms[0];
    o.grid = wf.grid;
    o.radial.resize(wf.grid.size());
    o.potential.resize(wf.grid.size());
    for (int i = 0; i < wf.grid.size(); ++i) {
      o.radial[i] = ss.u[0][i] / wf.grid.r[i];
      o.potential[i] = wf.potential[0][i] + s.shells[k](wf.grid.r[i]);
    }
    b.orbitals.push_back(std::move(o));
  }
  return b;
}

}  // namespace mesochain::skgen
