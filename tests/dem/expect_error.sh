#!/usr/bin/env bash
# Runs a command that must fail: non-zero exit, and its output (stdout + stderr) must match
# PATTERN (grep -E). usage: expect_error.sh PATTERN COMMAND...
set -uo pipefail
pattern=$1; shift
out=$("$@" 2>&1); rc=$?
if [ "$rc" -eq 0 ]; then echo "FAIL: exit status 0, expected an error: $*"; echo "$out" | tail -5; exit 1; fi
if ! grep -qE -- "$pattern" <<< "$out"; then
  echo "FAIL: exit $rc but no message matching '$pattern':"; echo "$out" | tail -5; exit 1
fi
echo "ok: exit $rc, message: $(grep -E -- "$pattern" <<< "$out" | head -1)"
