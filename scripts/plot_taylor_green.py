#!/usr/bin/python3
"""Taylor-Green decay from an isphdem run: the velocity amplitude of every snapshot (projection on
the unit mode at the particle positions) against the analytic exp(-8 pi^2 t / Re).

    /usr/bin/python3 scripts/plot_taylor_green.py OUT_DIR [--re 100] [-o decay.png]
"""
import argparse
import glob
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def amplitude(path, length=1.0):
    with h5py.File(path, "r") as f:
        t = float(f.attrs["time"])
        x = f["/fluid/position"][...]
        v = f["/fluid/velocity"][...]
        fluid = f["/fluid/kind"][...] == 0
    k = 2 * math.pi / length
    ux = -np.cos(k * x[fluid, 0]) * np.sin(k * x[fluid, 1])
    uy = np.sin(k * x[fluid, 0]) * np.cos(k * x[fluid, 1])
    a = (v[fluid, 0] * ux + v[fluid, 1] * uy).sum() / (ux * ux + uy * uy).sum()
    return t, a


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("out_dir")
    p.add_argument("--re", type=float, default=100.0)
    p.add_argument("-o", "--output", default=None)
    args = p.parse_args()
    files = sorted(glob.glob(os.path.join(args.out_dir, "snap_*.h5")))
    if not files:
        sys.exit(f"no snap_*.h5 in {args.out_dir}: run isphdem first")
    t, a = np.array([amplitude(f) for f in files]).T
    exact = np.exp(-8 * math.pi**2 * t / args.re)
    err = np.abs(a - exact) / exact
    out = args.output or os.path.join(args.out_dir, "decay.png")
    fig, ax = plt.subplots(figsize=(5.5, 3.8), dpi=120)
    ts = np.linspace(0, t.max(), 200)
    ax.plot(ts, np.exp(-8 * math.pi**2 * ts / args.re), "k-", label="exact  exp(-8π²t/Re)")
    ax.plot(t, a, "o", color="tab:red", label="isphdem")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("velocity amplitude / U")
    ax.set_title(f"Taylor–Green, Re = {args.re:g}: max error {100 * err.max():.2f}%")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out)
    print(f"amplitude at t = {t[-1]:.3g} s: {a[-1]:.4f} (exact {exact[-1]:.4f}); max relative error {err.max():.2e}")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
