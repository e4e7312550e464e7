#!/usr/bin/env bash
# `mpirun -np 2 mesochain run`: the same results JSON as one rank (timings aside), the same
# standard output (printed once, by rank 0), one structure file; `mesochain scan` stopped on 2
# ranks and resumed on 3 gives the 1-rank curve; bad input ends both ranks with exit code 2 and
# the error printed once.
# Usage: cli_under_mpirun.sh MESOCHAIN SOURCE_DIR WORK_DIR MPIRUN [MPIRUN OPTIONS...]
set -euo pipefail
bin=$1 src=$2 work=$3
shift 3
mpirun=("$@")
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$bin" -q run "$src/examples/cnt55.toml" --json one.json --structure one > one.out
"${mpirun[@]}" -np 2 "$bin" -q run "$src/examples/cnt55.toml" --json two.json --structure two > two.out
diff one.out two.out
python3 - <<'PY'
import json, sys
a, b = json.load(open("one.json")), json.load(open("two.json"))
for j in (a, b):
    j.pop("timings_seconds")
    j.pop("input", None)
if a != b:
    sys.exit("the 2-rank results JSON differs from the 1-rank one")
PY
cmp one.xyz two.xyz
# No temporary file of another rank left behind.
[ "$(ls | grep -c '\.tmp\.')" -eq 0 ] || { echo "stray temporary files"; ls; exit 1; }
# A stretch scan: 1 rank; 2 ranks stopped after 2 points, resumed on 3 ranks (its two chains on
# two groups): the same curve (timings aside), rows printed once.
mkdir -p scan1 scan2
for d in scan1 scan2; do cp "$src/examples/scan-stretch-cnt55.toml" "$src/examples/cnt55.toml" $d/; done
(cd scan1 && "$bin" -q scan scan-stretch-cnt55.toml > out.txt)
(cd scan2 && { "${mpirun[@]}" -np 2 "$bin" -q scan scan-stretch-cnt55.toml --stop-after 2 > out1.txt || [ $? -eq 4 ]; })
(cd scan2 && "${mpirun[@]}" -np 3 "$bin" -q scan scan-stretch-cnt55.toml --resume > out.txt)
python3 - <<'PY'
import json, sys
def strip(j):
    if isinstance(j, dict):
        return {k: strip(v) for k, v in j.items() if "time" not in k and k not in ("program",)}
    if isinstance(j, list):
        return [strip(x) for x in j]
    return j
a = json.load(open("scan1/scan-stretch-cnt55.json"))
b = json.load(open("scan2/scan-stretch-cnt55.json"))
if strip(a) != strip(b):
    sys.exit("the resumed 3-rank scan curve differs from the 1-rank one")
PY
[ "$(grep -c '^ *[0-9]/5 ' scan2/out.txt)" -eq "$(grep -c '^ *[0-9]/5 ' scan1/out.txt)" ] || { echo "scan rows printed more than once"; exit 1; }
[ -s scan2/scan-stretch-cnt55.png ] || { echo "no scan plot"; exit 1; }
# Bad input: exit code 2 (usage error) from mpirun, the message once.
set +e
"${mpirun[@]}" -np 2 "$bin" run "$work/missing.toml" > bad.out 2> bad.err
rc=$?
set -e
[ "$rc" -eq 2 ] || { echo "exit code $rc, expected 2"; cat bad.err; exit 1; }
n=$(grep -c "mesochain: error" bad.err || true)
[ "$n" -eq 1 ] || { echo "the error was printed $n times"; cat bad.err; exit 1; }
echo "cli under mpirun: run and scan as on one rank, output once, error once"
