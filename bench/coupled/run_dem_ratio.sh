#!/usr/bin/env bash
# Coupled wall time / wall time of the same DEM scene without fluid, in one run: the bed of
# examples/fluidization_2d/tank.toml (300 grains, 2640 fluid particles, 100 DEM substeps per
# fluid step) for SECONDS of simulated time with the water, then the same LIGGGHTS script and
# substeps with no [fluid] table (isphdem's DEM-only run). Both include in.tank's 0.15 s of dry
# settling before the timed steps. Usage: bench/coupled/run_dem_ratio.sh [BUILD] [SECONDS] [THREADS]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
seconds="${2:-0.5}"
export OMP_NUM_THREADS="${3:-2}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
case_dir="$root/examples/fluidization_2d"
cat >"$out/dry.toml" <<TOML
[time]
end = $seconds

[output]
interval = $seconds

[dem]
script = "$case_dir/in.tank"
substeps = 100
screen = "liggghts.screen"
log = "none"
TOML
wall() { /usr/bin/time -f %e "$@" 2>&1 >/dev/null | tail -1; }
echo "load average before: $(cut -d' ' -f1 /proc/loadavg), $OMP_NUM_THREADS thread(s), $seconds s simulated"
coupled=$(cd "$case_dir" && wall "$build/coupling/isphdem" run tank.toml --out "$out/coupled" \
  --set inflow.velocity=0.005 --set time.end="$seconds" --set output.interval="$seconds") ||
  { echo "the coupled run failed (rerun it by hand to see why)" >&2; exit 1; }
dry=$(cd "$out" && wall "$build/coupling/isphdem" run dry.toml --out "$out/dry") ||
  { echo "the DEM-only run failed" >&2; exit 1; }
awk -v c="$coupled" -v d="$dry" 'BEGIN {
  printf "| coupled (0.5 cm/s) | DEM alone | ratio |\n|---:|---:|---:|\n| %.1f s | %.1f s | %.2f |\n", c, d, c / d }'
