#!/usr/bin/env python3
"""k-point convergence of the (5,5) nanotube's 2-atom helical cell (examples/cnt55.toml).

The Mermin free energy per atom for N_kappa = 2, 4, 8, ... helical k-points at the ideal roll-up
geometry, and its change against the densest grid. Run from the build tree:

    PYTHONPATH=build/python /usr/bin/python3 examples/python/kpoint_convergence.py

(docs/python.md). Energies in Hartree, as the library computes them; eV beside them.
"""
import sys
from pathlib import Path

import mesochain as mc

here = Path(__file__).resolve().parent
base = mc.read_cell(str(here.parent / "cnt55.toml"))
symbols = base.cell.symbols
positions = base.cell.positions * mc.units.BOHR_IN_ANGSTROM  # Å, as the cell file takes them
translation = base.cell.translation * mc.units.BOHR_IN_ANGSTROM
twist = base.cell.twist / mc.units.DEGREE

grid = [2, 4, 8, 16, 32, 64, 128] if len(sys.argv) < 2 else [int(n) for n in sys.argv[1:]]
energies = []
for n in grid:
    inp = mc.make_input(symbols, positions, translation=translation, twist=twist,
                        rotation_order=base.cell.rotation_order, kpoints=n, temperature=300,
                        parameters="pbc-0-3")
    r = mc.Calculator(inp).evaluate(inp.cell, forces=False, strain=False)
    energies.append(r.free_energy / len(inp.cell))

print(f"{'N_kappa':>8} {'F per atom (Ha)':>20} {'F - F_densest (Ha/atom)':>24} {'(meV/atom)':>12}")
for n, f in zip(grid, energies):
    d = f - energies[-1]
    print(f"{n:>8d} {f:>20.12f} {d:>24.3e} {d * mc.units.HARTREE_IN_EV * 1e3:>12.4f}")
