#!/usr/bin/env bash
# Installs what is missing, builds, and runs the default test suite (labels unit, validation, mpi),
# then the unit tests again in an AddressSanitizer + UBSan build (scripts/test_sanitize.sh;
# ISPHDEM_SANITIZE_TESTS=0 skips that part).
# Left out: tests labelled slow (`ctest --test-dir build -L slow`) and work_in_progress (known not
# to pass yet, e.g. the dam-break comparison: `ctest --test-dir build -L work_in_progress`).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh"
# Open MPI refuses root unless told; CI and these machines run as root.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# One test per core, each on one thread: most cases are a few thousand particles, where a second
# thread gains little, so two tests side by side finish the suite sooner than one on two threads.
# The MPI tests run alone (RUN_SERIAL). Override with CTEST_PARALLEL_LEVEL / OMP_NUM_THREADS.
# (nproc reads OMP_NUM_THREADS too: ask it for the cores before that is set.)
jobs="${CTEST_PARALLEL_LEVEL:-$(env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc)}"
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-1}"
ctest --test-dir "${ISPHDEM_BUILD_DIR:-$root/build}" --output-on-failure -j "$jobs" \
  -LE "slow|work_in_progress" "$@"
if [ "${ISPHDEM_SANITIZE_TESTS:-1}" != 0 ]; then
  echo "test: the unit tests under AddressSanitizer + UBSan (scripts/test_sanitize.sh)"
  bash "$root/scripts/test_sanitize.sh"
fi
