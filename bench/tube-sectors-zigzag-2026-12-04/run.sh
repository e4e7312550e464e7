#!/bin/bash
# Zigzag sectors (n0,0)@(n0+9,0)@..., C9 (N = 1: the 4-atom C_n0 sector): the free-sliding rigidity of
# the zigzag family. Arguments: N-n0 pairs (default: N = 1, 2 for n0 = 27 ... 63). Rows already in
# results.txt are skipped. Settings as the armchair series (../tube-sectors-2026-12-01/run.sh) with
# 32 kappa points along T = sqrt(3) a (48 along a for armchair: about the same density).
M=${M:-../../build/mesochain}
pairs=("$@")
[ ${#pairs[@]} -eq 0 ] && pairs=(1-27 1-36 1-45 1-54 1-63 2-27 2-36 2-45 2-54 2-63)
for p in "${pairs[@]}"; do
  N=${p%-*}; n0=${p#*-}
  f=z$N-$n0.toml
  grep -q "^$N $n0 " results.txt 2>/dev/null && continue
  $M build tube-sector --family zigzag --inner $n0 --walls $N --kpoints 32 --task relax -o $f > /dev/null || exit 1
  python3 - "$f" <<'PY'
import sys
p = sys.argv[1]; s = open(p).read()
t = s.replace('[dispersion]\nmodel = "none"', '[dispersion]\nmodel = "lj"', 1)
assert t != s, "no [dispersion] model = none block to switch"
open(p, 'w').write(t)
PY
  start=$(date +%s.%N)
  OMP_NUM_THREADS=1 $M run $f --json ${f%.toml}.json > ${f%.toml}.log 2>&1 || exit 1
  end=$(date +%s.%N)
  echo "$N $n0 $(grep -m1 'cell:' ${f%.toml}.log | awk '{print $2}') $(grep 'Mermin free energy' ${f%.toml}.log | awk '{print $4, $5}') $(grep -m1 'relaxation:' ${f%.toml}.log) $(echo "$end - $start" | bc)" >> results.txt
done
