#!/bin/bash
# Builds and relaxes N-wall armchair sectors (C5), e.g. `./run.sh 3-15 3-20 4-15` (N-n0):
# `mesochain build tube-sector --family armchair --inner n0 --walls N --kpoints 48 --task relax`,
# LJ dispersion switched on, then `mesochain run` on one thread; appends a row to results.txt
# (N n0 atoms F_cell F_atom, the relaxation line, wall seconds). Then `python3 fit_walls.py`.
M=${M:-../../build/mesochain}
for spec in "$@"; do
  N=${spec%-*}; n0=${spec#*-}; f=s$N-$n0.toml
  $M build tube-sector --family armchair --inner $n0 --walls $N --kpoints 48 --task relax -o $f > /dev/null
  sed -i '/^\[dispersion\]$/{n;s/^model = "none"$/model = "lj"/}' $f
  start=$(date +%s.%N)
  OMP_NUM_THREADS=1 $M run $f --json ${f%.toml}.json > ${f%.toml}.log 2>&1
  end=$(date +%s.%N)
  echo "$N $n0 $(grep -m1 'cell:' ${f%.toml}.log | awk '{print $2}') $(grep 'Mermin free energy' ${f%.toml}.log | awk '{print $4, $5}') $(grep -m1 'relaxation:' ${f%.toml}.log) $(echo "$end - $start" | bc)" >> results.txt
done
