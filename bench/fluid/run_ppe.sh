#!/usr/bin/env bash
# Pressure solve against problem size (issue 25): the 2D Taylor-Green case at about 10k, 40k,
# 160k and 640k particles and the 3D dam break at about 140k (125k fluid), each with the jacobi
# and ilu0 BiCGSTAB paths (Eigen) and with amg (PETSc BiCGSTAB + hypre BoomerAMG), one run each
# in one go, on the same binary and machine. Every run is a fixed number of steps at the case's
# own time step, snapshots only at the start. Parsed from the summary of `isphdem run`:
#   PPE iterations per step, preconditioner setup and iteration time per step (ms), the PPE
#   time per particle and step (us), the whole step per particle (us) and particle-steps/s.
# Writes ppe_results.csv and ppe_results.md next to this script, then plot_ppe.py draws
# ppe_results.png. Waits for a quiet machine before each run (bench/quiet_machine.sh).
#
# usage: bench/fluid/run_ppe.sh [ISPHDEM] [WORKDIR]
#   env: RUNS="case:spacing:steps ..." (default below)   PRECONDITIONERS="jacobi ilu0 amg"
#        THREADS=1   LOAD_MAX=0.7   LOAD_WAIT=300   TABLE_ONLY=1 (only redo the table and chart)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=${2:-/tmp/bench_ppe}
# case:spacing:steps:dt. Each run takes `steps` fixed steps of dt (time.dt): Taylor-Green at its
# viscous limit 0.125 dx^2 / nu (nu = 0.01), the dam break at 1 ms (below its CFL and force
# limits while the column starts to fall). The finer runs take fewer steps, but every
# Taylor-Green run a multiple of 10: the periodic box solves spread_pin's second system in its
# first step and every 10th (sph/pressure_equation.hpp), and with 3 steps at 640k that one
# extra solve weighed a third of the PPE time instead of a tenth.
RUNS=${RUNS:-"taylor_green_2d:0.01:100:1.25e-3 taylor_green_2d:0.005:40:3.125e-4
  taylor_green_2d:0.0025:10:7.8125e-5 taylor_green_2d:0.00125:10:1.953125e-5
  dam_break_3d:0.002:5:1e-3"}
PRECONDITIONERS=${PRECONDITIONERS:-"jacobi ilu0 amg"}
THREADS=${THREADS:-1}
LOAD_MAX=${LOAD_MAX:-0.7}
LOAD_WAIT=${LOAD_WAIT:-300}

source "$here/../isphdem_binary.sh"
isphdem=$(isphdem_binary "$root" "${1:-}")   # the default one is built first if needed
mkdir -p "$work"
source "$here/../quiet_machine.sh"   # load1, busy, wait_quiet

csv=$here/ppe_results.csv
if [[ -z ${TABLE_ONLY:-} ]]; then
echo "case,particles,preconditioner,threads,steps,ppe_it_per_step,setup_ms_per_step,iterate_ms_per_step,ppe_us_per_particle_step,step_us_per_particle_step,particle_steps_per_s,load1" >"$csv"
for r in $RUNS; do
  IFS=: read -r name dx steps dt <<<"$r"
  t_end=$(/usr/bin/python3 -c "print($steps * $dt)")
  for pc in $PRECONDITIONERS; do
    out=$work/${name}_${dx}_$pc
    log=$out.log
    load=$(wait_quiet)
    echo "$name dx=$dx steps=$steps preconditioner=$pc threads=$THREADS load=$load" >&2
    OMP_NUM_THREADS=$THREADS "$isphdem" run "$root/examples/$name/case.toml" --out "$out" \
      --set particles.spacing="$dx" --set time.dt="$dt" --set time.end="$t_end" \
      --set output.interval=1e9 \
      --set solver.preconditioner="\"$pc\"" >"$log" 2>&1 || { tail -5 "$log" >&2; exit 1; }
    tail -3 "$log" >&2
    /usr/bin/python3 - "$log" "$name" "$pc" "$THREADS" "$load" >>"$csv" <<'PY'
import re, sys
log, name, pc, threads, load = sys.argv[1:]
text = open(log).read()
fluid, wall = map(int, re.search(r"particles: (\d+) fluid, (\d+) wall", text).groups())
n = fluid + wall
done = re.search(r"in (\d+) steps, .* wall, ([\d.e+]+) particle-steps/s, ([\d.]+) PPE", text)
steps, rate, its = int(done[1]), float(done[2]), float(done[3])
setup, iterate = map(float, re.search(r"setup ([\d.e+]+) ms/step, iterations ([\d.e+]+) ms/step",
                                      text).groups())
ppe_us = 1e3 * (setup + iterate) / n
print(f"{name},{n},{pc},{threads},{steps},{its},{setup:.4g},{iterate:.4g},{ppe_us:.4g},"
      f"{1e6 / rate:.4g},{rate:.4g},{load}")
PY
  done
done
fi

{
  echo "PPE solvers, isphdem run, $(date -u +%Y-%m-%d), $(nproc) cores" \
       "($(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -1)), OMP_NUM_THREADS=$THREADS"
  echo
  echo "| case | particles | preconditioner | steps | PPE it/step | setup ms/step | iterations ms/step | PPE µs/particle-step | step µs/particle-step | particle-steps/s | load before |"
  echo "|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|"
  tail -n +2 "$csv" | while IFS=, read -r c n pc nt st it su itm ppe step rate l; do
    echo "| $c | $n | $pc | $st | $it | $su | $itm | $ppe | $step | $rate | $l |"
  done
} >"$here/ppe_results.md"
cat "$here/ppe_results.md"
/usr/bin/python3 "$here/plot_ppe.py" "$csv" "$here/ppe_results.png" || echo "(no chart)" >&2
