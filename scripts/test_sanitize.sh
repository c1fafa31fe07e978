#!/usr/bin/env bash
# Builds the AddressSanitizer + UBSan variant (build-sanitize/) and runs tests under it.
#   scripts/test_sanitize.sh                                  the unit tests (what CI runs)
#   scripts/test_sanitize.sh -LE "slow|work_in_progress"      the whole default suite
# Extra arguments go to ctest. A sanitizer report makes the test that triggered it fail: ASan and
# UBSan stop the process, LeakSanitizer changes the exit status. The options and the suppressions
# (third-party leaks only, each with its reason) are compiled into the binaries
# (tests/sanitizers/sanitizer_defaults.cpp).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/build.sh" --sanitize
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
jobs="${CTEST_PARALLEL_LEVEL:-$(env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc)}"
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-1}"
if [ $# -eq 0 ]; then set -- -L unit -LE "slow|work_in_progress"; fi
ctest --test-dir "${ISPHDEM_SANITIZE_BUILD_DIR:-$root/build-sanitize}" --output-on-failure \
  -j "$jobs" "$@"
