#!/usr/bin/env bash
# The 2D dam break (Martin & Moyce 1952, examples/dam_break_2d) at several resolutions, through
# isphdem's ISPH and through LIGGGHTS's own weakly-compressible SPH (in.wcsph: atom_style sph,
# pair_style sph/artVisc/tensCorr, Tait EOS, dynamic boundary particles), side by side in one
# invocation. For every run: wall time, particles, steps, particle-steps/s and the surge-front
# error against the table (front.py, the definition of the validation test). Writes
# results.csv, results.md and results.png (front error against wall time, both codes).
#
# usage: [RES="20 30 40"] [THREADS=2] [DTF=0.1] [ALPHA=0.1] run_bench.sh ISPHDEM [WORKDIR]
# DTF, ALPHA: LIGGGHTS time-step factor (dt = DTF h / c0) and artificial viscosity (see in.wcsph).
# LIGGGHTS runs on one MPI rank (its SPH has no OpenMP); isphdem on THREADS OpenMP threads; both
# are also reported per core-second. Runs wait for a quiet machine (1-min load <= LOAD_MAX, at
# most LOAD_WAIT s, '!' marks a run that started above it).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
isphdem=$(realpath "$1"); work=${2:-bench_dam_break_out}
RES=${RES:-20 30 40}; THREADS=${THREADS:-2}; DTF=${DTF:-0.1}; ALPHA=${ALPHA:-0.1}
LOAD_MAX=${LOAD_MAX:-0.7}; LOAD_WAIT=${LOAD_WAIT:-120}
mkdir -p "$work" && cd "$work"
source "$here/../quiet_machine.sh"   # load1, busy, wait_quiet
now() { date +%s.%N; }
a=0.1
echo "code,a_over_dx,particles,steps,wall_s,load,T_reached,mean_err,max_err" > results.csv
for n in $RES; do
  dx=$(/usr/bin/python3 -c "print($a / $n)")
  # isphdem: snapshots every 5 ms (the front is interpolated between them)
  load=$(wait_quiet); t0=$(now)
  OMP_NUM_THREADS=$THREADS "$isphdem" run "$root/examples/dam_break_2d/case.toml" --out "isph_$n" \
    --set particles.spacing="$dx" --set output.interval=0.005 > "isph_$n.log" 2>&1 || true
  wall=$(/usr/bin/python3 -c "print($(now) - $t0)")
  /usr/bin/python3 "$here/front.py" "isph_$n" --dx "$dx" --json "isph_$n.json" > "isph_$n.front"
  parts=$(sed -n 's/.*particles: \([0-9]*\) fluid, \([0-9]*\) wall.*/\1 \2/p' "isph_$n.log" | awk '{print $1 + $2}')
  steps=$(/usr/bin/python3 -c "import h5py, glob; print(max(h5py.File(f, 'r').attrs['step'] for f in glob.glob('isph_$n/snap_*.h5')))")
  /usr/bin/python3 - "$n" "$parts" "$steps" "$wall" "$load" "isph_$n.json" isphdem >> results.csv <<'PY'
import json, sys
n, parts, steps, wall, load, js, code = sys.argv[1:]
r = json.load(open(js))
print(f"{code},{n},{parts},{steps},{float(wall):.2f},{load},{r['T_reached']:.3f},"
      f"{r['mean_abs_error_T_le_2.5']:.4f},{r['max_abs_error_T_le_2.5']:.4f}")
PY
  # LIGGGHTS WCSPH, the same geometry and resolution
  mkdir -p "wcsph_$n"
  load=$(wait_quiet); t0=$(now)
  (cd "wcsph_$n" && liggghts -in "$here/in.wcsph" -var dx "$dx" -var dtout 0.005 -var dtf "$DTF" \
    -var alpha "$ALPHA" -log none \
    > run.log 2>&1) || true
  wall=$(/usr/bin/python3 -c "print($(now) - $t0)")
  # the time step in.wcsph derives (dt = dtf h / c0), for the dump's step numbers
  dt=$(/usr/bin/python3 -c "
import math; dx=$dx; h=1.2*dx; c0=10*math.sqrt(2*9.81*2*$a)
print($DTF*h/c0)")
  /usr/bin/python3 "$here/front.py" "wcsph_$n/dump.wcsph" --dx "$dx" --dt "$dt" \
    --json "wcsph_$n.json" > "wcsph_$n.front"
  parts=$(grep -m1 "^Loop time" "wcsph_$n/run.log" | sed 's/.* with \([0-9]*\) atoms.*/\1/')
  steps=$(grep -m1 "^Loop time" "wcsph_$n/run.log" | sed 's/.* for \([0-9]*\) steps.*/\1/')
  /usr/bin/python3 - "$n" "$parts" "$steps" "$wall" "$load" "wcsph_$n.json" liggghts-wcsph >> results.csv <<'PY'
import json, sys
n, parts, steps, wall, load, js, code = sys.argv[1:]
r = json.load(open(js))
print(f"{code},{n},{parts},{steps},{float(wall):.2f},{load},{r['T_reached']:.3f},"
      f"{r['mean_abs_error_T_le_2.5']:.4f},{r['max_abs_error_T_le_2.5']:.4f}")
PY
  tail -n 2 results.csv
done
/usr/bin/python3 "$here/plot.py" results.csv results.png results.md "$THREADS"
cat results.md
