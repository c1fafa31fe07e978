#!/usr/bin/env bash
# MPI ranks against OpenMP threads (issue 26), on this machine's 2 cores: each case run as
# 1 rank x 1 thread, 2 ranks x 1 thread (mpirun; a fluid-only case decomposed: each rank holds
# and steps its own part), 2 ranks with shared rows (layout 2x1s: every rank holds the whole
# fluid and computes its block of rows of each stage, parallel.decompose = false) and 1 rank x 2
# threads, PPE with amg, one run each in one go, same binary; the pressure equation is one PETSc
# system (docs/parallel.md). Coupled cases are decomposed too, PMS bodies included.
# Parsed from the summary of `isphdem run` and result.json: wall time, particle-steps/s, PPE
# iterations per step, the PPE's setup and iteration ms per step, the exchanges' ms per step,
# how the fluid was split, the largest resident memory of a rank (/usr/bin/time) and the wall
# time per simulated second.
# Writes results.csv and results.md next to this script. Waits for a quiet machine before each
# run (bench/quiet_machine.sh).
#
# usage: bench/mpi/run_ranks.sh [ISPHDEM] [WORKDIR]
#   env: RUNS="case.toml:spacing:t_end:dt[:key=value] ..." (spacing/dt "-": the case's own;
#        key=value: one more --set)
#        LAYOUTS="1x1 2x1 2x1s 1x2" (ranks x threads, s: shared rows)   LOAD_MAX=0.7
#        LOAD_WAIT=300
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=${2:-/tmp/bench_mpi}
# Taylor-Green at 40k and 160k particles at its viscous limit 0.125 dx^2 / nu (20 and 10 steps),
# the 2D dam break's first 0.05 s (automatic step), the closed internal-erosion tank (coupled,
# LIGGGHTS on the same ranks) for 0.05 s, unresolved and semi-resolved.
RUNS=${RUNS:-"taylor_green_2d/case.toml:0.005:6.25e-3:3.125e-4
  taylor_green_2d/case.toml:0.0025:7.8125e-4:7.8125e-5
  dam_break_2d/case.toml:-:0.05:-
  internal_erosion_2d/closed.toml:-:0.05:-
  internal_erosion_2d/closed.toml:-:0.05:-:coupling.model=\"semi-resolved\""}
LAYOUTS=${LAYOUTS:-"1x1 2x1 2x1s 1x2"}
LOAD_MAX=${LOAD_MAX:-0.7}
LOAD_WAIT=${LOAD_WAIT:-300}

source "$here/../isphdem_binary.sh"
isphdem=$(isphdem_binary "$root" "${1:-}")
mkdir -p "$work"
source "$here/../quiet_machine.sh"

csv=$here/results.csv
echo "case,particles,ranks,threads,sim_time,steps,wall_s,wall_per_sim_s,particle_steps_per_s,ppe_it_per_step,setup_ms_per_step,iterate_ms_per_step,exchange_ms_per_step,fluid_on_ranks,max_rss_mb,load1" >"$csv"
for r in $RUNS; do
  IFS=: read -r case dx t_end dt extra <<<"$r"
  sets=(--set time.end="$t_end" --set output.interval=1e9 --set solver.preconditioner='"amg"')
  [[ $dx != - ]] && sets+=(--set particles.spacing="$dx")
  [[ $dt != - ]] && sets+=(--set time.dt="$dt")
  [[ -n $extra ]] && sets+=(--set "$extra")
  label=$case
  [[ -n $extra ]] && label="$case ${extra//\"/}"
  for layout in $LAYOUTS; do
    ranks=${layout%x*} threads=${layout#*x}
    layout_sets=()
    if [[ $threads == *s ]]; then
      threads=${threads%s}
      layout_sets=(--set parallel.decompose=false)
    fi
    out=$work/$(echo "$case" | tr / _)_${dx}${extra:+_${extra%%=*}}_$layout
    log=$out.log
    rm -f "$log.rss"
    load=$(wait_quiet)
    echo "$case dx=$dx t_end=$t_end ranks=$ranks threads=$threads load=$load" >&2
    # Open MPI refuses root unless told: set for this script's own runs only.
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=$threads \
      mpirun --oversubscribe --bind-to none -np "$ranks" \
      /usr/bin/time -a -o "$log.rss" -f "maxrss_kb %M" \
      "$isphdem" run "$root/examples/$case" --out "$out" "${sets[@]}" "${layout_sets[@]}" \
      >"$log" 2>&1 || { tail -5 "$log" >&2; exit 1; }
    /usr/bin/python3 - "$here" "$log" "$label" "$ranks" "$threads" "$load" "$t_end" \
      "$out/result.json" >>"$csv" <<'PY'
import sys
sys.dont_write_bytecode = True  # nothing written into bench/mpi/
sys.path.insert(0, sys.argv[1])
import run_summary
log, case, ranks, threads, load, t_end, result = sys.argv[2:]
r = run_summary.read(log, result)
n, steps, wall, t = r["particles"], r["steps"], r["wall_s"], float(t_end)
split = "decomposed" if r["decomposed"] else "shared rows" if r["rows_shared"] else "-"
print(f"{case},{n},{ranks},{threads},{t},{steps},{wall:.4g},{wall / t:.4g},"
      f"{n * steps / wall:.4g},{r['ppe_it']},{r['setup_ms']:.4g},{r['iterate_ms']:.4g},"
      f"{r['exchange_ms']:.3g},{split},{r['max_rss_mb']:.0f},{load}")
PY
    tail -1 "$csv" >&2
  done
done

{
  echo "Ranks against threads, isphdem run, $(date -u +%Y-%m-%d), $(nproc) cores" \
       "($(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -1)), PPE amg"
  echo
  echo "| case | particles | ranks × threads | fluid on the ranks | steps | wall (s) | wall per simulated s | speed-up vs 1×1 | particle-steps/s | PPE it/step | PPE setup ms/step | PPE iterations ms/step | exchanges ms/step | memory per rank (MB) | load before |"
  echo "|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  /usr/bin/python3 - "$csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
base = {}
for r in rows:
    key = (r["case"], r["particles"])
    if r["ranks"] == "1" and r["threads"] == "1":
        base[key] = float(r["wall_s"])
for r in rows:
    b = base.get((r["case"], r["particles"]))
    up = f"{b / float(r['wall_s']):.2f}" if b else ""
    print(f"| {r['case']} | {r['particles']} | {r['ranks']} × {r['threads']} | "
          f"{r['fluid_on_ranks']} | {r['steps']} | {r['wall_s']} | {r['wall_per_sim_s']} | {up} | "
          f"{r['particle_steps_per_s']} | {r['ppe_it_per_step']} | {r['setup_ms_per_step']} | "
          f"{r['iterate_ms_per_step']} | {r['exchange_ms_per_step']} | {r['max_rss_mb']} | "
          f"{r['load1']} |")
PY
} >"$here/results.md"
cat "$here/results.md"
