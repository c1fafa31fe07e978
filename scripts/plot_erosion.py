#!/usr/bin/python3
"""Grains over the fluid-speed field, as in the seed's Figs. 3 and 4; two or more runs side by side.

Reads isphdem output directories (snap_*.h5). Fine grains (body = -1) are drawn orange, clump
spheres grey, at their true radius in the x-y plane; fluid particles (kinds 0 and 3) are coloured
by |v| / v_in (or |v| without --vin); the paths of randomly chosen fluid particles are drawn
from the first snapshot to the one shown. Grains only (a dry run) works too.

usage: plot_erosion.py OUT_DIR [OUT_DIR ...] [--times T ...] [--vin V] [--png FILE]
                       [--frames DIR] [--gif FILE] [--paths N] [--xlim A B] [--ylim A B]
                       [--vmax X] [--labels NAME ...] [--title TEXT] [--summary FILE]
  one OUT_DIR:
  --png     a panel figure of the snapshots nearest to --times (default: 4 evenly spaced)
  --frames  one PNG per snapshot into DIR (frame_0000.png, ...)
  --gif     an animation of all snapshots (every --every-th)
  two or more OUT_DIRs (the same case under different settings, e.g. the coupling models):
  --png     one panel per run side by side at the snapshot nearest to --times (default: the
            last), one colour scale for all (--vmax, default the largest 99.5th percentile),
            a legend for fines, coarse grains and PMS particles; titles from --labels (default
            coupling.model of case_used.toml) and the run's pore_jet metric (result.json)
  --gif     the same side by side for every --every-th snapshot
  --summary five lines, printed and written to FILE: the runs' pore jets (result.json pore_jet),
            fines moved more than --moved mm (first to last snapshot, by grain id), the surface
            rise (surface_rise) and the wall time. v_in defaults to inflow.velocity of
            case_used.toml.
"""
import argparse
import glob
import json
import os
import sys

import h5py
import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PatchCollection
from matplotlib.lines import Line2D
from matplotlib.patches import Circle, Patch


def snapshots(out_dir):
    files = sorted(glob.glob(os.path.join(out_dir, "snap_*.h5")))
    if not files:
        sys.exit(f"plot_erosion.py: no snap_*.h5 in {out_dir}")
    times = []
    for f in files:
        with h5py.File(f, "r") as h:
            times.append(float(h.attrs["time"]))
    return files, np.array(times)


def read(path):
    with h5py.File(path, "r") as h:
        d = {"time": float(h.attrs["time"])}
        if "fluid" in h:
            d["fx"] = h["/fluid/position"][...][:, :2]
            d["fv"] = np.linalg.norm(h["/fluid/velocity"][...], axis=1)
            d["fkind"] = h["/fluid/kind"][...]
            d["fid"] = h["/fluid/id"][...]
        if "dem" in h:
            d["gx"] = h["/dem/position"][...][:, :2]
            d["gr"] = h["/dem/radius"][...]
            d["gbody"] = h["/dem/body"][...]
    return d


class Paths:
    """Positions of chosen fluid particles (by id) over all snapshots."""

    def __init__(self, files, n, seed=1):
        self.track = {}
        first = read(files[0])
        if n <= 0 or "fid" not in first:
            return
        ids = first["fid"][first["fkind"] == 0]
        rng = np.random.default_rng(seed)
        chosen = rng.choice(ids, size=min(n, len(ids)), replace=False)
        self.track = {int(i): [] for i in chosen}
        for f in files:
            d = read(f)
            index = {int(i): k for k, i in enumerate(d["fid"])}
            for i in self.track:
                k = index.get(i)
                self.track[i].append(d["fx"][k] if k is not None else (np.nan, np.nan))

    def draw(self, ax, upto):
        for p in self.track.values():
            p = np.array(p[: upto + 1])
            ax.plot(p[:, 0] * 1e3, p[:, 1] * 1e3, "-", color="white", lw=0.6, alpha=0.9)
            ax.plot(p[-1, 0] * 1e3, p[-1, 1] * 1e3, "o", color="white", ms=1.5)


def draw(ax, d, args, paths=None, index=0, fluid_size=3, vin=None, see_through=False):
    """see_through: grains drawn translucent (fines as orange rings) over the fluid, so that the
    pore water's speed shows between and under them."""
    ax.set_facecolor("#f4f4f4")
    mappable = None
    vin = vin if vin is not None else args.vin
    if "fx" in d:
        wet = (d["fkind"] == 0) | (d["fkind"] == 3)
        speed = d["fv"][wet] / (vin if vin else 1.0)
        vmax = args.vmax or (np.percentile(speed, 99.5) if len(speed) else 1.0)
        mappable = ax.scatter(d["fx"][wet, 0] * 1e3, d["fx"][wet, 1] * 1e3, c=speed,
                              s=fluid_size, marker="s" if fluid_size > 3 else "o",
                              cmap="viridis", vmin=0, vmax=vmax, linewidths=0)
        walls = d["fkind"] == 1
        ax.scatter(d["fx"][walls, 0] * 1e3, d["fx"][walls, 1] * 1e3,
                   c="#b0b0b0" if see_through else "k",
                   s=fluid_size if see_through else max(1.5, fluid_size / 2),
                   marker="s" if see_through else "o", linewidths=0)
        solid = d["fkind"] == 2
        ax.scatter(d["fx"][solid, 0] * 1e3, d["fx"][solid, 1] * 1e3, c="#555555",
                   s=max(2, fluid_size / 3), linewidths=0)
    if "gx" in d:
        fines = d["gbody"] < 0
        for sel, colour in ((~fines, "#8c8c8c"), (fines, "#ff8c1a")):
            circles = [Circle((x * 1e3, y * 1e3), r * 1e3) for (x, y), r in
                       zip(d["gx"][sel], d["gr"][sel])]
            if not see_through:
                style = dict(facecolor=colour, edgecolor="k", linewidths=0.2, alpha=0.95)
            elif colour == "#8c8c8c":
                style = dict(facecolor=(0.55, 0.55, 0.55, 0.45), edgecolor=(0.3, 0.3, 0.3, 0.8),
                             linewidths=0.4)
            else:
                style = dict(facecolor=(1.0, 0.55, 0.1, 0.25), edgecolor="#ff7f00",
                             linewidths=1.6)
            ax.add_collection(PatchCollection(circles, **style))
    if paths is not None:
        paths.draw(ax, index)
    ax.set_aspect("equal")
    if args.xlim:
        ax.set_xlim(*args.xlim)
    if args.ylim:
        ax.set_ylim(*args.ylim)
    ax.set_title(f"t = {d['time']:.2f} s", fontsize=9)
    ax.set_xlabel("x [mm]")
    return mappable


def colourbar(fig, ax, mappable, args):
    if mappable is not None:
        fig.colorbar(mappable, ax=ax, shrink=0.8,
                     label="|v| / v_in" if args.vin else "|v| [m/s]")


# --- two or more runs side by side ----------------------------------------------------------

def case_used(out_dir):
    try:
        import tomllib
        with open(os.path.join(out_dir, "case_used.toml"), "rb") as f:
            return tomllib.load(f)
    except (ImportError, OSError, ValueError):
        return {}


def result(out_dir):
    try:
        with open(os.path.join(out_dir, "result.json")) as f:
            r = json.load(f)
    except (OSError, ValueError):
        return {}
    r["metric"] = {m["name"]: m.get("value") for m in r.get("metrics", [])}
    return r


class Run:
    def __init__(self, out_dir, label, args):
        self.dir = out_dir
        self.files, self.times = snapshots(out_dir)
        case = case_used(out_dir)
        self.label = label or case.get("coupling", {}).get("model") or os.path.basename(
            os.path.normpath(out_dir))
        self.vin = args.vin or case.get("inflow", {}).get("velocity")
        self.dx = case.get("particles", {}).get("spacing")
        self.result = result(out_dir)
        self.paths = Paths(self.files, args.paths)

    def nearest(self, t):
        return int(np.argmin(np.abs(self.times - t)))


MODELS = {"unresolved": ": every grain as porosity + drag",
          "semi-resolved": ": coarse grains resolved (PMS)",
          "resolved": ": every grain resolved (PMS)"}

LEGEND = [
    Patch(facecolor=(1.0, 0.55, 0.1, 0.25), edgecolor="#ff7f00", linewidth=1.6,
          label="fine grain (1 mm sphere)"),
    Patch(facecolor=(0.55, 0.55, 0.55, 0.45), edgecolor=(0.3, 0.3, 0.3, 0.8), linewidth=0.4,
          label="coarse grain (clump of 1 mm spheres)"),
    Line2D([], [], marker="o", ls="", color="#555555", ms=3,
           label="PMS solid particle (coarse grain resolved)"),
    Line2D([], [], marker="s", ls="", color="#b0b0b0", ms=5, label="wall"),
]


def fluid_marker_size(fig, ax, dx):
    """Area in pt^2 of a square marker dx wide (the fluid as a continuous field)."""
    if not dx:
        return 3
    ax.apply_aspect()
    width_pt = ax.get_window_extent().width * 72.0 / fig.dpi
    x0, x1 = ax.get_xlim()
    return (dx * 1e3 * width_pt / (x1 - x0)) ** 2


def common_vmax(runs, picks):
    tops = []
    for run, k in zip(runs, picks):
        d = read(run.files[k])
        if "fx" in d:
            wet = (d["fkind"] == 0) | (d["fkind"] == 3)
            tops.append(np.percentile(d["fv"][wet] / (run.vin or 1.0), 99.5))
    return max(tops) if tops else 1.0


def compare_figure(runs, picks, args, title=None, metric=True):
    n = len(runs)
    fig, axes = plt.subplots(1, n, figsize=(4.2 * n + 1.2, 5.4), squeeze=False)
    top = 0.86 if title else 0.9
    fig.subplots_adjust(left=0.07, right=0.87, bottom=0.2, top=top, wspace=0.12)
    axes = axes[0]
    m = None
    for ax, run, k in zip(axes, runs, picks):
        d = read(run.files[k])
        # Limits first, so that the fluid's markers can be sized to one spacing.
        xs = [d[c][:, 0] for c in ("fx", "gx") if c in d]
        ys = [d[c][:, 1] for c in ("fx", "gx") if c in d]
        ax.set_aspect("equal")
        ax.set_xlim(*(args.xlim or (1e3 * min(map(np.min, xs)), 1e3 * max(map(np.max, xs)))))
        ax.set_ylim(*(args.ylim or (1e3 * min(map(np.min, ys)), 1e3 * max(map(np.max, ys)))))
        size = fluid_marker_size(fig, ax, 1.25 * run.dx if run.dx else None)
        m = draw(ax, d, args, run.paths, k, fluid_size=size, vin=run.vin, see_through=True) or m
        jet = run.result.get("metric", {}).get("pore_jet")
        sub = f"pore jets {jet:.1f} v_in" if metric and isinstance(jet, (int, float)) else ""
        what = MODELS.get(run.label, "")
        ax.set_title(f"{run.label}{what}\nt = {d['time']:.2f} s   {sub}", fontsize=10)
    axes[0].set_ylabel("y [mm]")
    if m is not None:
        unit = "|v| / v_in" if all(r.vin for r in runs) else "|v| [m/s]"
        fig.colorbar(m, cax=fig.add_axes([0.89, 0.22, 0.015, top - 0.26]),
                     label=f"fluid speed {unit} (same scale in every panel)")
    fig.legend(handles=LEGEND, loc="lower center", ncol=2, fontsize=9, frameon=False,
               bbox_to_anchor=(0.45, 0.0))
    if title:
        fig.suptitle(title, fontsize=11)
    return fig


def fines_moved(run, threshold):
    """Fines (body < 0) whose centre moved more than threshold [m] from the first snapshot to the
    last, matched by id; and how many fines there are."""
    def fines(path):
        with h5py.File(path, "r") as h:
            if "dem" not in h:
                return {}
            ids, x, body = h["/dem/id"][...], h["/dem/position"][...], h["/dem/body"][...]
        return {int(i): p for i, p, b in zip(ids, x, body) if b < 0}
    a, b = fines(run.files[0]), fines(run.files[-1])
    moved = sum(1 for i, p in a.items() if i not in b or np.linalg.norm(b[i] - p) > threshold)
    return moved, len(a)


def shown(path):
    """path relative to the working directory when it lies under it."""
    rel = os.path.relpath(path)
    return path if rel.startswith("..") else rel


def summary(runs, args):
    def each(fmt):
        return ", ".join(f"{r.label} {fmt(r)}" for r in runs)

    def metric(r, name):
        v = r.result.get("metric", {}).get(name)
        return v if isinstance(v, (int, float)) else float("nan")

    def wall(r):
        w = r.result.get("wall_seconds", float("nan"))
        return f"{int(w // 60)} min {w % 60:02.0f} s" if w == w else "?"

    t = max(r.times[-1] for r in runs)
    vin = runs[0].vin
    head = f"{len(runs)} runs to t = {t:.2f} s" + (f" at v_in = {100 * vin:g} cm/s" if vin else "")
    moved = {r.label: fines_moved(r, args.moved * 1e-3) for r in runs}
    lines = [
        head + " (" + shown(os.path.commonpath([os.path.abspath(r.dir) for r in runs])) + ")",
        "pore jets (fastest pore water in the layer / v_in, mean after 0.1 s): "
        + each(lambda r: f"{metric(r, 'pore_jet'):.1f}"),
        f"fines moved more than {args.moved:g} mm: "
        + each(lambda r: "{} of {}".format(*moved[r.label])),
        "layer surface rise: " + each(lambda r: f"{1e3 * metric(r, 'surface_rise'):.2f} mm"),
        "wall time: " + each(wall),
    ]
    text = "\n".join(lines) + "\n"
    print(text, end="")
    with open(args.summary, "w") as f:
        f.write(text)


def compare(args):
    runs = [Run(d, (args.labels or [None] * len(args.out_dirs))[i], args)
            for i, d in enumerate(args.out_dirs)]
    t_last = min(r.times[-1] for r in runs)
    if args.png or not (args.gif or args.summary):
        t = (args.times or [t_last])[0]
        picks = [r.nearest(t) for r in runs]
        if not args.vmax:
            args.vmax = common_vmax(runs, picks)
        fig = compare_figure(runs, picks, args, args.title)
        out = args.png or os.path.join(args.out_dirs[0], "compare.png")
        fig.savefig(out, dpi=110, bbox_inches="tight")
        plt.close(fig)
        print(f"wrote {out}")
    if args.gif:
        from PIL import Image
        times = [t for t in runs[0].times if t <= t_last + 1e-9][:: args.every]
        if not args.vmax:
            args.vmax = common_vmax(runs, [r.nearest(t_last) for r in runs])
        frames = []
        for t in times:
            fig = compare_figure(runs, [r.nearest(t) for r in runs], args, args.title,
                                 metric=False)
            fig.canvas.draw()
            frames.append(Image.fromarray(np.asarray(fig.canvas.buffer_rgba())).convert(
                "RGB").convert("P", palette=Image.ADAPTIVE))
            plt.close(fig)
        frames[0].save(args.gif, save_all=True, append_images=frames[1:], duration=250, loop=0)
        print(f"wrote {args.gif} ({len(frames)} frames)")
    if args.summary:
        summary(runs, args)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out_dirs", nargs="+", metavar="OUT_DIR")
    ap.add_argument("--times", type=float, nargs="*")
    ap.add_argument("--vin", type=float)
    ap.add_argument("--vmax", type=float)
    ap.add_argument("--png")
    ap.add_argument("--frames")
    ap.add_argument("--gif")
    ap.add_argument("--every", type=int, default=1)
    ap.add_argument("--paths", type=int, default=12)
    ap.add_argument("--xlim", type=float, nargs=2)
    ap.add_argument("--ylim", type=float, nargs=2)
    ap.add_argument("--labels", nargs="+")
    ap.add_argument("--summary")
    ap.add_argument("--title", help="a title over the side-by-side panels")
    ap.add_argument("--moved", type=float, default=0.5,
                    help="--summary counts fines that moved more than this [mm]")
    args = ap.parse_args()
    if len(args.out_dirs) > 1 or args.summary:
        compare(args)
        return
    args.out_dir = args.out_dirs[0]
    files, times = snapshots(args.out_dir)
    paths = Paths(files, args.paths)

    if args.png or not (args.frames or args.gif):
        wanted = args.times or list(np.linspace(times[0], times[-1], 4))
        picks = [int(np.argmin(np.abs(times - t))) for t in wanted]
        fig, axes = plt.subplots(1, len(picks), figsize=(3.2 * len(picks) + 1, 3.6),
                                 squeeze=False)
        m = None
        for ax, k in zip(axes[0], picks):
            m = draw(ax, read(files[k]), args, paths, k) or m
        axes[0][0].set_ylabel("y [mm]")
        colourbar(fig, axes[0].tolist(), m, args)
        out = args.png or os.path.join(args.out_dir, "erosion.png")
        fig.savefig(out, dpi=130, bbox_inches="tight")
        print(f"wrote {out}")

    if args.frames or args.gif:
        frames_dir = args.frames or os.path.join(args.out_dir, "frames")
        os.makedirs(frames_dir, exist_ok=True)
        written = []
        for n, k in enumerate(range(0, len(files), args.every)):
            fig, ax = plt.subplots(figsize=(5, 4.2))
            colourbar(fig, ax, draw(ax, read(files[k]), args, paths, k), args)
            ax.set_ylabel("y [mm]")
            path = os.path.join(frames_dir, f"frame_{n:04d}.png")
            fig.savefig(path, dpi=100)
            plt.close(fig)
            written.append(path)
        print(f"wrote {len(written)} frames to {frames_dir}")
        if args.gif:
            from PIL import Image
            images = [Image.open(p).convert("P", palette=Image.ADAPTIVE) for p in written]
            images[0].save(args.gif, save_all=True, append_images=images[1:], duration=120,
                           loop=0)
            print(f"wrote {args.gif}")


if __name__ == "__main__":
    main()
