#!/usr/bin/env bash
# Where a fluid step's time goes (issue 48, item 1): each run's result.json stage_seconds (the
# step's stages as `isphdem run` times them, docs: bench/README.md) for
#   - the seed's erosion tank (examples/internal_erosion_2d/case.toml, semi-resolved, 0.5 cm/s,
#     at 2.5e-4 s with 250 DEM substeps): sequential exchange on 1 and 2 threads, the staggered
#     exchange on 1 thread (the DEM on the second core),
#     and decomposed on 2 ranks (amg: the free surface's remesh gathered over the ranks);
#   - Taylor-Green at 160k particles (spacing 0.0025, 25 steps at the viscous limit): the case's
#     Jacobi on 1 and 2 threads, amg on 1 thread and decomposed on 2 ranks;
#   - the 3D dam break at a/dx = 40 (spacing 0.0025, 0.01 s at the automatic step): 1 and 2
#     threads.
# Writes profile.csv (one row per run, seconds per step by stage) and profile.md (the table)
# next to this script. The erosion example is copied to WORKDIR first (its packing is made
# there, not in the source tree).
#
# usage: bench/fluid/run_profile.sh [ISPHDEM] [WORKDIR]
#   env: CASES="tank tg dam" (a subset)   TANK_END=0.1   LOAD_MAX=0.7   LOAD_WAIT=300
#        TABLE_ONLY=1: no runs, only profile.md again from profile.csv
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=${2:-/tmp/bench_profile}
CASES=${CASES:-"tank tg dam"}
TANK_END=${TANK_END:-0.1}
LOAD_MAX=${LOAD_MAX:-0.7}
LOAD_WAIT=${LOAD_WAIT:-300}
csv=$here/profile.csv

if [[ -z ${TABLE_ONLY:-} ]]; then
source "$here/../isphdem_binary.sh"
source "$here/../quiet_machine.sh"   # load1, busy, wait_quiet
isphdem=$(isphdem_binary "$root" "${1:-}")
mkdir -p "$work"
rm -f "$csv.new"

# run NAME THREADS RANKS CASE_FILE [--set ...]: one timed run, its row appended to profile.csv
run() {
  local name=$1 threads=$2 ranks=$3 case_file=$4
  shift 4
  local out=$work/$name load
  load=$(wait_quiet)
  local cmd=("$isphdem" run "$case_file" --out "$out" --quiet --set output.interval=1e9 "$@")
  echo "$name: $threads thread(s), $ranks rank(s), load $load" >&2
  if ((ranks > 1)); then
    OMP_NUM_THREADS=$threads OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
      mpirun -np "$ranks" --oversubscribe "${cmd[@]}" >"$out.log" 2>&1
  else
    OMP_NUM_THREADS=$threads "${cmd[@]}" >"$out.log" 2>&1
  fi || { echo "$name failed:" >&2; tail -5 "$out.log" >&2; exit 1; }
  /usr/bin/python3 "$here/profile_table.py" --row "$name" "$threads" "$ranks" "$load" \
    "$out/result.json" >>"$csv.new"
}

/usr/bin/python3 "$here/profile_table.py" --header >"$csv.new"
for c in $CASES; do
  case $c in
  tank)
    rm -rf "$work/erosion"
    cp -r "$root/examples/internal_erosion_2d" "$work/erosion"
    echo "packing the seed's layer (about a minute)" >&2
    (cd "$work/erosion" && "$isphdem" dem in.packing -log none -screen none >/dev/null)
    tank=("$work/erosion/case.toml" --set time.end="$TANK_END" --set time.dt=2.5e-4
      --set dem.substeps=250 --set 'coupling.model="semi-resolved"')
    run tank_sequential_1t 1 1 "${tank[@]}"
    run tank_sequential_2t 2 1 "${tank[@]}"
    run tank_staggered_1t 1 1 "${tank[@]}" --set 'dem.exchange="staggered"'
    run tank_amg_2r 1 2 "${tank[@]}" --set 'solver.preconditioner="amg"'
    ;;
  tg)
    # dt = 0.125 dx^2 / nu (nu = 0.01), 25 steps
    tg=("$root/examples/taylor_green_2d/case.toml" --set particles.spacing=0.0025
      --set time.dt=7.8125e-5 --set time.end=0.001953125)
    run tg160k_1t 1 1 "${tg[@]}"
    run tg160k_2t 2 1 "${tg[@]}"
    run tg160k_amg_1t 1 1 "${tg[@]}" --set 'solver.preconditioner="amg"'
    run tg160k_amg_2r 1 2 "${tg[@]}" --set 'solver.preconditioner="amg"'
    ;;
  dam)
    dam=("$root/examples/dam_break_3d/case.toml" --set particles.spacing=0.0025
      --set time.end=0.01)
    run dam3d_1t 1 1 "${dam[@]}"
    run dam3d_2t 2 1 "${dam[@]}"
    ;;
  *) echo "unknown case '$c' (tank, tg, dam)" >&2; exit 2 ;;
  esac
done
mv "$csv.new" "$csv"
fi
/usr/bin/python3 "$here/profile_table.py" --table "$csv" >"$here/profile.md"
cat "$here/profile.md"
