#!/usr/bin/env bash
# Fluid throughput (issue 2): the 2D Taylor-Green case (examples/taylor_green_2d) at about 10k,
# 40k and 160k particles, 1 and 2 OpenMP threads, in one go. Each run is a fixed number of
# steps at the case's own (viscous-limited) time step, with snapshots only at the start and the
# end. Parses the summary lines of `isphdem run` and writes results.md (markdown table) and
# results.csv next to this script, then plot.py draws results.png if matplotlib is there.
#
# Before every timed run the machine must be quiet: the 1-minute load average must be <= 0.7
# (waits up to LOAD_WAIT seconds, default 300, then runs anyway and the table marks it with '!').
# "other cores" is the CPU time the rest of the machine used during the run, per second of it
# (0.00: the run had the machine to itself; 1.00: another process kept a whole core busy).
# A run with other > OTHER_MAX (0.1) is repeated, at most TRIES (4) times in all.
#
# usage: bench/fluid/run_taylor_green.sh [ISPHDEM] [WORKDIR]
#   env: SIZES="spacing:steps ..." (default "0.01:300 0.005:100 0.0025:25")
#        THREADS="1 2"   ILUT_STEPS=10 (the 40k case once with the ILUT preconditioner; 0: skip)
#        ILU0=1 (every size and thread count also with the ILU(0) preconditioner; 0: skip)
#        LOAD_MAX=0.7    LOAD_WAIT=300    OTHER_MAX=0.1    TRIES=4
#        TABLE_ONLY=1: no runs, only results.md and results.png again from results.csv
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=${2:-/tmp/bench_fluid}
case_file=$root/examples/taylor_green_2d/case.toml
SIZES=${SIZES:-"0.01:300 0.005:100 0.0025:25"}
THREADS=${THREADS:-"1 2"}
ILUT_STEPS=${ILUT_STEPS:-10}
ILU0=${ILU0:-1}
LOAD_MAX=${LOAD_MAX:-0.7}
LOAD_WAIT=${LOAD_WAIT:-300}
OTHER_MAX=${OTHER_MAX:-0.1}
TRIES=${TRIES:-4}
nu=0.01   # viscosity of the case: dt = 0.125 dx^2 / nu (viscous limit, smaller than CFL here)

source "$here/../isphdem_binary.sh"
isphdem=$(isphdem_binary "$root" "${1:-}")   # the default one is built first if needed
mkdir -p "$work"

source "$here/../quiet_machine.sh"   # load1, busy, wait_quiet
seconds() {   # "7.2s", "1m05s", "1h02m" -> seconds
  /usr/bin/python3 - "$1" <<'EOF'
import re, sys
s = sys.argv[1]; m = re.fullmatch(r'(?:(\d+)h)?(?:(\d+)m)?(?:([\d.]+)s)?', s)
h, mi, se = (float(g) if g else 0.0 for g in m.groups())
print(3600 * h + 60 * mi + se)
EOF
}

csv=$here/results.csv
if [[ -z ${TABLE_ONLY:-} ]]; then   # TABLE_ONLY=1: only redo results.md/png from results.csv
echo "particles,threads,preconditioner,steps,wall_s,particle_steps_per_s,ppe_it_per_step,neighbours_pct,operators_pct,assembly_pct,solve_pct,rest_pct,speedup,load1,other_cores,cpu_s" >"$csv"
declare -A rate1
# run SPACING STEPS THREADS PRECONDITIONER
run() {
  local dx=$1 steps=$2 nt=$3 pc=$4
  local dt t_end log load
  dt=$(/usr/bin/python3 -c "print(0.125 * $dx**2 / $nu)")
  t_end=$(/usr/bin/python3 -c "print($steps * $dt)")   # run_until takes equal steps
  log=$work/tg_${dx}_${nt}t_${pc}.log
  # A run that another process disturbed (other > OTHER_MAX cores) is repeated, up to TRIES
  # times; the last attempt counts whatever happened.
  local try other b0
  for ((try = 1; try <= TRIES; try++)); do
    load=$(wait_quiet)
    echo "dx=$dx steps=$steps threads=$nt preconditioner=$pc load=$load (try $try)" >&2
    b0=$(busy)
    OMP_NUM_THREADS=$nt /usr/bin/time -f "%e %U %S" -o "$log.time" "$isphdem" run "$case_file" \
      --out "$work/tg_${dx}_${nt}t_$pc" --set particles.spacing="$dx" --set time.end="$t_end" \
      --set output.interval=1e9 --set solver.preconditioner="\"$pc\"" >"$log" 2>&1 ||
      { cat "$log" >&2; exit 1; }
    # Other processes during the run: CPU-seconds of the machine minus ours, per second (cores).
    other=$(/usr/bin/python3 -c "e, u, s = map(float, open('$log.time').read().split()[-3:]); \
print(f'{max(0.0, ($(busy) - $b0 - u - s) / e):.2f}')")
    echo "  other processes used $other cores" >&2
    /usr/bin/python3 -c "import sys; sys.exit(0 if $other <= $OTHER_MAX else 1)" && break
  done
  tail -2 "$log" >&2
  local n done parts nsteps wall rate ppe cpu
  cpu=$(/usr/bin/python3 -c "e, u, s = map(float, open('$log.time').read().split()[-3:]); \
print(f'{u + s:.1f}')")
  n=$(sed -n 's/^  particles: \([0-9]*\) fluid.*/\1/p' "$log")
  done=$(grep '^done:' "$log")
  parts=$(grep 'time per part:' "$log" | grep -o '[0-9]*%' | tr -d '%' | paste -sd, -)
  nsteps=$(sed 's/.* in \([0-9]*\) steps.*/\1/' <<<"$done")
  wall=$(seconds "$(sed 's/.* steps, \([^ ]*\) wall.*/\1/' <<<"$done")")
  rate=$(sed 's/.* wall, \([^ ]*\) particle-steps.*/\1/' <<<"$done")
  ppe=$(sed 's/.*, \([0-9.]*\) PPE.*/\1/' <<<"$done")
  local speedup=""
  if [[ $pc == jacobi ]]; then
    [[ $nt == 1 ]] && rate1[$dx]=$rate
    [[ -n ${rate1[$dx]:-} ]] && speedup=$(/usr/bin/python3 -c "print(f'{$rate / ${rate1[$dx]}:.2f}')")
  fi
  echo "$n,$nt,$pc,$nsteps,$wall,$rate,$ppe,$parts,$speedup,$load,$other,$cpu" >>"$csv"
}

for s in $SIZES; do
  for nt in $THREADS; do run "${s%%:*}" "${s##*:}" "$nt" jacobi; done
  if ((ILU0)); then
    for nt in $THREADS; do run "${s%%:*}" "${s##*:}" "$nt" ilu0; done
  fi
done
if ((ILUT_STEPS > 0)); then run 0.005 "$ILUT_STEPS" 1 ilut; fi
fi

{
  echo "Taylor-Green 2D (examples/taylor_green_2d), $(date -u +%Y-%m-%d), $(nproc) cores" \
       "($(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -1))"
  echo
  echo "| particles | threads | PPE preconditioner | steps | wall (s) | particle-steps/s | PPE it/step | neighbours % | operators % | assembly % | solve % | rest % | speed-up 1→2 | load before | other cores | CPU s |"
  echo "|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  tail -n +2 "$csv" | while IFS=, read -r n nt pc st w r p a b c d e sp l o cpu; do
    echo "| $n | $nt | $pc | $st | $w | $r | $p | $a | $b | $c | $d | $e | $sp | $l | $o | $cpu |"
  done
} >"$here/results.md"
cat "$here/results.md"
/usr/bin/python3 "$here/plot.py" "$csv" "$here/results.png" || echo "(no chart: plot.py failed)" >&2
