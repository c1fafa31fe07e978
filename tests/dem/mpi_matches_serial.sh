#!/usr/bin/env bash
# dem_mpi_probe on 1 and on 2 ranks: each must pass on its own, and the final states must agree
# to round-off (free spheres without contacts: no summation order can differ, so exactly).
# usage: mpi_matches_serial.sh PROBE INPUT WORKDIR
set -euo pipefail
probe=$1 input=$2 work=$3
mkdir -p "$work"
mpirun --allow-run-as-root --oversubscribe -np 1 "$probe" "$input" "$work/np1.txt"
mpirun --allow-run-as-root --oversubscribe -np 2 "$probe" "$input" "$work/np2.txt"
/usr/bin/python3 - "$work/np1.txt" "$work/np2.txt" <<'PY'
import sys
a = [list(map(float, l.split())) for l in open(sys.argv[1])]
b = [list(map(float, l.split())) for l in open(sys.argv[2])]
assert len(a) == len(b) > 0, (len(a), len(b))
worst = 0.0
for ra, rb in zip(a, b):
    assert ra[0] == rb[0], "lattice sites differ"
    for x, y in zip(ra[1:], rb[1:]):
        worst = max(worst, abs(x - y) / max(abs(x), 1e-300) if x != y else 0.0)
print(f"1 vs 2 ranks: {len(a)} spheres, max relative difference {worst:.3e}")
sys.exit(0 if worst <= 1e-12 else 1)
PY
