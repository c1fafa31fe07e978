#!/usr/bin/python3
"""Plots the fluid particles of one isphdem snapshot (snap_<step>.h5) to a PNG.

Fluid particles (kind 0) and forcing/inflow particles (kind 3) are coloured by --field; walls and
dummies (kind 1) are light grey, PMS solid particles (kind 2) dark grey. 3-D snapshots are
projected onto --axes (default x-z, z up). Run with Debian's interpreter, which has h5py and
matplotlib:

    /usr/bin/python3 scripts/plot_fluid.py out/snap_00001200.h5 -o bed.png --field pressure \
        --quiver 10 --dem
"""
import argparse
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")  # files only; no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import EllipseCollection  # noqa: E402

FIELDS = {"speed": "speed |v| [m/s]", "pressure": "pressure [Pa]", "porosity": "porosity [-]"}
KIND_FLUID, KIND_WALL, KIND_SOLID, KIND_FORCING = 0, 1, 2, 3
AXIS = {"x": 0, "y": 1, "z": 2}


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("snapshot", help="snap_<step>.h5 written by isphdem")
    p.add_argument("-o", "--output", help="PNG to write (default: the snapshot's name, .png)")
    p.add_argument("--field", choices=sorted(FIELDS), default="speed",
                   help="colour fluid particles by this (default: speed)")
    p.add_argument("--quiver", type=int, default=0, metavar="N",
                   help="draw velocity arrows for one in N fluid particles (default: none)")
    p.add_argument("--axes", choices=["xy", "xz", "yz"],
                   help="plane to plot (default: xy in 2-D, xz in 3-D)")
    p.add_argument("--dem", action="store_true", help="outline DEM grains (/dem) as circles")
    p.add_argument("--dem-axes", choices=["xy", "xz", "yz"],
                   help="DEM coordinates (always 3-D) to draw in the plot plane (default: --axes)")
    p.add_argument("--clim", type=float, nargs=2, metavar=("MIN", "MAX"),
                   help="colour range (default: the data's)")
    p.add_argument("--dpi", type=int, default=150)
    p.add_argument("--slab", type=float, metavar="HALF_WIDTH",
                   help="3-D: plot only particles within HALF_WIDTH [m] of a plane normal to the "
                        "axis left out of --axes (default: all, projected)")
    p.add_argument("--slab-at", type=float, metavar="COORD",
                   help="position of that plane (default: the middle of the particles' range)")
    return p.parse_args(argv)


def read(path):
    with h5py.File(path, "r") as f:
        if "fluid" not in f or "position" not in f["fluid"]:
            raise SystemExit("plot_fluid: %s has no /fluid/position" % path)
        g = f["fluid"]
        data = {name: np.asarray(g[name]) for name in g}
        dem = None
        if "dem" in f and "position" in f["dem"] and "radius" in f["dem"]:
            dem = (np.asarray(f["dem/position"]), np.asarray(f["dem/radius"]))
        return float(f.attrs["time"]), int(f.attrs["step"]), data, dem


def field_values(data, field):
    if field == "speed":
        if "velocity" not in data:
            raise SystemExit("plot_fluid: no /fluid/velocity to compute speed from")
        return np.linalg.norm(np.atleast_2d(data["velocity"]), axis=1)
    if field not in data:
        raise SystemExit("plot_fluid: snapshot has no /fluid/%s" % field)
    return np.asarray(data[field], dtype=float).reshape(-1)


def typical_spacing(xy):
    """Median nearest-neighbour distance over a sample of particles (robust to empty regions)."""
    n = len(xy)
    if n < 2:
        return 1.0
    rng = np.random.default_rng(0)
    sample = xy[rng.choice(n, size=min(n, 300), replace=False)]
    nearest = np.full(len(sample), np.inf)
    for start in range(0, n, 10000):  # bounded memory (~50 MB) for millions of particles
        block = xy[start:start + 10000]
        d2 = ((sample[:, None, :] - block[None, :, :]) ** 2).sum(axis=2)
        d2[d2 == 0] = np.inf  # the particle itself (and exact duplicates)
        nearest = np.minimum(nearest, d2.min(axis=1))
    finite = nearest[np.isfinite(nearest)]
    return float(np.sqrt(np.median(finite))) if len(finite) else 1.0


def marker_area(ax, fig, spacing):
    """Scatter marker area (points^2) so that neighbouring particles about touch. Only valid once
    the layout is final: the equal aspect and the colour bar both shrink the axes."""
    fig.canvas.draw()
    xmin, xmax = ax.get_xlim()
    width_pts = ax.get_window_extent().width * 72.0 / fig.dpi
    return max((spacing / (xmax - xmin) * width_pts) ** 2, 0.5)


def main(argv):
    args = parse_args(argv)
    time, step, data, dem = read(args.snapshot)
    pos = np.atleast_2d(data["position"])
    dim = pos.shape[1]
    axes = args.axes or ("xy" if dim == 2 else "xz")
    cols = [AXIS[a] for a in axes]
    if max(cols) >= dim:
        raise SystemExit("plot_fluid: --axes %s needs 3-D positions" % axes)
    kind = np.asarray(data.get("kind", np.zeros(len(pos), dtype=int))).reshape(-1)
    values = field_values(data, args.field)
    vel_all = np.atleast_2d(data["velocity"]) if "velocity" in data else None
    if args.slab is not None and dim == 3:
        # A section instead of a projection: in a projection the fluid in front hides the bodies.
        normal = ({0, 1, 2} - set(cols)).pop()
        at = args.slab_at
        if at is None:
            at = 0.5 * (pos[:, normal].min() + pos[:, normal].max())
        keep = np.abs(pos[:, normal] - at) <= args.slab
        pos, kind, values = pos[keep], kind[keep], values[keep]
        if vel_all is not None:
            vel_all = vel_all[keep]
    xy = pos[:, cols]
    n = len(pos)
    coloured = (kind == KIND_FLUID) | (kind == KIND_FORCING)

    fig, ax = plt.subplots(figsize=(8, 6))
    ax.set_aspect("equal")
    spacing = typical_spacing(xy)
    if n:
        pad = max(0.02 * max(np.ptp(xy[:, 0]), np.ptp(xy[:, 1])), spacing, 1e-12)
        ax.set_xlim(xy[:, 0].min() - pad, xy[:, 0].max() + pad)
        ax.set_ylim(xy[:, 1].min() - pad, xy[:, 1].max() + pad)
    particles = []  # scatter plots, sized once the layout is known
    for k, colour in ((KIND_WALL, "0.75"), (KIND_SOLID, "0.35")):
        m = kind == k
        if m.any():
            particles.append(ax.scatter(xy[m, 0], xy[m, 1], c=colour, linewidths=0))
    if coloured.any():
        vmin, vmax = args.clim if args.clim else (None, None)
        sc = ax.scatter(xy[coloured, 0], xy[coloured, 1], c=values[coloured],
                        cmap="viridis", vmin=vmin, vmax=vmax, linewidths=0)
        particles.append(sc)
        fig.colorbar(sc, ax=ax, label=FIELDS[args.field])
    if args.quiver > 0 and vel_all is not None and coloured.any():
        vel = vel_all[:, cols]
        # A random 1/N subset: taking every N-th id draws stripes on lattice-ordered particles.
        fluid = np.flatnonzero(coloured)
        rng = np.random.default_rng(1)
        idx = np.sort(rng.choice(fluid, size=max(len(fluid) // args.quiver, 1), replace=False))
        ax.quiver(xy[idx, 0], xy[idx, 1], vel[idx, 0], vel[idx, 1], color="k", width=0.002)
    if args.dem and dem is not None and len(dem[1]):
        centres = np.atleast_2d(dem[0])[:, [AXIS[a] for a in (args.dem_axes or axes)]]
        d = 2 * np.asarray(dem[1]).reshape(-1)
        ax.add_collection(EllipseCollection(d, d, np.zeros_like(d), units="xy", offsets=centres,
                                            transOffset=ax.transData, facecolors="none",
                                            edgecolors="tab:brown", linewidths=0.6))
    if n:
        area = marker_area(ax, fig, spacing)
        for c in particles:
            c.set_sizes([area])
    ax.set_xlabel("%s [m]" % axes[0])
    ax.set_ylabel("%s [m]" % axes[1])
    ax.set_title("t = %.6g s (step %d): %s" % (time, step, args.field))
    out = args.output or os.path.splitext(args.snapshot)[0] + ".png"
    fig.savefig(out, dpi=args.dpi, bbox_inches="tight")
    plt.close(fig)
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
