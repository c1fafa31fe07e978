#!/usr/bin/python3
"""Error against cost from an `isphdem study` table: study.csv -> study.png.

One line per value of --series (e.g. coupling.model), |error| of --metric against the wall
time of each point, each point labelled with its --label value (e.g. particles.spacing).
Points that stopped early (blow-up, CFL stop) are drawn as crosses at their wall time on the
lower edge, so that a method's failures show on the same chart; points that never ran are listed
in the title. With --reference POINT (the study's `reference`), the errors are against that
point, which is drawn apart as a star on the lower edge.

With --stability X Y it draws instead how every point ended over two varied keys (e.g.
particles.spacing and time.cfl), one panel per value of --series (e.g. coupling.model): finished
points as dots, stopped ones marked by their cause (CFL stop, NaN, pressure solve, porosity out of
range, fluid or grain leaving its domain, grain overlap growth, energy growth), refused ones as
squares, and the stability boundary between the largest finished and the smallest stopped Y at
each X.

With --convergence KEY (e.g. time.dt) it draws every metric (or --metric) against KEY, one line
per combination of the other varied keys (those that change together with KEY, such as
dem.substeps with time.dt, are left out of it), with the observed order of convergence from the
three smallest values of KEY and each point's departure from the smallest's value and from the
Richardson extrapolation to KEY -> 0; the numbers go to a CSV beside the PNG.

usage: plot_study.py STUDY_CSV [-o PNG] [--metric NAME] [--series KEY] [--label KEY]
                     [--reference POINT]
       plot_study.py STUDY_CSV --stability X Y [-o PNG]
       plot_study.py STUDY_CSV --convergence KEY [-o PNG] [--metric NAME]
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


def metric_names(columns):
    # study.csv: each metric as <name>, <name>_expected, <name>_error.
    return [c[: -len("_error")] for c in columns if c.endswith("_error")]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("table")
    ap.add_argument("-o", "--output", default=None)
    ap.add_argument("--metric", default=None, help="a metric column of study.csv (default: the first)")
    ap.add_argument("--series", default=None)
    ap.add_argument("--label", default=None)
    ap.add_argument("--reference", default=None, help="the point the errors are measured against")
    ap.add_argument("--stability", nargs=2, metavar=("X", "Y"), default=None)
    ap.add_argument("--convergence", metavar="KEY", default=None)
    args = ap.parse_args()
    with open(args.table, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_study: {args.table} has no points")
    columns = list(rows[0].keys())
    if args.stability:
        return stability(args, rows, columns)
    if args.convergence:
        return convergence(args, rows, columns)
    metrics = metric_names(columns)
    metric = args.metric or (metrics[0] if metrics else None)
    if metric is None:
        sys.exit("plot_study: study.csv has no metric columns: the base case needs [reference]")
    if metric + "_error" not in columns:
        sys.exit(f"plot_study: no metric '{metric}' in {args.table} (it has: {', '.join(metrics)})")
    for key in (args.series, args.label):
        if key and key not in columns:
            sys.exit(f"plot_study: no column '{key}' in {args.table}")

    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    reference = [r for r in rows if r["point"] == args.reference]
    rows = [r for r in rows if r["point"] != args.reference]
    series = {}
    for r in rows:
        series.setdefault(r[args.series] if args.series else "", []).append(r)
    never = [r["point"] for r in rows if r["status"] not in ("finished", "stopped")]
    finite = [abs(number(r[metric + "_error"])) for r in rows if r["status"] == "finished"]
    finite = [e for e in finite if math.isfinite(e) and e > 0]
    floor = min(finite) / 3 if finite else 1e-6
    for name, points in series.items():
        done = [p for p in points if p["status"] == "finished"
                and math.isfinite(number(p[metric + "_error"]))]
        done.sort(key=lambda p: number(p["wall_seconds"]))
        x = [number(p["wall_seconds"]) for p in done]
        y = [max(abs(number(p[metric + "_error"])), floor) for p in done]
        # Points that leave the series key at the base case's value have no value in the table.
        shown = name or ("as in the case" if args.series else metric)
        line, = ax.plot(x, y, "o-", label=shown)
        if args.label:
            for p, xi, yi in zip(done, x, y):
                ax.annotate(p[args.label], (xi, yi), textcoords="offset points", xytext=(4, 4),
                            fontsize=8)
        stopped = [p for p in points if p["status"] == "stopped"]
        if stopped:
            ax.plot([number(p["wall_seconds"]) for p in stopped], [floor] * len(stopped), "x",
                    color=line.get_color(), markersize=9, label=f"{name} stopped" if name else "stopped")
    for r in reference:
        ax.plot([number(r["wall_seconds"])], [floor], "*", color="black", markersize=12,
                label=f"reference: {r['point']}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time per point [s]")
    ax.set_ylabel(f"|{metric} error|" + (f" against {args.reference}" if reference else ""))
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


# Stopped points by their cause (result.json "cause", study.csv column "cause").
CAUSES = {
    "cfl": ("x", "tab:red", "CFL stop"),
    "nan": ("X", "darkred", "NaN"),
    "pressure_solver": ("P", "tab:purple", "pressure solve failed"),
    "porosity": ("v", "tab:brown", "porosity out of range"),
    "fluid_left_domain": ("<", "tab:orange", "fluid left the domain"),
    "grain_lost": (">", "tab:pink", "grain left the DEM box"),
    "grain_overlap": ("D", "tab:olive", "grain overlap growth"),
    "energy_growth": ("^", "tab:cyan", "energy growth"),
}


def stability_panel(ax, rows, xkey, ykey, shown):
    for r in rows:
        x, y = number(r[xkey]), number(r[ykey])
        if not (math.isfinite(x) and math.isfinite(y)):
            continue
        if r["status"] == "finished":
            marker, color, label = "o", "tab:green", "finished"
        elif r["status"] == "stopped":
            cause = r.get("cause", "") or "other"
            marker, color, label = CAUSES.get(cause, ("x", "black", f"stopped ({cause})"))
        elif r["status"] == "error":
            marker, color, label = "s", "tab:gray", "refused at start"
        else:
            marker, color, label = "^", "black", r["status"]
        ax.plot([x], [y], marker, color=color, markersize=9, linestyle="none",
                label=None if label in shown else label)
        shown.add(label)
    # The boundary: at each X, between the finished Ys and the others, on whichever side of them
    # the finished ones lie (small steps stable; or, for a density, large values stable).
    xs = sorted({number(r[xkey]) for r in rows})
    bx, by = [], []

    def between(a, b):
        return math.sqrt(a * b) if a > 0 else 0.5 * b

    for x in xs:
        at = [r for r in rows if number(r[xkey]) == x]
        ok = [number(r[ykey]) for r in at if r["status"] == "finished"]
        bad = [number(r[ykey]) for r in at if r["status"] != "finished"]
        if not (ok and bad):
            continue
        if max(ok) < min(bad):
            bx.append(x)
            by.append(between(max(ok), min(bad)))
        elif max(bad) < min(ok):
            bx.append(x)
            by.append(between(max(bad), min(ok)))
    if bx:
        label = "stability boundary"
        ax.plot(bx, by, "--", color="black", marker="_", markersize=24,
                label=None if label in shown else label)
        shown.add(label)
    for key, setter in ((xkey, ax.set_xscale), (ykey, ax.set_yscale)):
        values = [number(r[key]) for r in rows]
        if values and all(v > 0 for v in values) and max(values) / min(values) >= 4:
            setter("log")
    ax.set_xlabel(xkey)
    ax.grid(True, which="both", alpha=0.3)


def stability(args, rows, columns):
    """How each point ended over X and Y, one panel per value of --series (e.g. the model)."""
    xkey, ykey = args.stability
    for key in (xkey, ykey) + ((args.series,) if args.series else ()):
        if key not in columns:
            sys.exit(f"plot_study: no column '{key}' in {args.table}")
    groups = {}
    for r in rows:
        groups.setdefault(r[args.series] if args.series else "", []).append(r)
    fig, axes = plt.subplots(1, len(groups), figsize=(5.2 * len(groups) + 1.2, 4.6), squeeze=False,
                             sharey=True)
    shown = set()
    for ax, (name, points) in zip(axes[0], groups.items()):
        stability_panel(ax, points, xkey, ykey, shown)
        ax.set_title(f"{args.series} = {name}" if args.series else "how each point ended",
                     fontsize=10)
    axes[0][0].set_ylabel(ykey)
    # Each label is drawn once, in whichever panel had it first: gather them all for one legend.
    handles, labels = [], []
    for ax in axes[0]:
        for h, l in zip(*ax.get_legend_handles_labels()):
            if l not in labels:
                handles.append(h)
                labels.append(l)
    axes[0][-1].legend(handles, labels, fontsize=8, loc="best")
    fig.tight_layout()
    out = args.output or args.table.rsplit(".", 1)[0] + "_stability.png"
    fig.savefig(out, dpi=120)
    print(f"plot_study: {out}")


def observed_order(h, f):
    """Order p of f(h) = f0 + C h^p through three points, h[0] < h[1] < h[2]; nan if the
    differences change sign (not in the asymptotic range) or vanish."""
    d1, d2 = f[1] - f[0], f[2] - f[1]
    if d1 == 0 or d2 == 0 or (d1 > 0) != (d2 > 0):
        return math.nan
    target = d2 / d1

    def ratio(p):
        return (h[2] ** p - h[1] ** p) / (h[1] ** p - h[0] ** p)

    lo, hi = 0.05, 8.0  # ratio(p) grows with p
    if not ratio(lo) <= target <= ratio(hi):
        return math.nan
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if ratio(mid) < target else (lo, mid)
    return 0.5 * (lo + hi)


def varied_keys(columns):
    # study.csv: point, the varied keys, then status and the results.
    return columns[columns.index("point") + 1: columns.index("status")]


def convergence(args, rows, columns):
    """Each metric against --convergence KEY, a line per combination of the other varied keys."""
    key = args.convergence
    if key not in columns:
        sys.exit(f"plot_study: no column '{key}' in {args.table}")
    metrics = metric_names(columns)
    if args.metric:
        if args.metric not in metrics:
            sys.exit(f"plot_study: no metric '{args.metric}' in {args.table}")
        metrics = [args.metric]
    if not metrics:
        sys.exit("plot_study: study.csv has no metric columns: the base case needs [reference]")
    # Keys that change with KEY and only with it (dem.substeps with time.dt) do not split lines.
    others = []
    for k in varied_keys(columns):
        if k == key:
            continue
        by_key = {}
        if not all(by_key.setdefault(r[key], r[k]) == r[k] for r in rows):
            others.append(k)
    groups = {}
    for r in rows:
        name = ", ".join(f"{k.split('.')[-1]} {r[k]}" for k in others) or "all points"
        groups.setdefault(name, []).append(r)
    ncol = min(3, len(metrics))
    nrow = (len(metrics) + ncol - 1) // ncol
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.6 * ncol, 3.6 * nrow + 0.8), squeeze=False)
    table = []
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for ax, metric in zip(axes.flat, metrics):
        allv, orders = [], []
        for g, (name, points) in enumerate(groups.items()):
            color = colors[g % len(colors)]
            done = [(number(p[key]), number(p[metric]), p) for p in points
                    if p["status"] == "finished" and math.isfinite(number(p[metric]))
                    and math.isfinite(number(p[key]))]
            done.sort(key=lambda t: t[0])
            if not done:
                continue
            h = [t[0] for t in done]
            f = [t[1] for t in done]
            order = observed_order(h[:3], f[:3]) if len(done) >= 3 else math.nan
            limit = math.nan
            if math.isfinite(order):
                limit = f[0] - (f[1] - f[0]) / ((h[1] / h[0]) ** order - 1)
            for _, fi, p in done:
                table.append({"group": name, "metric": metric, key: p[key], "point": p["point"],
                              "value": fi,
                              "departure_from_finest": (fi - f[0]) / f[0] if f[0] else math.nan,
                              "departure_from_extrapolated":
                                  (fi - limit) / limit if math.isfinite(limit) and limit else math.nan,
                              "observed_order": order, "extrapolated": limit})
            orders.append(f"{order:.2f}" if math.isfinite(order) else "-")
            ax.plot(h, f, "o-", color=color, label=name)
            if math.isfinite(limit):
                ax.axhline(limit, color=color, linestyle=":", linewidth=1)
            stopped = [number(p[key]) for p in points if p["status"] == "stopped"]
            if stopped:
                ax.plot(stopped, [f[-1]] * len(stopped), "x", color=color, markersize=9,
                        label=f"{name}: stopped")
            allv += f
        ax.set_xscale("log")
        if allv and min(allv) > 0 and max(allv) / min(allv) >= 10:
            ax.set_yscale("log")
        ax.set_xlabel(key)
        ax.set_title(f"{metric} (p: {', '.join(orders)})", fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
    for ax in list(axes.flat)[len(metrics):]:
        ax.set_visible(False)
    # The lines are the same groups in every panel, in the same colours: one legend below.
    handles, labels = [], []
    for ax in axes.flat:
        for hnd, lab in zip(*ax.get_legend_handles_labels()):
            if lab not in labels:
                handles.append(hnd)
                labels.append(lab)
    fig.legend(handles, labels, loc="lower center", ncol=min(4, len(labels)), fontsize=8)
    fig.suptitle(f"metrics against {key}; dotted: the extrapolation to {key} -> 0; p: the observed "
                 "order from the three smallest, per line in legend order (-: not monotone)",
                 fontsize=9)
    fig.tight_layout(rect=(0, 0.04 + 0.02 * ((len(labels) - 1) // 4), 1, 1))
    out = args.output or args.table.rsplit(".", 1)[0] + "_convergence.png"
    fig.savefig(out, dpi=110)
    csv_out = out.rsplit(".", 1)[0] + ".csv"
    with open(csv_out, "w", newline="") as f:
        fields = ["group", "metric", key, "point", "value", "departure_from_finest",
                  "departure_from_extrapolated", "observed_order", "extrapolated"]
        w = csv.DictWriter(f, fieldnames=fields, lineterminator="\n")
        w.writeheader()
        for row in table:
            w.writerow({k: (f"{v:.10g}" if isinstance(v, float) else v) for k, v in row.items()})
    print(f"plot_study: {out}, {csv_out}")


if __name__ == "__main__":
    main()
