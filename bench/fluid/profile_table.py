#!/usr/bin/env python3
"""Rows and table of bench/fluid/run_profile.sh.

  profile_table.py --header                               the CSV header
  profile_table.py --row NAME THREADS RANKS LOAD RESULT    one CSV row from a run's result.json
  profile_table.py --table CSV                            profile.md from profile.csv

A row holds milliseconds per step for each part of result.json's stage_seconds: the fluid step's
stages in the order they run, then the coupled run's own parts.
"""
import csv
import json
import sys

FLUID = ["neighbours", "free_surface", "operators", "predictor", "pressure_rhs", "assembly",
         "solve_setup", "solve_iterations", "correction", "shifting", "advection", "other"]
COUPLED = ["coupling", "dem", "dem_wait", "output", "dem_beside"]
FIELDS = ["run", "threads", "ranks", "load", "particles", "steps", "wall_s", "ppe_it_per_step",
          "fluid_ms_per_step", "fluid_us_per_particle_step"] + [s + "_ms" for s in FLUID + COUPLED]


def row(name, threads, ranks, load, result):
    r = json.load(open(result))
    if r.get("status") != "finished":
        sys.exit(f"{result}: the run did not finish ({r.get('status')}: {r.get('message')})")
    steps = max(1, r["steps"])
    s = r.get("stage_seconds", {})
    fluid = sum(s.get(k, 0.0) for k in FLUID)
    values = [name, threads, ranks, load, r["particles"], r["steps"], f"{r['wall_seconds']:.2f}",
              f"{r['ppe_iterations_per_step']:.1f}", f"{1e3 * fluid / steps:.3f}",
              f"{1e6 * fluid / steps / max(1, r['particles']):.3f}"]
    values += [f"{1e3 * s[k] / steps:.3f}" if k in s else "" for k in FLUID + COUPLED]
    csv.writer(sys.stdout).writerow(values)


def table(path):
    rows = list(csv.DictReader(open(path)))
    print("| run | threads | ranks | particles | steps | wall (s) | PPE it/step | fluid ms/step "
          "| µs per particle-step | " + " | ".join(FLUID) + " | coupling | DEM | DEM wait | "
          "output | DEM beside |")
    print("|---|" + "---:|" * (9 + len(FLUID) + 5))
    for r in rows:
        fluid = float(r["fluid_ms_per_step"])
        cells = [r["run"], r["threads"], r["ranks"], r["particles"], r["steps"], r["wall_s"],
                 r["ppe_it_per_step"], f"{fluid:.2f}", r["fluid_us_per_particle_step"]]
        for k in FLUID:
            v = float(r[k + "_ms"] or 0.0)
            cells.append(f"{v:.2f} ({100 * v / fluid:.0f}%)" if fluid > 0 else "")
        for k in COUPLED:
            cells.append(f"{float(r[k + '_ms']):.2f}" if r[k + "_ms"] else "")
        print("| " + " | ".join(cells) + " |")
    print()
    print("Milliseconds per step by stage (in brackets: share of the fluid step); coupled parts "
          "apart. 'DEM beside' runs on the second core during the fluid step (staggered "
          "exchange) and is not part of the wall time; 'output' is the wall time the stages "
          "leave (start, snapshots, diagnostics).")


if __name__ == "__main__":
    if sys.argv[1:2] == ["--header"]:
        csv.writer(sys.stdout).writerow(FIELDS)
    elif sys.argv[1:2] == ["--row"] and len(sys.argv) == 7:
        row(*sys.argv[2:7])
    elif sys.argv[1:2] == ["--table"] and len(sys.argv) == 3:
        table(sys.argv[2])
    else:
        sys.exit(__doc__)
