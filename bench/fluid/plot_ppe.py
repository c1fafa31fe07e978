"""Chart of bench/fluid/ppe_results.csv: PPE iterations per step and PPE time per particle-step
against the particle count, per preconditioner (Taylor-Green 2D as lines, the 3D dam break as
single points). usage: plot_ppe.py ppe_results.csv ppe_results.png"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

rows = list(csv.DictReader(open(sys.argv[1])))
fig, axes = plt.subplots(1, 3, figsize=(14, 4))
columns = (("ppe_it_per_step", "PPE iterations per step"),
           ("ppe_us_per_particle_step", "PPE time per particle-step (µs)"),
           ("step_us_per_particle_step", "whole step per particle-step (µs)"))
for pc, colour in (("jacobi", "C0"), ("ilu0", "C1"), ("amg", "C2")):
    for case, style in (("taylor_green_2d", "o-"), ("dam_break_3d", "s")):
        sel = sorted((r for r in rows if r["preconditioner"] == pc and r["case"] == case),
                     key=lambda r: int(r["particles"]))
        if not sel:
            continue
        n = [int(r["particles"]) for r in sel]
        label = f"{pc}, {'Taylor-Green 2D' if case.startswith('taylor') else 'dam break 3D'}"
        for ax, (col, _) in zip(axes, columns):
            ax.plot(n, [float(r[col]) for r in sel], style, color=colour, label=label)
for ax, (_, title) in zip(axes, columns):
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("particles")
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
axes[0].legend(fontsize=8)
fig.suptitle("Pressure solve against size, isphdem run, one thread")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=100)
print("wrote", sys.argv[2])
