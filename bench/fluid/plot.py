"""Chart of bench/fluid/results.csv: particle-steps/s and PPE iterations per step against N.
usage: plot.py results.csv results.png"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

rows = list(csv.DictReader(open(sys.argv[1])))
fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
for pc, marker in (("jacobi", "o"), ("ilu0", "^"), ("ilut", "s")):
    for nt in sorted({r["threads"] for r in rows if r["preconditioner"] == pc}):
        sel = sorted((r for r in rows if r["preconditioner"] == pc and r["threads"] == nt),
                     key=lambda r: int(r["particles"]))
        n = [int(r["particles"]) for r in sel]
        label = f"{pc}, {nt} thread{'s' if nt != '1' else ''}"
        a.plot(n, [float(r["particle_steps_per_s"]) for r in sel], marker=marker, label=label)
        if nt == "1":
            b.plot(n, [float(r["ppe_it_per_step"]) for r in sel], marker=marker, label=pc)
jac = sorted((r for r in rows if r["preconditioner"] == "jacobi" and r["threads"] == "1"),
             key=lambda r: int(r["particles"]))
if len(jac) >= 2:  # reference slope: iterations ~ N^(1/2) (~ 1/dx in 2D)
    n0, i0 = int(jac[0]["particles"]), float(jac[0]["ppe_it_per_step"])
    ns = [int(r["particles"]) for r in jac]
    b.plot(ns, [i0 * (x / n0) ** 0.5 for x in ns], "k:", label="~ N^(1/2)")
for ax, title in ((a, "throughput"), (b, "PPE iterations per step (BiCGSTAB)")):
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("particles")
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
a.set_ylabel("particle-steps / s")
b.set_ylabel("iterations / step")
fig.suptitle("Taylor-Green 2D, isphdem run")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=100)
print("wrote", sys.argv[2])
