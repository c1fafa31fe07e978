#!/usr/bin/python3
"""Error against cost from an `isphdem study` table: study.csv -> study.png.

One line per value of --series (e.g. coupling.model), |error| of --metric against the wall
time of each point, each point labelled with its --label value (e.g. particles.spacing).
Points that stopped early (blow-up, CFL stop) are drawn as crosses at their wall time on the
lower edge, so that a method's failures show on the same chart; points that never ran are listed
in the title.

usage: plot_study.py STUDY_CSV [-o PNG] [--metric NAME] [--series KEY] [--label KEY]
"""
import argparse
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("table")
    ap.add_argument("-o", "--output", default=None)
    ap.add_argument("--metric", default=None, help="a metric column of study.csv (default: the first)")
    ap.add_argument("--series", default=None)
    ap.add_argument("--label", default=None)
    args = ap.parse_args()
    with open(args.table, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_study: {args.table} has no points")
    columns = list(rows[0].keys())
    metrics = [c[: -len("_error")] for c in columns if c.endswith("_error")]
    metric = args.metric or (metrics[0] if metrics else None)
    if metric is None:
        sys.exit("plot_study: study.csv has no metric columns: the base case needs [reference]")
    if metric + "_error" not in columns:
        sys.exit(f"plot_study: no metric '{metric}' in {args.table} (it has: {', '.join(metrics)})")
    for key in (args.series, args.label):
        if key and key not in columns:
            sys.exit(f"plot_study: no column '{key}' in {args.table}")

    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    series = {}
    for r in rows:
        series.setdefault(r[args.series] if args.series else "", []).append(r)
    never = [r["point"] for r in rows if r["status"] not in ("finished", "stopped")]
    finite = [abs(number(r[metric + "_error"])) for r in rows if r["status"] == "finished"]
    finite = [e for e in finite if math.isfinite(e) and e > 0]
    floor = min(finite) / 3 if finite else 1e-6
    for name, points in series.items():
        done = [p for p in points if p["status"] == "finished"]
        done.sort(key=lambda p: number(p["wall_seconds"]))
        x = [number(p["wall_seconds"]) for p in done]
        y = [max(abs(number(p[metric + "_error"])), floor) for p in done]
        line, = ax.plot(x, y, "o-", label=name or metric)
        if args.label:
            for p, xi, yi in zip(done, x, y):
                ax.annotate(p[args.label], (xi, yi), textcoords="offset points", xytext=(4, 4),
                            fontsize=8)
        stopped = [p for p in points if p["status"] == "stopped"]
        if stopped:
            ax.plot([number(p["wall_seconds"]) for p in stopped], [floor] * len(stopped), "x",
                    color=line.get_color(), markersize=9, label=f"{name} stopped" if name else "stopped")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time per point [s]")
    ax.set_ylabel(f"|{metric} error|")
    title = f"{metric}: error against cost"
    if never:
        title += f"\n(not run: {', '.join(never)})"
    ax.set_title(title, fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(title=args.series, fontsize=8)
    fig.tight_layout()
    out = args.output or args.table.rsplit(".", 1)[0] + ".png"
    fig.savefig(out, dpi=120)
    print(f"plot_study: {out}")


if __name__ == "__main__":
    main()
