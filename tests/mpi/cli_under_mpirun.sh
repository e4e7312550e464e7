#!/usr/bin/env bash
# `mpirun -np 2 mesochain run`: the same results JSON as one rank (timings aside), the same
# standard output (printed once, by rank 0), one structure file; bad input ends both ranks with
# exit code 2 and the error printed once.
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
# Bad input: exit code 2 (usage error) from mpirun, the message once.
set +e
"${mpirun[@]}" -np 2 "$bin" run "$work/missing.toml" > bad.out 2> bad.err
rc=$?
set -e
[ "$rc" -eq 2 ] || { echo "exit code $rc, expected 2"; cat bad.err; exit 1; }
n=$(grep -c "mesochain: error" bad.err || true)
[ "$n" -eq 1 ] || { echo "the error was printed $n times"; cat bad.err; exit 1; }
echo "cli under mpirun: same results as one rank, output once, error once"
