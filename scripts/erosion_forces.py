#!/usr/bin/python3
"""Why a fine does or does not erupt (docs/internal_erosion.md): for the free fines whose top lies
within DEPTH of the initial layer surface (the median over 2 mm columns of the highest grain top,
as surface_height in diagnostics.csv) or above it, the vertical fluid force against the grain's weight,
the pore speed around them, and how fast they move, at every snapshot of a coupled run.

force_hydro holds the drag and -grad p V (buoyancy included), so F_y / (m g) > 1 means the fluid
alone would lift the fine: its contacts (the grains on top of it, and friction) then hold it
down by m g - F_y, since it does not accelerate; fines_lifted_covered counts the lifted fines with
a grain touching them from above. The single-sphere terminal speed (Schiller-
Naumann drag, the fine in clear water) is the pore speed a fine above the surface needs to rise.

Writes OUT/erosion_forces.csv (one row per snapshot) and prints a summary over the snapshots
after SETTLED s (the clumps at the surface rearrange in the first 0.3 s). 2D runs: up is y.
usage: erosion_forces.py OUT --vin V [--depth 0.003] [--rho-s 2600] [--rho 1000] [--nu 1e-6]
"""
import argparse
import csv
import glob
import math
import os
import re
import sys

import h5py
import numpy as np


SETTLED = 0.25  # s


def terminal_speed(d, rho_s, rho, nu, g=9.81):
    """Settling speed of one sphere in clear fluid, Schiller-Naumann C_d (Re < 800)."""
    lo, hi = 1e-6, 10.0
    weight = (rho_s - rho) * g * math.pi * d ** 3 / 6.0
    for _ in range(200):
        u = 0.5 * (lo + hi)
        re = u * d / nu
        cd = 24.0 / re * (1.0 + 0.15 * re ** 0.687)
        drag = 0.5 * rho * u * u * cd * math.pi * d * d / 4.0
        lo, hi = (u, hi) if drag < weight else (lo, u)
    return 0.5 * (lo + hi)


def layer_surface(x, r, column=2e-3):
    """Median over 2 mm columns of the highest grain top: diagnostics.csv's surface_height."""
    lo = float((x[:, 0] - r).min())
    cols = np.floor((x[:, 0] - lo) / column).astype(int)
    tops = [float((x[cols == c, 1] + r[cols == c]).max()) for c in np.unique(cols)]
    return float(np.median(tops))


def snapshots(out):
    paths = glob.glob(os.path.join(out, "snap_*.h5"))
    return sorted(paths, key=lambda p: int(re.search(r"snap_(\d+)", p).group(1)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--vin", type=float, required=True)
    ap.add_argument("--depth", type=float, default=0.003)
    ap.add_argument("--rho-s", type=float, default=2600.0)
    ap.add_argument("--rho", type=float, default=1000.0)
    ap.add_argument("--nu", type=float, default=1e-6)
    args = ap.parse_args()
    g = 9.81
    paths = snapshots(args.out)
    if not paths:
        sys.exit(f"erosion_forces: no snap_*.h5 in {args.out}")
    with h5py.File(paths[0], "r") as f:
        x0, r0, body0 = f["/dem/position"][...], f["/dem/radius"][...], f["/dem/body"][...]
    surface0 = layer_surface(x0, r0)
    rows = []
    for path in paths:
        with h5py.File(path, "r") as f:
            t = float(f.attrs["time"])
            x, r = f["/dem/position"][...], f["/dem/radius"][...]
            v, fh, body = f["/dem/velocity"][...], f["/dem/force_hydro"][...], f["/dem/body"][...]
            xf, vf = f["/fluid/position"][...], f["/fluid/velocity"][...]
            kind, eps = f["/fluid/kind"][...], f["/fluid/porosity"][...]
        top = (body == -1) & (x[:, 1] + r > surface0 - args.depth)
        fluid = kind == 0
        xf = xf[fluid]
        pore = np.linalg.norm(vf[fluid], axis=1) / np.maximum(eps[fluid], 1e-6)
        ratios, speeds, grain_speeds, covered = [], [], [], 0
        for k in np.flatnonzero(top):
            m = args.rho_s * 4.0 / 3.0 * math.pi * r[k] ** 3
            ratios.append(fh[k, 1] / (m * g))
            if ratios[-1] > 1.0:
                # A lifted fine held from above: a grain touching it (within 0.1 mm) whose centre
                # is higher by more than half its radius. In the planar slab it cannot pass one.
                dist = np.linalg.norm(x[:, :2] - x[k, :2], axis=1)
                above = (dist < r + r[k] + 1e-4) & (x[:, 1] > x[k, 1] + 0.5 * r[k])
                above[k] = False
                covered += int(above.any())
            near = np.linalg.norm(xf - x[k, :2], axis=1) < r[k] + 1e-3
            speeds.append(pore[near].max() / args.vin if near.any() else 0.0)
            grain_speeds.append(np.linalg.norm(v[k]) / args.vin)
        ratios = np.array(ratios)
        rows.append({
            "time": t, "fines_near_surface": int(top.sum()),
            "lift_ratio_max": float(ratios.max()) if len(ratios) else 0.0,
            "lift_ratio_median": float(np.median(ratios)) if len(ratios) else 0.0,
            "fines_lifted": int((ratios > 1.0).sum()),
            "fines_lifted_covered": covered,
            "pore_speed_ratio_max": max(speeds, default=0.0),
            "pore_speed_ratio_median": float(np.median(speeds)) if speeds else 0.0,
            "grain_speed_ratio_max": max(grain_speeds, default=0.0),
        })
    with open(os.path.join(args.out, "erosion_forces.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    d = 2.0 * float(r0[body0 == -1].mean()) if (body0 == -1).any() else 1e-3
    ut = terminal_speed(d, args.rho_s, args.rho, args.nu)
    late = [row for row in rows if row["time"] >= SETTLED] or rows
    print(f"initial layer surface {1e3 * surface0:.2f} mm; fines within {1e3 * args.depth:.1f} mm "
          f"of it: {rows[0]['fines_near_surface']}")
    print(f"single-fine terminal speed (d = {1e3 * d:.2f} mm): {100 * ut:.1f} cm/s = "
          f"{ut / args.vin:.1f} v_in")
    for name in ("lift_ratio_max", "lift_ratio_median", "pore_speed_ratio_max",
                 "pore_speed_ratio_median", "grain_speed_ratio_max"):
        vals = [row[name] for row in late]
        print(f"{name} over t >= {late[0]['time']:.2f} s: mean {np.mean(vals):.2f}, "
              f"max {np.max(vals):.2f}")
    print(f"snapshots with a fine lifted (F_y > m g): "
          f"{sum(row['fines_lifted'] > 0 for row in late)} of {len(late)}; "
          f"most fines lifted at once: {max(row['fines_lifted'] for row in late)}; of the lifted "
          f"ones, covered by a grain above: {sum(row['fines_lifted_covered'] for row in late)} of "
          f"{sum(row['fines_lifted'] for row in late)}")


if __name__ == "__main__":
    sys.exit(main())
