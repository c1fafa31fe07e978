#!/usr/bin/env bash
# Wall time of the same settled granular scene under stock liggghts and under `isphdem dem` with
# fix couple/isph (zero loads), side by side in one invocation, serial and on 2 ranks. Reports
# LIGGGHTS's own "Loop time" of the timed (last) run and the ratio isphdem / liggghts (target
# <= 1.05). The two alternate, REPEAT times (default 3); each repetition gives a paired ratio and
# the summary is the median of those (plus the ratio of the fastest runs).
#
# Every run waits for a quiet machine first: 1-minute load average <= LOAD_MAX (0.7), for at
# most LOAD_WAIT seconds (300; then it runs anyway and the load is marked '!'). "other" is the
# CPU time the rest of the machine used during the run per second of it (0.00 = undisturbed);
# a run with other > OTHER_MAX (0.1) is repeated, at most TRIES (4) times in all.
#
# usage: [REPEAT=n] [NP="1 2"] run_bench.sh ISPHDEM [LIGGGHTS] [WORKDIR] [extra -var args]
# For experiments on the isphdem side only: COUPLE=0 (no fix couple/isph), ISPHDEM_LAUNCH_ARGS
# (extra mpirun arguments, e.g. "-x LD_PRELOAD=..."). OMP_NUM_THREADS etc. reach both.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
isphdem=$(realpath "$1"); liggghts=${2:-/usr/bin/liggghts}; work=${3:-bench_dem_out}
shift $(( $# < 3 ? $# : 3 ))
LOAD_MAX=${LOAD_MAX:-0.7}; LOAD_WAIT=${LOAD_WAIT:-300}
mkdir -p "$work" && cd "$work"
py() { /usr/bin/python3 -c "$1"; }
loop_time() { grep "^Loop time" "$1" | tail -1 | awk '{print $4}'; }
atoms() { grep "^Loop time" "$1" | tail -1 | sed 's/.* with \([0-9]*\) atoms.*/\1/'; }
source "$here/../quiet_machine.sh"   # load1, busy, wait_quiet
# timed NAME CMD...: runs CMD after waiting for a quiet machine; sets LOAD and OTHER. A run that
# other processes disturbed (OTHER > OTHER_MAX cores) is repeated, TRIES times at most.
timed() {
  local name=$1 try b0 t0; shift
  for ((try = 1; try <= ${TRIES:-4}; try++)); do
    LOAD=$(wait_quiet)
    b0=$(busy); t0=$(date +%s.%N)
    /usr/bin/time -f "%U %S" -o "$name.cpu" "$@"
    # /usr/bin/time counts mpirun and the ranks it waits for; the rest of the machine's CPU time
    # during the run is someone else's.
    OTHER=$(py "
u, s = map(float, open('$name.cpu').read().split()[-2:])
e = $(date +%s.%N) - $t0
print(f'{max(0.0, ($(busy) - $b0 - u - s) / e):.2f}')")
    py "import sys; sys.exit(0 if $OTHER <= ${OTHER_MAX:-0.1} else 1)" && return
    echo "  ($name disturbed: other processes used $OTHER cores; again)" >&2
  done
}
med() {
  local name=$1; shift
  LOAD=$(wait_quiet)
  local b0 t0; b0=$(busy); t0=$(date +%s.%N)
  /usr/bin/time -f "%U %S" -o "$name.cpu" "$@"
  # /usr/bin/time counts mpirun and the ranks it waits for; the rest of the machine's CPU time
  # during the run is someone else's.
  OTHER=$(py "
u, s = map(float, open('$name.cpu').read().split()[-2:])
e = $(date +%s.%N) - $t0
print(f'{max(0.0, ($(busy) - $b0 - u - s) / e):.2f}')")
}
med() { py "import statistics, sys; print(statistics.median([float(x) for x in '$*'.split()]))"; }

printf "%-5s %-4s %-6s %12s %6s %6s %12s %6s %6s %7s\n" ranks rep atoms "liggghts (s)" load other \
  "isphdem (s)" load other ratio
summary=()
for np in ${NP:-1 2}; do
  launch=(mpirun --allow-run-as-root --oversubscribe -np "$np")
  as=() bs=() rs=()
  for rep in $(seq "${REPEAT:-3}"); do
    timed stock_np${np}_$rep "${launch[@]}" "$liggghts" -in "$here/in.bench" -var couple 0 \
      -log none -screen stock_np${np}_$rep.txt "$@"
    a=$(loop_time stock_np${np}_$rep.txt) la=$LOAD oa=$OTHER
    # shellcheck disable=SC2086
    timed isphdem_np${np}_$rep "${launch[@]}" ${ISPHDEM_LAUNCH_ARGS:-} "$isphdem" dem \
      "$here/in.bench" -var couple "${COUPLE:-1}" \
      -log none -screen isphdem_np${np}_$rep.txt "$@"
    b=$(loop_time isphdem_np${np}_$rep.txt)
    r=$(py "print(f'{$b / $a:.3f}')")
    as+=("$a") bs+=("$b") rs+=("$r")
    printf "%-5s %-4s %-6s %12.3f %6s %6s %12.3f %6s %6s %7s\n" "$np" "$rep" \
      "$(atoms stock_np${np}_$rep.txt)" "$a" "$la" "$oa" "$b" "$LOAD" "$OTHER" "$r"
  done
  summary+=("$(printf "%-5s %12.3f %12.3f %13.3f %13.3f %s" "$np" "$(med "${as[*]}")" \
    "$(med "${bs[*]}")" "$(med "${rs[*]}")" \
    "$(py "print(min(map(float, '${bs[*]}'.split())) / min(map(float, '${as[*]}'.split())))")" "${rs[*]}")")
done
echo
printf "%-5s %12s %12s %13s %13s %s\n" ranks "liggghts med" "isphdem med" "median ratio" \
  "fastest ratio" "ratios"
printf "%s\n" "${summary[@]}"
