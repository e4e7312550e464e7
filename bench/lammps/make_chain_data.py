#!/usr/bin/env python3
"""Writes a LAMMPS data file of bonded chains, the peer of `mesochain-bench dem`.

Usage: make_chain_data.py TOTAL_PARTICLES CHAIN_LENGTH OUTPUT.data

Chains of point particles (mass 1, spacing 1 along z) placed on a square grid of pitch 5 in x
and y like the filaments of `mesochain-bench dem`; bonds between consecutive particles of a
chain and angles between consecutive triples; small deterministic initial velocities.
"""
import math
import sys


def main():
    total, length, path = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    atoms, bonds, angles, velocities = [], [], [], []
    placed, chain = 0, 0
    while placed < total:
        count = min(length, total - placed)
        x, y = 5.0 * (chain % 100), 5.0 * (chain // 100)
        for k in range(count):
            i = placed + k + 1
            atoms.append(f"{i} {chain + 1} 1 {x:.6f} {y:.6f} {float(k):.6f}")
            velocities.append(f"{i} {0.01 * math.sin(1.3 * i):.8f} "
                              f"{0.01 * math.cos(0.7 * i):.8f} {0.01 * math.sin(0.3 * i):.8f}")
            if k > 0:
                bonds.append((i - 1, i))
            if k > 1:
                angles.append((i - 2, i - 1, i))
        placed += count
        chain += 1
    nx = 5.0 * min(chain, 100)
    ny = 5.0 * (chain // 100 + 1)
    with open(path, "w") as f:
        f.write("LAMMPS data file: bonded chains (mesochain bench/lammps)\n\n")
        f.write(f"{len(atoms)} atoms\n{len(bonds)} bonds\n{len(angles)} angles\n")
        f.write("1 atom types\n1 bond types\n1 angle types\n\n")
        f.write(f"-5.0 {nx + 5.0} xlo xhi\n-5.0 {ny + 5.0} ylo yhi\n-5.0 {length + 5.0} zlo zhi\n\n")
        f.write("Masses\n\n1 1.0\n\nAtoms # molecular\n\n")
        f.write("\n".join(atoms))
        f.write("\n\nVelocities\n\n")
        f.write("\n".join(velocities))
        f.write("\n\nBonds\n\n")
        f.write("\n".join(f"{n + 1} 1 {a} {b}" for n, (a, b) in enumerate(bonds)))
        f.write("\n\nAngles\n\n")
        f.write("\n".join(f"{n + 1} 1 {a} {b} {c}" for n, (a, b, c) in enumerate(angles)))
        f.write("\n")


if __name__ == "__main__":
    main()
