#!/usr/bin/python3
"""Surge front of a 2D dam break against an instant-release reference (OpenFOAM interFoam VOF of the
same tank, the table of tests/validation/test_dam_break.cpp) and Martin & Moyce (1952), for isphdem
output (a directory of snap_*.h5) or a LIGGGHTS dump (id x y vx vy per frame). The errors reported
(mean/max for T <= 2.5) are against the instant-release reference: the experiment's barrier
release lags it by dT = 0.285 (docs/fluid.md).

The front is the definition of tests/validation/test_dam_break.cpp: the largest x among water
particles within 2 dx of the floor that have at least 6 water neighbours within 2 dx, plus dx/2.
The front between frames is interpolated linearly in time to the table's T = t sqrt(2 g / a).

usage: front.py (OUT_DIR | DUMP) --dx DX [--a 0.1] [--json FILE]
"""
import argparse
import glob
import json
import math
import os
import sys

import numpy as np

# Front Z = x/a at the times T of Martin & Moyce (1952), column twice as high as wide:
# (T, Z Martin & Moyce, Z instant-release reference), the reference being interFoam VOF,
# 40 cells per a (scripts/dam_break_vof_reference.py), as in tests/validation/test_dam_break.cpp.
FRONT_TABLE = [(0.41, 1.11, 1.119), (0.84, 1.23, 1.410), (1.19, 1.44, 1.721), (1.43, 1.67, 1.966),
               (1.63, 1.89, 2.194), (1.82, 2.11, 2.422), (1.97, 2.33, 2.610), (2.20, 2.56, 2.912),
               (2.32, 2.78, 3.072), (2.50, 3.00, 3.324), (2.64, 3.22, 3.526), (2.82, 3.44, 3.795),
               (2.96, 3.67, 4.006)]


def front(xy, dx):
    near_floor = xy[:, 1] < 2.0 * dx
    if not near_floor.any():
        return float("nan")
    # Neighbours within 2 dx of each near-floor particle (itself excluded); the near-floor rows
    # are a few hundred particles, so the dense distance block stays small.
    d2 = ((xy[near_floor, None, :] - xy[None, :, :]) ** 2).sum(axis=2)
    counts = (d2 <= (2.0 * dx + 1e-12) ** 2).sum(axis=1) - 1
    candidates = xy[near_floor][counts >= 6]
    return float(candidates[:, 0].max() + 0.5 * dx) if len(candidates) else float("nan")


def isphdem_frames(out_dir):
    import h5py
    for path in sorted(glob.glob(os.path.join(out_dir, "snap_*.h5"))):
        with h5py.File(path, "r") as f:
            kind = f["/fluid/kind"][...]
            # x and the vertical (last) axis: in 3D the front is read in the x-z plane
            yield float(f.attrs["time"]), f["/fluid/position"][...][kind == 0][:, [0, -1]]


def liggghts_frames(dump, dt):
    with open(dump) as f:
        lines = iter(f)
        for line in lines:
            if not line.startswith("ITEM: TIMESTEP"):
                continue
            step = int(next(lines))
            next(lines)
            n = int(next(lines))
            while not next(lines).startswith("ITEM: ATOMS"):
                pass
            rows = np.array([next(lines).split() for _ in range(n)], dtype=float)
            yield step * dt, rows[:, 1:3]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("source")
    ap.add_argument("--dx", type=float, required=True)
    ap.add_argument("--a", type=float, default=0.1)
    ap.add_argument("--dt", type=float, help="LIGGGHTS time step (dump files)")
    ap.add_argument("--json")
    args = ap.parse_args()
    g = 9.81
    scale = math.sqrt(2.0 * g / args.a)
    frames = (isphdem_frames(args.source) if os.path.isdir(args.source)
              else liggghts_frames(args.source, args.dt))
    T, Z = [], []
    for t, xy in frames:
        T.append(t * scale)
        Z.append(front(xy, args.dx) / args.a)
    T, Z = np.array(T), np.array(Z)
    rows, errors = [], []
    print(f"{'T':>6} {'Z M&M':>7} {'Z VOF':>7} {'Z':>7} {'vs VOF':>8} {'vs M&M':>8}")
    for t_ref, z_mm, z_ref in FRONT_TABLE:
        if len(T) == 0 or t_ref > T.max():
            print(f"{t_ref:6.2f} {z_mm:7.2f} {z_ref:7.3f}   (not reached)")
            continue
        z = float(np.interp(t_ref, T, Z))
        err = z / z_ref - 1.0
        rows.append({"T": t_ref, "Z_ref": z_ref, "Z_MartinMoyce": z_mm, "Z": z, "error": err})
        if t_ref <= 2.5:
            errors.append(abs(err))
        print(f"{t_ref:6.2f} {z_mm:7.2f} {z_ref:7.3f} {z:7.3f} {100 * err:+7.1f}% "
              f"{100 * (z / z_mm - 1.0):+7.1f}%")
    result = {"T_reached": float(T.max()) if len(T) else 0.0, "rows": rows,
              "mean_abs_error_T_le_2.5": float(np.mean(errors)) if errors else float("nan"),
              "max_abs_error_T_le_2.5": float(np.max(errors)) if errors else float("nan")}
    print(f"T reached {result['T_reached']:.2f}; |error| vs VOF for T <= 2.5: mean "
          f"{100 * result['mean_abs_error_T_le_2.5']:.1f}%, max {100 * result['max_abs_error_T_le_2.5']:.1f}%")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(result, f, indent=1)


if __name__ == "__main__":
    sys.exit(main())
