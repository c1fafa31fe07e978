#!/usr/bin/python3
"""Grains over the fluid-speed field, as in the seed's Figs. 3 and 4.

Reads an isphdem output directory (snap_*.h5). Fine grains (body = -1) are drawn orange, clump
spheres grey, at their true radius in the x-y plane; fluid particles (kinds 0 and 3) are coloured
by |v| / v_in (or |v| without --vin); the paths of randomly chosen fluid particles are drawn
from the first snapshot to the one shown. Grains only (a dry run) works too.

usage: plot_erosion.py OUT_DIR [--times T ...] [--vin V] [--png FILE] [--frames DIR]
                       [--gif FILE] [--paths N] [--xlim A B] [--ylim A B] [--vmax X]
  --png     a panel figure of the snapshots nearest to --times (default: 4 evenly spaced)
  --frames  one PNG per snapshot into DIR (frame_0000.png, ...)
  --gif     an animation of all snapshots (every --every-th)
"""
import argparse
import glob
import os
import sys

import h5py
import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PatchCollection
from matplotlib.patches import Circle


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


def draw(ax, d, args, paths=None, index=0):
    ax.set_facecolor("#f4f4f4")
    mappable = None
    if "fx" in d:
        wet = (d["fkind"] == 0) | (d["fkind"] == 3)
        speed = d["fv"][wet] / (args.vin if args.vin else 1.0)
        vmax = args.vmax or (np.percentile(speed, 99.5) if len(speed) else 1.0)
        mappable = ax.scatter(d["fx"][wet, 0] * 1e3, d["fx"][wet, 1] * 1e3, c=speed, s=3,
                              cmap="viridis", vmin=0, vmax=vmax, linewidths=0)
        walls = d["fkind"] == 1
        ax.scatter(d["fx"][walls, 0] * 1e3, d["fx"][walls, 1] * 1e3, c="k", s=1.5, linewidths=0)
        solid = d["fkind"] == 2
        ax.scatter(d["fx"][solid, 0] * 1e3, d["fx"][solid, 1] * 1e3, c="#555555", s=2,
                   linewidths=0)
    if "gx" in d:
        fines = d["gbody"] < 0
        for sel, colour in ((~fines, "#8c8c8c"), (fines, "#ff8c1a")):
            circles = [Circle((x * 1e3, y * 1e3), r * 1e3) for (x, y), r in
                       zip(d["gx"][sel], d["gr"][sel])]
            ax.add_collection(PatchCollection(circles, facecolor=colour, edgecolor="k",
                                              linewidths=0.2, alpha=0.95))
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


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out_dir")
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
    args = ap.parse_args()
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
