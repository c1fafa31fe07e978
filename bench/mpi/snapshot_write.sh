#!/usr/bin/env bash
# A fluid snapshot written by the ranks together (parallel HDF5, each rank its block of rows)
# against rank 0 alone holding every row, at 2 ranks and three sizes (bench_snapshot_write, median
# of 9 of each, alternating). Writes snapshot_write.csv beside this script.
# usage: bench/mpi/snapshot_write.sh [ISPHDEM] [WORKDIR]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=${2:-/tmp/bench_snapshot_write}
source "$here/../isphdem_binary.sh"
isphdem=$(isphdem_binary "$root" "${1:-}")
build=$(dirname "$(dirname "$isphdem")")
bench=$build/bench/bench_snapshot_write
[[ -x $bench ]] || cmake --build "$build" --target bench_snapshot_write
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
out=$here/snapshot_write.csv
first=1
for n in 40000 160000 1280000; do
  rm -rf "$work"
  line=$(mpirun --oversubscribe -np 2 "$bench" "$work" "$n" 9)
  if ((first)); then echo "$line" | head -1 >"$out"; first=0; fi
  echo "$line" | tail -1 | tee -a "$out"
done
rm -rf "$work"
echo "wrote $out"
