#!/usr/bin/env python3
"""Sliding rigidity of N-wall armchair sectors (C5) from a series over the inner index n0.

Reads results.txt (N n0 atoms E_cell e_atom ...) and the relaxed walls s{N}-{n0}-relaxed.xyz
(here, or for N = 1, 2 in ../tube-sectors-2026-12-01/)
(atoms in wall order, inner first; wall k has 4 (n0 + 5k) / 5 atoms; N = 1 is the 4-atom
C_n0 sector), and fits per N

    e = e_inf + 1/2 D1_eff a_atom x,   x = sum_k n_k / R_k^2 / sum_k n_k

(every wall bends as a monolayer of its own radius R_k, the mean distance of its atoms from
the axis; n_k its atoms), a_atom = 3 sqrt(3) b^2 / 4 with b = T / sqrt(3) from the relaxed
translation T. With free sliding D1_eff is the monolayer's D1 and the stack's rigidity is
N D1_eff; the bonded plate bound is N D1 + Y2D / (1 - nu^2) sum_k z_k^2, z_k = (k - (N-1)/2) d
with d the mean measured wall spacing. Python 3, no packages.
"""
import math
import os
import sys

HARTREE_EV = 27.211386245988
Y2D_N_PER_M, NU = 387.1, 0.291          # the monolayer's in-plane constants (docs/filament-constants.md)
EV = 1.602176634e-19


def walls(N, n0, atoms):
    if N == 1:                      # the monolayer series is the 4-atom C_n0 sector
        return [len(atoms)]
    return [4 * (n0 + 5 * k) // 5 for k in range(N)]


def read_xyz(path):
    if not os.path.exists(path):                 # N = 1, 2: the series of 2026-12-01
        path = os.path.join('..', 'tube-sectors-2026-12-01', path)
    lines = open(path).read().split('\n')
    n = int(lines[0])
    T = float([t for t in lines[1].split() if t.startswith('mesochain:translation=')][0].split('=')[1])
    atoms = [list(map(float, l.split()[1:4])) for l in lines[2:2 + n]]
    return T, atoms


def fit_line(x, y):
    n = len(x)
    mx, my = sum(x) / n, sum(y) / n
    sxx = sum((a - mx) ** 2 for a in x)
    s = sum((a - mx) * (b - my) for a, b in zip(x, y)) / sxx
    c = my - s * mx
    res = [b - (c + s * a) for a, b in zip(x, y)]
    se = math.sqrt(sum(r * r for r in res) / (n - 2) / sxx) if n > 2 else float('nan')
    return s, c, se, max(abs(r) for r in res)


def main(path='results.txt'):
    series = {}
    for line in open(path):
        p = line.split()
        if len(p) < 5 or not p[0].isdigit():
            continue
        N, n0, e = int(p[0]), int(p[1]), float(p[4])
        T, atoms = read_xyz(f's{N}-{n0}-relaxed.xyz')
        counts, radii, i = walls(N, n0, atoms), [], 0
        for c in counts:
            radii.append(sum(math.hypot(a[0], a[1]) for a in atoms[i:i + c]) / c)
            i += c
        x = sum(c / r ** 2 for c, r in zip(counts, radii)) / sum(counts)
        series.setdefault(N, []).append((n0, e, x, radii, T))
    d1 = None
    for N, rows in sorted(series.items()):
        x = [r[2] for r in rows]
        y = [r[1] for r in rows]
        T = rows[0][4]
        b = T / math.sqrt(3)
        a_atom = 3 * math.sqrt(3) / 4 * b * b
        print(f'N = {N}: n0 = {[r[0] for r in rows]}, wall radii (A) = '
              f'{[[round(v, 3) for v in r[3]] for r in rows]}')
        if len(rows) < 2:
            print('   one radius only: no fit')
            continue
        s, c, se, mr = fit_line(x, y)
        D1_eff = 2 * s * HARTREE_EV / a_atom
        err = 2 * se * HARTREE_EV / a_atom
        if N == 1:
            d1 = D1_eff
        spacing = [sum(r[3][k + 1] - r[3][k] for k in range(N - 1)) / max(N - 1, 1) for r in rows]
        dmean = sum(spacing) / len(spacing) if N > 1 else 0.0
        sum_z2 = sum(((k - (N - 1) / 2) * dmean * 1e-10) ** 2 for k in range(N))
        bonded = N * (d1 if d1 else D1_eff) + Y2D_N_PER_M / (1 - NU ** 2) * sum_z2 / EV
        print(f'   D1_eff = {D1_eff:.4f} +- {err:.4f} eV (max residual {mr * HARTREE_EV * 1e3:.3f} meV/atom);'
              f' sliding N D1_eff = {N * D1_eff:.3f} eV; mean spacing {dmean:.3f} A;'
              f' bonded plate {bonded:.1f} eV; ratio {bonded / (N * D1_eff):.1f}')


if __name__ == '__main__':
    main(*sys.argv[1:])
