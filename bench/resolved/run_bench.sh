#!/usr/bin/env bash
# Cost of the resolved (PMS) coupling per clump and fluid step (bench/resolved/pms_cost.cpp), on
# one thread, written to bench/resolved/results.md. Run on a quiet machine (bench/quiet_machine.sh).
# Usage: bench/resolved/run_bench.sh [BUILD_DIR] [STEPS]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${1:-$root/build}"
steps="${2:-60}"
cmake --build "$build" --target bench_resolved >/dev/null
out="$root/bench/resolved/results.md"
source "$root/bench/quiet_machine.sh"
LOAD_MAX="${LOAD_MAX:-0.7}" LOAD_WAIT="${LOAD_WAIT:-600}"
tmp="$(mktemp)"
trap 'rm -f "$tmp"' EXIT
{
  echo "$(date -u +%Y-%m-%d), $(nproc) cores, load average before: $(wait_quiet) ('!': never quiet)"
  echo
  OMP_NUM_THREADS=1 "$build/bench/bench_resolved" "$steps" | grep -v "^resolved coupling:"
} | tee "$tmp"
mv "$tmp" "$out"
trap - EXIT
echo "written: $out"
