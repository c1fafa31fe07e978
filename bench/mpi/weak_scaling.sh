#!/usr/bin/env bash
# Weak-scaling estimate for the decomposed fluid (issue 26), from what this 2-core machine can
# measure:
#  1. bench_halo_share at 1, 2, 4, 8 ranks (40k particles per rank, periodic square, RCB, halo
#     one kernel support wide): the halo share, and at 2 ranks (one per core) the time of one
#     halo refresh and of one allreduce;
#  2. Taylor-Green with 40k particles per rank at 1, 2, 4, 8 ranks (oversubscribed beyond 2: only
#     the PPE iteration counts are read from those, not times), 10 steps at the viscous limit;
#  3. one rank's time per step split into the PPE and the rest (the 40k run of 2.).
# The estimate (python below) for P ranks of N particles each:
#   T_P = (rest_1 + setup_1 + iterations_1 it_P / it_1) (1 + h_P) + E refresh_2
#         + A log2(P) allreduce_2
# with h_P the halo share (8 ranks' value beyond 8: every box then has neighbours on all sides),
# it_P the PPE iterations per step, measured to 8 ranks and fitted as a + b log2 P (b >= 0) from
# 2 ranks on beyond, E = 11 refreshes and
# A = 8 reductions per step (docs/parallel.md), the 2-rank exchange costs (shared memory; a
# network adds latency). Efficiency T_1 / T_P. Writes weak_scaling.csv and weak_scaling.md.
# usage: bench/mpi/weak_scaling.sh [ISPHDEM] [WORKDIR]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=${2:-/tmp/bench_weak}
source "$here/../isphdem_binary.sh"
isphdem=$(isphdem_binary "$root" "${1:-}")
halo_bench=$(dirname "$(dirname "$isphdem")")/bench/bench_halo_share
[[ -x $halo_bench ]] || cmake --build "$(dirname "$(dirname "$isphdem")")" --target bench_halo_share
mkdir -p "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
per_rank=40000

halo=$work/halo.csv
echo "ranks,particles_per_rank,halo_mean,halo_max,refresh_ms,allreduce_us,rows_exchange_ms" >"$halo"
for p in 1 2 4 8; do
  mpirun --oversubscribe --bind-to none -np $p "$halo_bench" $per_rank 200 >>"$halo"
done
cat "$halo" >&2

ppe=$work/ppe.csv
echo "ranks,particles,ppe_it_per_step,setup_ms_per_step,iterate_ms_per_step,step_ms" >"$ppe"
for p in 1 2 4 8; do
  # dx for about 40k particles per rank in the unit box (a whole number of spacings across the
  # periodic box); dt at the viscous limit 0.125 dx^2 / nu.
  read -r dx dt t_end < <(/usr/bin/python3 -c "
import math; dx = 1 / round(math.sqrt($per_rank * $p)); dt = 12.5 * dx * dx
print(dx, dt, 10 * dt)")
  log=$work/tg_$p.log
  mpirun --oversubscribe --bind-to none -np $p "$isphdem" run \
    "$root/examples/taylor_green_2d/case.toml" --out "$work/tg_$p" --set particles.spacing="$dx" \
    --set time.dt="$dt" --set time.end="$t_end" --set output.interval=1e9 \
    --set solver.preconditioner='"amg"' >"$log" 2>&1 || { tail -5 "$log" >&2; exit 1; }
  /usr/bin/python3 - "$here" "$log" "$p" "$work/tg_$p/result.json" >>"$ppe" <<'PY'
import sys
sys.dont_write_bytecode = True  # nothing written into bench/mpi/
sys.path.insert(0, sys.argv[1])
import run_summary
r = run_summary.read(sys.argv[2], sys.argv[4])
print(f"{sys.argv[3]},{r['particles']},{r['ppe_it']},{r['setup_ms']:.4g},{r['iterate_ms']:.4g},"
      f"{1e3 * r['wall_s'] / r['steps']:.4g}")
PY
  tail -1 "$ppe" >&2
done

/usr/bin/python3 - "$halo" "$ppe" "$here" <<'PY'
import csv, math, sys
halo = {int(r["ranks"]): r for r in csv.DictReader(open(sys.argv[1]))}
ppe = {int(r["ranks"]): r for r in csv.DictReader(open(sys.argv[2]))}
here = sys.argv[3]
h = {p: float(halo[p]["halo_max"]) for p in halo}
refresh = float(halo[2]["refresh_ms"])
allreduce = float(halo[2]["allreduce_us"]) / 1e3
it = {p: float(ppe[p]["ppe_it_per_step"]) for p in ppe}
# Least squares it = a + b log2 P over the measured ranks from 2 on (one rank's count is lower by
# a step: BoomerAMG's aggressive coarsening across rank boundaries), b at least 0.
many = [p for p in sorted(it) if p >= 2]
xs = [math.log2(p) for p in many]
ys = [it[p] for p in many]
mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
b = max(0.0, sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs))
a = my - b * mx
setup1 = float(ppe[1]["setup_ms_per_step"])
iterate1 = float(ppe[1]["iterate_ms_per_step"])
ppe1 = setup1 + iterate1
rest1 = float(ppe[1]["step_ms"]) - ppe1
t1 = rest1 + ppe1
rows = []
for p in [1, 2, 4, 8, 16, 32, 64]:
    hp = h.get(p, h[8]) if p > 1 else 0.0
    itp = it[p] if p in it else a + b * math.log2(p)
    comm = (11 * refresh + 8 * math.log2(p) * allreduce) if p > 1 else 0.0
    tp = (rest1 + setup1 + iterate1 * itp / it[1]) * (1 + hp) + comm
    rows.append((p, hp, itp, p in it, comm, tp, t1 / tp))
with open(f"{here}/weak_scaling.csv", "w") as f:
    f.write("ranks,halo_share,ppe_it_per_step,measured_it,comm_ms_per_step,step_ms,efficiency\n")
    for p, hp, itp, meas, comm, tp, e in rows:
        f.write(f"{p},{hp:.4f},{itp:.2f},{'yes' if meas else 'no'},{comm:.3g},{tp:.4g},{e:.3f}\n")
with open(f"{here}/weak_scaling.md", "w") as f:
    f.write(f"Weak-scaling estimate, 40k particles per rank (Taylor-Green); one rank: "
            f"{t1:.1f} ms/step ({ppe1:.1f} PPE, {rest1:.1f} rest); halo refresh "
            f"{refresh * 1e3:.1f} us, allreduce {allreduce * 1e3:.2f} us at 2 ranks; "
            f"PPE iterations fitted {a:.2f} + {b:.2f} log2 P\n\n")
    f.write("| ranks | halo share | PPE it/step | | comm ms/step | step ms | efficiency |\n")
    f.write("|---:|---:|---:|---|---:|---:|---:|\n")
    for p, hp, itp, meas, comm, tp, e in rows:
        f.write(f"| {p} | {100 * hp:.1f}% | {itp:.2f} | {'measured' if meas else 'fitted'} | "
                f"{comm:.3g} | {tp:.4g} | {100 * e:.0f}% |\n")
print(open(f"{here}/weak_scaling.md").read())
PY
