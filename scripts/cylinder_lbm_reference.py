#!/usr/bin/python3
"""Independent reference for examples/cylinder_re20_2d: the same configuration solved with a
D2Q9 lattice-Boltzmann method (BGK; the disc by Bouzidi's interpolated bounce-back; drag by
momentum exchange).

The example is not an unbounded stream: it is periodic both ways, a forcing band re-sets the
wake to the uniform stream, and the period across the stream puts image cylinders W apart. This
script computes what that configuration itself gives, so that the SPH result can be split into
"what the configuration does to C_d" (blockage and inlet) and "what the SPH discretisation adds".
It shares no code with isphdem.

    /usr/bin/python3 scripts/cylinder_lbm_reference.py --d 24 --width 20      # about 28 min
    /usr/bin/python3 scripts/cylinder_lbm_reference.py --d 16 --width 40      # about 17 min

Measured on this machine (docs/resolved.md), 30 D period along the stream, cylinder 13 D behind
the band: C_d = 2.178 (D = 16) and 2.172 (D = 24) at W = 20 D, 2.146 (D = 16) at W = 40 D.
"""
import argparse
import sys
import time

import numpy as np

C = np.array([[0, 0], [1, 0], [0, 1], [-1, 0], [0, -1], [1, 1], [-1, 1], [-1, -1], [1, -1]])
WEIGHT = np.array([4 / 9] + [1 / 9] * 4 + [1 / 36] * 4)
OPPOSITE = [0, 3, 4, 1, 2, 7, 8, 5, 6]


def equilibrium(rho, ux, uy):
    out = np.empty((9,) + rho.shape)
    usq = 1.5 * (ux * ux + uy * uy)
    for i in range(9):
        cu = 3.0 * (C[i, 0] * ux + C[i, 1] * uy)
        out[i] = WEIGHT[i] * rho * (1.0 + cu + 0.5 * cu * cu - usq)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--d", type=int, default=16, help="cylinder diameter in lattice units")
    ap.add_argument("--width", type=float, default=20.0, help="period across the stream, in D")
    ap.add_argument("--length", type=float, default=30.0, help="period along the stream, in D")
    ap.add_argument("--upstream", type=float, default=13.0,
                    help="cylinder centre behind the forcing band's end, in D")
    ap.add_argument("--band", type=float, default=2.0, help="forcing band length, in D")
    ap.add_argument("--end", type=float, default=30.0, help="end time in D/U")
    ap.add_argument("--re", type=float, default=20.0)
    ap.add_argument("--u", type=float, default=0.05, help="stream speed in lattice units")
    ap.add_argument("--halfway", action="store_true",
                    help="halfway bounce-back (staircase wall) instead of Bouzidi's interpolation")
    ap.add_argument("--save", help="write u/U, v/U and the C_d history to this .npz")
    a = ap.parse_args()
    if a.d < 6 or a.u <= 0 or a.u > 0.1:
        sys.exit("cylinder_lbm_reference: need --d >= 6 and 0 < --u <= 0.1 (Mach number)")
    if a.band + a.upstream + 0.5 >= a.length:
        sys.exit("cylinder_lbm_reference: --band + --upstream leaves no room for the cylinder")

    D, U = a.d, a.u
    nx, ny = int(round(a.length * D)), int(round(a.width * D))
    nu = U * D / a.re
    tau = 0.5 + 3.0 * nu
    if tau < 0.51:
        sys.exit(f"cylinder_lbm_reference: relaxation time {tau:.4f} too close to 0.5; raise --u or --d")
    omega = 1.0 / tau
    xs = np.arange(nx)[:, None] + 0.5
    ys = np.arange(ny)[None, :] + 0.5
    xc, yc = (a.band + a.upstream) * D, ny / 2.0
    solid = (xs - xc) ** 2 + (ys - yc) ** 2 < (D / 2.0) ** 2
    band = np.broadcast_to(xs < a.band * D, (nx, ny))
    # Links: fluid node x receives direction i from x - c_i, a solid node. The wall cuts the link
    # at a fraction q of it from x; Bouzidi et al. (2001) interpolate the reflected population
    # (second order in space; halfway bounce-back puts the wall at q = 1/2 for every link, a
    # staircase whose C_d moved by 1.2% between D = 16 and 24).
    # Per direction i: the link nodes x, the nodes x + c_i one further from the wall (Bouzidi's
    # q < 1/2 branch reads them), and q.
    link, far, frac = [None] * 9, [None] * 9, [None] * 9
    for i in range(1, 9):
        px, py = np.nonzero(np.roll(solid, shift=tuple(C[i]), axis=(0, 1)) & ~solid)
        link[i] = (px, py)
        far[i] = ((px + C[i, 0]) % nx, (py + C[i, 1]) % ny)
        dxw, dyw = px + 0.5 - xc, py + 0.5 - yc
        ex, ey = -C[i, 0], -C[i, 1]  # towards the wall
        a2 = ex * ex + ey * ey
        b = dxw * ex + dyw * ey
        cc = dxw * dxw + dyw * dyw - (D / 2.0) ** 2
        frac[i] = np.clip((-b - np.sqrt(np.maximum(b * b - a2 * cc, 0.0))) / a2, 1e-6, 1.0)
    print(f"{nx} x {ny} nodes, tau = {tau:.4f}, {solid.sum()} solid nodes "
          f"(pi D^2/4 = {np.pi * D * D / 4:.1f}), Re = {a.re:g}", flush=True)

    rho = np.ones((nx, ny))
    ux = np.where(solid, 0.0, U)
    uy = np.zeros((nx, ny))
    f = equilibrium(rho, ux, uy)
    band_u, band_v = np.full(np.count_nonzero(band), U), np.zeros(np.count_nonzero(band))
    steps = int(round(a.end * D / U))
    window = int(round(4.0 * D / U))  # progress lines show the mean over the last 4 D/U
    history = np.zeros(steps)
    t0 = time.time()
    for n in range(steps):
        rho = f.sum(axis=0)
        ux = (f[1] + f[5] + f[8] - f[3] - f[6] - f[7]) / rho
        uy = (f[2] + f[5] + f[6] - f[4] - f[7] - f[8]) / rho
        post = f - omega * (f - equilibrium(rho, ux, uy))
        post[:, band] = equilibrium(rho[band], band_u, band_v)
        for i in range(9):
            f[i] = np.roll(post[i], shift=tuple(C[i]), axis=(0, 1))
        fx = 0.0
        for i in range(1, 9):
            o, m, q = OPPOSITE[i], link[i], frac[i]
            here = post[o][m]
            if a.halfway:
                back = here
            else:
                back = np.where(q < 0.5, 2 * q * here + (1 - 2 * q) * post[o][far[i]],
                                here / (2 * q) + (2 * q - 1) / (2 * q) * post[i][m])
            f[i][m] = back
            fx += C[o, 0] * (here + back).sum()
        history[n] = fx / (0.5 * U * U * D)
        if not np.isfinite(history[n]):
            sys.exit(f"cylinder_lbm_reference: diverged at t U/D = {(n + 1) * U / D:.2f}")
        if (n + 1) % max(1, steps // 20) == 0 or n + 1 == steps:
            k = min(window, n + 1)
            print(f"t U/D = {(n + 1) * U / D:6.2f}  C_d = {history[n + 1 - k:n + 1].mean():.4f}"
                  f"  ({time.time() - t0:.0f} s)", flush=True)
    # The weakly compressible box rings (C_d swings by about +-1% over a few D/U), so the result
    # is the mean over the second half of the run.
    half = history[steps // 2:]
    cd = half.mean()
    drift = half[len(half) // 2:].mean() - half[:len(half) // 2].mean()
    side = [float(ux[int(xc), int(yc + s * D) % ny] / U) for s in (2, 5, 9)]
    print(f"C_d = {cd:.4f} (mean over t U/D = {a.end / 2:g}-{a.end:g}; its second half minus its "
          f"first {drift:+.4f}); D = {D}, W = {a.width:g} D, period {a.length:g} D, cylinder "
          f"{a.upstream:g} D behind the band; u/U beside the cylinder at 2, 5, 9 D: "
          + ", ".join(f"{s:.4f}" for s in side))
    if a.save:
        np.savez(a.save, u=ux / U, v=uy / U, cd=history, d=D, xc=xc, yc=yc)


if __name__ == "__main__":
    main()
