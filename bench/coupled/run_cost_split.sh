#!/usr/bin/env bash
# Cost split of a coupled (unresolved) step: DEM substeps / coupling (porosity map, drag,
# pressure force) / ISPH, from the `time per part` line of `isphdem run` on the fluidization
# example, one thread, at the two seed velocities. Usage: bench/coupled/run_cost_split.sh [BUILD]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${1:-$root/build}"
out="$(mktemp -d)"
export OMP_NUM_THREADS=1
for u in 0.005 0.02; do
  echo "inflow.velocity = $u m/s (load average $(cut -d' ' -f1 /proc/loadavg))"
  "$build/coupling/isphdem" run "$root/examples/fluidization_2d/case.toml" --out "$out/u$u" \
    --set inflow.velocity=$u --set output.interval=1.0 | grep -E "^done|time per part"
done
rm -rf "$out"
