#!/usr/bin/env bash
# Configures and builds isphdem into build/ (Release).
# Usage: scripts/build.sh [--sanitize] [extra cmake args] [-- targets...]
#   --sanitize  AddressSanitizer + UBSan build (RelWithDebInfo) into build-sanitize/
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${ISPHDEM_BUILD_DIR:-$root/build}"
config=(-DCMAKE_BUILD_TYPE=Release)
if [ "${1:-}" = "--sanitize" ]; then
  shift
  build="${ISPHDEM_SANITIZE_BUILD_DIR:-$root/build-sanitize}"
  config=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DISPHDEM_SANITIZE=ON)
fi
args=() targets=()
while [ $# -gt 0 ]; do
  if [ "$1" = "--" ]; then shift; targets=("$@"); break; fi
  args+=("$1"); shift
done
cmake -S "$root" -B "$build" "${config[@]}" "${args[@]}" >/dev/null
# nproc reads OMP_NUM_THREADS too, and scripts/test.sh sets it to 1 before the sanitized build:
# ask for the cores without it (that build had run on one core).
cores="$(env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc)"
if [ ${#targets[@]} -gt 0 ]; then
  cmake --build "$build" -j "$cores" --target "${targets[@]}"
else
  cmake --build "$build" -j "$cores"
fi
