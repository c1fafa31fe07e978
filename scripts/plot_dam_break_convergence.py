#!/usr/bin/python3
"""Surge front Z(T) of the 2D dam break at several a/dx against the instant-release interFoam
reference and Martin & Moyce, from the JSON files of bench/dam_break/front.py (with a_over_dx and
wall_s added by scripts/dam_break_convergence.sh). Writes PREFIX.csv (one row per a/dx and T) and
PREFIX.png (front, and its difference from the reference).
usage: plot_dam_break_convergence.py PREFIX RESULT.json [...]"""
import csv
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    prefix, paths = sys.argv[1], sys.argv[2:]
    runs = sorted((json.load(open(p)) for p in paths), key=lambda r: r["a_over_dx"])
    with open(prefix + ".csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["a_over_dx", "wall_s", "T", "Z", "Z_reference", "Z_MartinMoyce", "error"])
        for r in runs:
            for row in r["rows"]:
                w.writerow([r["a_over_dx"], r["wall_s"], row["T"], f"{row['Z']:.4f}",
                            row["Z_ref"], row["Z_MartinMoyce"], f"{row['error']:.4f}"])
    fig, (ax, ax_err) = plt.subplots(1, 2, figsize=(10, 4))
    ref = runs[0]["rows"]
    ax.plot([x["T"] for x in ref], [x["Z_ref"] for x in ref], "k-",
            label="interFoam VOF, instant release")
    ax.plot([x["T"] for x in ref], [x["Z_MartinMoyce"] for x in ref], "ks",
            label="Martin & Moyce (1952)")
    for r in runs:
        T = [x["T"] for x in r["rows"]]
        label = (f"ISPH a/dx = {r['a_over_dx']} (max {100 * r['max_abs_error_T_le_2.5']:.1f}%, "
                 f"{r['wall_s']:.0f} s)")
        line, = ax.plot(T, [x["Z"] for x in r["rows"]], "o--", ms=3, label=label)
        ax_err.plot(T, [100 * x["error"] for x in r["rows"]], "o--", ms=3, color=line.get_color(),
                    label=f"a/dx = {r['a_over_dx']}")
    ax.set_xlabel("T = t (2g/a)^1/2")
    ax.set_ylabel("front Z = x/a")
    ax.legend(fontsize=7)
    ax_err.axhspan(-5, 5, color="0.9")
    ax_err.axvline(2.5, color="0.6", lw=0.8)
    ax_err.set_xlabel("T")
    ax_err.set_ylabel("front vs instant-release reference [%]")
    ax_err.legend(fontsize=7)
    fig.suptitle("2D dam break: surge front against resolution")
    fig.tight_layout()
    fig.savefig(prefix + ".png", dpi=120)
    for r in runs:
        print(f"a/dx {r['a_over_dx']:3d}: |error| vs reference for T <= 2.5: mean "
              f"{100 * r['mean_abs_error_T_le_2.5']:.1f}%, max {100 * r['max_abs_error_T_le_2.5']:.1f}%"
              f" ({r['wall_s']:.0f} s)")


if __name__ == "__main__":
    sys.exit(main())
