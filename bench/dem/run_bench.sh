#!/usr/bin/env bash
# Wall time of the same settled granular scene under stock liggghts and under `isphdem dem` with
# fix couple/isph (zero loads), side by side in one invocation, serial and on 2 ranks. Reports
# LIGGGHTS's own "Loop time" of the timed (last) run and the ratio (target <= 1.05). The two
# alternate REPEAT times (default 3) and the fastest of each counts, which filters out other
# load on the machine (2 ranks on 2 cores are very sensitive to it).
# usage: [REPEAT=n] run_bench.sh ISPHDEM [LIGGGHTS] [WORKDIR] [extra -var args]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
isphdem=$(realpath "$1"); liggghts=${2:-/usr/bin/liggghts}; work=${3:-bench_dem_out}
shift $(( $# < 3 ? $# : 3 ))
mkdir -p "$work" && cd "$work"
loop_time() { grep "^Loop time" "$1" | tail -1 | awk '{print $4}'; }
atoms() { grep "^Loop time" "$1" | tail -1 | sed 's/.* with \([0-9]*\) atoms.*/\1/'; }
printf "%-6s %-8s %14s %14s %8s\n" ranks atoms "liggghts (s)" "isphdem (s)" ratio
for np in 1 2; do
  launch=(mpirun --allow-run-as-root --oversubscribe -np "$np")
  a=1e30 b=1e30
  for rep in $(seq "${REPEAT:-3}"); do
    "${launch[@]}" "$liggghts" -in "$here/in.bench" -var couple 0 -log none -screen stock_np$np.txt "$@"
    a=$(/usr/bin/python3 -c "print(min($a, $(loop_time stock_np$np.txt)))")
    "${launch[@]}" "$isphdem" dem "$here/in.bench" -var couple 1 -log none -screen isphdem_np$np.txt "$@"
    b=$(/usr/bin/python3 -c "print(min($b, $(loop_time isphdem_np$np.txt)))")
  done
  printf "%-6s %-8s %14.3f %14.3f %8.3f\n" "$np" "$(atoms stock_np$np.txt)" "$a" "$b" \
    "$(/usr/bin/python3 -c "print($b / $a)")"
done
