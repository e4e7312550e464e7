#!/usr/bin/env python3
"""A stretch scan of the (5,5) tube's 2-atom helical cell, fitted with the beam fitter.

Relaxes the reference (T0 at zero axial force), then each strain at fixed T = T0 (1 + strain),
and fits the stretching stiffness C of U(strain) = U0 + C strain^2 / 2 in the curve's quadratic
regime (docs/beam.md), as `mesochain scan` + `mesochain beam` do. Run from the build tree:

    PYTHONPATH=build/python /usr/bin/python3 examples/python/stretch_fit.py

Energies per slice of length T0 (Hartree); C also in eV and per unit length (docs/scan-file.md).
"""
from pathlib import Path

import mesochain as mc

here = Path(__file__).resolve().parent
inp = mc.read_cell(str(here.parent / "cnt55.toml"))
strains = [-0.01, -0.0075, -0.005, -0.0025, 0.0025, 0.005, 0.0075, 0.01]
result = mc.scan(inp, kind="stretch", values=strains, force_tolerance=1e-5)
curve = result.curve()
x = [p["deformation"] for p in curve["points"]]
u = [p["energy_hartree"] for p in curve["points"]]
fit = mc.fit_quadratic(x, u, quantity="C")

print(f"T0 = {result.translation0 * mc.units.BOHR_IN_ANGSTROM:.6f} Å, {result.cells_per_slice} cells per slice")
print(f"{'strain':>10} {'U - U0 (Ha per slice)':>24}")
for xi, ui in zip(x, u):
    print(f"{xi:>10.4f} {ui - fit.energy0:>24.6e}")
print(f"C = {fit.stiffness:.6f} ± {fit.uncertainty:.2e} Ha per slice "
      f"({fit.stiffness * mc.units.HARTREE_IN_EV:.4f} eV), window |strain| <= {fit.window_half_width}, "
      f"{fit.points_used} of {fit.points_total} points")
c_per_length = fit.stiffness * mc.units.HARTREE_IN_EV / (result.translation0 * mc.units.BOHR_IN_ANGSTROM)
print(f"C / T0 = {c_per_length:.4f} eV/Å (stretching stiffness, energy per length per strain^2)")
