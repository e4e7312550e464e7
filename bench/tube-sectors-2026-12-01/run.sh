#!/bin/bash
M=${M:-../../build/mesochain}
for N in 1 2; do for n0 in 15 20 25 30 35; do
  f=s$N-$n0.toml
  $M build tube-sector --family armchair --inner $n0 --walls $N --kpoints 48 --task relax -o $f > /dev/null
  python3 - "$f" <<'PY'
import sys,re
p=sys.argv[1]; s=open(p).read()
s=s.replace('[dispersion]\nmodel = "none"','[dispersion]\nmodel = "lj"',1)
open(p,'w').write(s)
PY
  start=$(date +%s.%N)
  OMP_NUM_THREADS=1 $M run $f --json ${f%.toml}.json > ${f%.toml}.log 2>&1
  end=$(date +%s.%N)
  echo "$N $n0 $(grep -m1 'cell:' ${f%.toml}.log | awk '{print $2}') $(grep 'Mermin free energy' ${f%.toml}.log | awk '{print $4, $5}') $(grep -m1 'relaxation:' ${f%.toml}.log) $(echo "$end - $start" | bc)" >> results.txt
done; done
echo ALLDONE >> results.txt
