#!/usr/bin/python3
"""Front error against wall time for isphdem ISPH and LIGGGHTS WCSPH (results.csv of run_bench.sh).
usage: plot.py results.csv results.png results.md THREADS"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

src, png, md, threads = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
rows = list(csv.DictReader(open(src)))
fig, ax = plt.subplots(figsize=(6, 4.2))
for code, marker in (("isphdem", "o"), ("liggghts-wcsph", "s")):
    r = [x for x in rows if x["code"] == code]
    if not r:
        continue
    wall = [float(x["wall_s"]) for x in r]
    err = [100 * float(x["mean_err"]) for x in r]
    label = f"isphdem ISPH ({threads} threads)" if code == "isphdem" else "LIGGGHTS WCSPH (1 rank)"
    ax.plot(wall, err, marker=marker, label=label)
    for x, w, e in zip(r, wall, err):
        done = "" if float(x["T_reached"]) >= 2.5 else f", stopped T={float(x['T_reached']):.2f}"
        ax.annotate(f"a/dx={x['a_over_dx']}{done}", (w, e), textcoords="offset points",
                    xytext=(4, 4), fontsize=7)
ax.set_xscale("log")
ax.set_xlabel("wall time to T = 3.08 [s]")
ax.set_ylabel("mean |front error| vs instant-release VOF, T <= 2.5 [%]")
ax.set_title("2D dam break: front error against cost")
ax.grid(True, which="both", alpha=0.3)
ax.legend()
fig.tight_layout()
fig.savefig(png, dpi=120)
with open(md, "w") as f:
    f.write("| code | a/dx | particles | steps | wall [s] | load | particle-steps/s | T reached | "
            "mean / max front error vs VOF (T ≤ 2.5) |\n|---|---|---|---|---|---|---|---|---|\n")
    for x in rows:
        ps = float(x["particles"]) * float(x["steps"]) / float(x["wall_s"])
        f.write(f"| {x['code']} | {x['a_over_dx']} | {x['particles']} | {x['steps']} | "
                f"{float(x['wall_s']):.1f} | {x['load']} | {ps:.3g} | {float(x['T_reached']):.2f} | "
                f"{100 * float(x['mean_err']):.1f}% / {100 * float(x['max_err']):.1f}% |\n")
