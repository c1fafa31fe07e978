#!/usr/bin/env bash
# The DEM beside the fluid ([dem] exchange = "staggered") against the sequential exchange, in one
# run of this script: the seed's tank (examples/internal_erosion_2d/case.toml, semi-resolved,
# 0.5 cm/s; 2480 fluid and 978 wall particles, 16 clumps, 80 fines) at time.dt = DT with the DEM
# step held at 1e-6 s, SECONDS simulated, three ways in turn, REPS times:
#   seq1  sequential, OMP_NUM_THREADS=1     seq2  sequential, 2 threads
#   stag  staggered, OMP_NUM_THREADS=1 (the fluid on one core, the DEM on the other)
# The wall times (/usr/bin/time) and the ratios stag/seq1 and stag/seq2 pair by pair, their
# medians last. The packing is made first in a temporary directory (about 8 s).
# Usage: bench/coupled/run_exchange.sh [BUILD] [SECONDS] [DT] [REPS]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
seconds="${2:-0.2}" dt="${3:-5e-4}" reps="${4:-3}"
isphdem="$build/coupling/isphdem"
case_dir="$root/examples/internal_erosion_2d"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
"$isphdem" dem "$case_dir/in.packing" -var case_dir "$case_dir" -var packing_dir "$out" \
  -log none -screen none >/dev/null
substeps=$(awk -v dt="$dt" 'BEGIN { printf "%d", dt / 1e-6 + 0.5 }')
run() {  # NAME THREADS EXCHANGE: prints the wall seconds
  OMP_NUM_THREADS="$2" /usr/bin/time -f %e "$isphdem" run "$case_dir/case.toml" \
    --out "$out/$1" --quiet --set "dem.variables.packing_dir=\"$out\"" \
    --set 'coupling.model="semi-resolved"' --set time.end="$seconds" --set time.dt="$dt" \
    --set dem.substeps="$substeps" --set output.interval="$seconds" \
    --set "dem.exchange=\"$3\"" 2>&1 >/dev/null | tail -1
}
echo "load average before: $(cut -d' ' -f1 /proc/loadavg); $seconds s simulated at dt = $dt s" \
  "($substeps DEM substeps), $reps repetitions"
echo "| rep | seq1 (s) | seq2 (s) | stag (s) | stag/seq1 | stag/seq2 |"
echo "|---:|---:|---:|---:|---:|---:|"
r1=() r2=()
for k in $(seq 1 "$reps"); do
  a=$(run seq1 1 sequential) b=$(run seq2 2 sequential) c=$(run stag 1 staggered)
  x=$(awk -v a="$a" -v c="$c" 'BEGIN { printf "%.3f", c / a }')
  y=$(awk -v b="$b" -v c="$c" 'BEGIN { printf "%.3f", c / b }')
  r1+=("$x") r2+=("$y")
  echo "| $k | $a | $b | $c | $x | $y |"
done
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
echo "median stag/seq1 $(median "${r1[@]}"), stag/seq2 $(median "${r2[@]}")"
