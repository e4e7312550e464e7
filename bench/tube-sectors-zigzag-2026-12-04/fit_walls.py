#!/usr/bin/env python3
"""Sliding rigidity of N-wall zigzag sectors (C9; N = 1: the 4-atom C_n0 sector) from a series
over the inner index n0, beside the armchair result (../tube-sectors-2026-12-02/fit_walls.py).

Reads results.txt (N n0 atoms E_cell e_atom ...) and the relaxed walls z{N}-{n0}-relaxed.xyz
(atoms in wall order, inner first; wall k of (n0 + 9k, 0) holds 4 (n0 + 9k) / 9 atoms) and fits
per N

    e = e_inf + 1/2 D1_eff a_atom x,   x = sum_k n_k / R_k^2 / sum_k n_k

(every wall bends as a monolayer of its own radius R_k, the mean distance of its atoms from the
axis; n_k its atoms) with a_atom = 3 sqrt(3) b^2 / 4, b = T / 3 from the relaxed translation
(zigzag: T = sqrt(3) a = 3 b). With free sliding D1_eff is the monolayer's D1.

The zigzag step of 9 indices sets the walls 3.52 A apart before relaxation (the armchair step of 5:
3.39 A), so the relaxed spacing d (3.45-3.50 A) lies above the equilibrium and changes along the
series; for series of at least 4 radii the fit is repeated with the interlayer term of that
offset, e = e_inf + 1/2 D1 a_atom x + B (d - d0)^2, d the mean spacing and d0 = 3.408 A (the
armchair bilayer's relaxed spacing). Python 3, no packages.
"""
import importlib.util
import math
import os
import sys

HARTREE_EV = 27.211386245988

# read_xyz and fit_line are the armchair series' (one script, two families).
_here = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location(
    'armchair_fit_walls', os.path.join(_here, '..', 'tube-sectors-2026-12-02', 'fit_walls.py'))
_armchair = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(_armchair)
read_xyz, fit_line = _armchair.read_xyz, _armchair.fit_line


def wall_counts(N, n0, natoms):
    if N == 1:
        return [natoms]
    return [4 * (n0 + 9 * k) // 9 for k in range(N)]


def solve3(X, y):
    """Least squares of y ~ X (three columns, more than three rows) by the normal equations:
    the coefficients and their standard errors (sigma^2 (X^T X)^-1, sigma^2 = RSS / (n - 3))."""
    n = len(X)
    # Gauss-Jordan on [X^T X | X^T y | I]: the solution and the inverse together.
    A = [[sum(r[i] * r[j] for r in X) for j in range(3)] + [sum(r[i] * v for r, v in zip(X, y))]
         + [1.0 if k == i else 0.0 for k in range(3)] for i in range(3)]
    for i in range(3):
        A[i] = [a / A[i][i] for a in A[i]]
        for j in range(3):
            if j != i:
                f = A[j][i]
                A[j] = [a - f * b for a, b in zip(A[j], A[i])]
    sol = [A[i][3] for i in range(3)]
    rss = sum((v - sum(c * x for c, x in zip(sol, r))) ** 2 for r, v in zip(X, y))
    err = [math.sqrt(rss / (n - 3) * A[i][4 + i]) for i in range(3)]
    return sol, err


D0_SPACING = 3.408


def main(path='results.txt'):
    series = {}
    for line in open(path):
        p = line.split()
        if len(p) < 5 or not p[0].isdigit():
            continue
        N, n0, e = int(p[0]), int(p[1]), float(p[4])
        T, atoms = read_xyz(os.path.join(_here, f'z{N}-{n0}-relaxed.xyz'))
        counts = wall_counts(N, n0, len(atoms))
        assert sum(counts) == len(atoms), (N, n0, counts, len(atoms))
        radii, i = [], 0
        for c in counts:
            radii.append(sum(math.hypot(a[0], a[1]) for a in atoms[i:i + c]) / c)
            i += c
        x = sum(c / r ** 2 for c, r in zip(counts, radii)) / sum(counts)
        series.setdefault(N, []).append((n0, e, x, radii, T))
    for N, rows in sorted(series.items()):
        print(f'N = {N}: n0 = {[r[0] for r in rows]}, wall radii (A) = '
              f'{[[round(v, 3) for v in r[3]] for r in rows]}, T (A) = {[round(r[4], 5) for r in rows]}')
        if len(rows) < 2:
            print('   one radius only: no fit')
            continue
        b = rows[0][4] / 3
        a_atom = 3 * math.sqrt(3) / 4 * b * b
        s, _, se, mr = fit_line([r[2] for r in rows], [r[1] for r in rows])
        d1, err = 2 * s * HARTREE_EV / a_atom, 2 * se * HARTREE_EV / a_atom
        spacing = [sum(r[3][k + 1] - r[3][k] for k in range(N - 1)) / (N - 1) for r in rows] if N > 1 else []
        print(f'   D1_eff = {d1:.4f} +- {err:.4f} eV (max residual {mr * HARTREE_EV * 1e3:.4f} meV/atom);'
              f' sliding N D1_eff = {N * d1:.3f} eV'
              + (f'; wall spacing {min(spacing):.3f}-{max(spacing):.3f} A' if spacing else ''))
        if N > 1 and len(rows) >= 4:
            X = [[1.0, r[2], (d - D0_SPACING) ** 2] for r, d in zip(rows, spacing)]
            sol, err = solve3(X, [r[1] for r in rows])
            print(f'   with the spacing term: D1_eff = {2 * sol[1] * HARTREE_EV / a_atom:.4f}'
                  f' +- {2 * err[1] * HARTREE_EV / a_atom:.4f} eV,'
                  f' B = {sol[2] * HARTREE_EV:.4f} +- {err[2] * HARTREE_EV:.4f} eV/A^2 per atom')


if __name__ == '__main__':
    main(*sys.argv[1:])
