#!/usr/bin/env python3
"""Instant-release VOF (OpenFOAM interFoam) reference for the 2D dam break.

What it is
    An independent grid (volume-of-fluid) Navier-Stokes solution of the dam break of
    examples/dam_break_2d/case.toml: a water column a = 0.1 m wide and 2a high at
    x in [0, a], y in [0, 2a] in a tank 5a long (walls at x = 0, x = 5a, floor y = 0,
    open top), g = 9.81, water rho 1000 / nu 1e-6, air rho 1 / nu 1.48e-5, released at
    t = 0 and run to t = 0.22 s (T = t sqrt(2g/a) = 3.08). The surge front Z = x_front/a
    against T is compared with Martin & Moyce (1952). Its purpose is to tell whether an
    instant-release solver leads the experiment by the same amount as our SPH does.

    The script writes the OpenFOAM case from scratch (one block, square cells, one cell
    thick in z with empty front/back patches, an `atmosphere` patch at the top with
    totalPressure / pressureInletOutletVelocity / inletOutlet), runs blockMesh, setFields
    and interFoam serially (adjustable time step, maxCo = maxAlphaCo = 0.2 by default,
    fields written every 0.005 s in ASCII), reads the alpha.water files directly and
    prints the front at every write time next to Martin & Moyce (linearly interpolated in
    T), with the percent difference, the same at the Martin & Moyce T values, and the time
    shift dT by which the VOF curve would have to be delayed to match the experiment in
    0.8 < T < 1.8. A CSV (front.csv) is written in the work directory.

    Front definitions (all Z = x/a; alpha = 0.5 crossings are linearly interpolated
    between neighbouring cell centres):
      Z_bot   largest x where alpha.water >= 0.5 in the bottom cell row (the primary one)
      Z_row3  the largest such x over the first three cell rows
      Z_ext   the alpha = 0.5 crossings of rows 1-3 fitted by a straight line x(y) and
              extrapolated to the floor y = 0
      Z_a01   bottom row with threshold alpha >= 0.1 instead of 0.5 (thin-film sensitivity;
              biased by +0.4 dx for a sharp step, e.g. 1.01 at t = 0 for a/dx = 40)
      Z_int   dx * sum(alpha.water) over the bottom row (water length of the row; no threshold)

Requirements
    OpenFOAM (interFoam, blockMesh, setFields). On Debian: `ISPHDEM_REFERENCE=1 bash scripts/setup.sh`
    (installs the openfoam package)
    (v1912). The environment is taken from $WM_PROJECT_DIR if set, else from
    /usr/share/openfoam/etc/bashrc (or --foam-bashrc). Python 3 standard library only.

How to run
    /usr/bin/python3 scripts/dam_break_vof_reference.py                  # a/dx = 40, no-slip
    /usr/bin/python3 scripts/dam_break_vof_reference.py --cells-per-a 80
    /usr/bin/python3 scripts/dam_break_vof_reference.py --slip           # slip floor
    /usr/bin/python3 scripts/dam_break_vof_reference.py --extract-only --workdir DIR
  Options: --cells-per-a N (default 40), --slip (free-slip floor; side walls stay no-slip),
  --sigma S (surface tension, default 0), --height H (tank height, default 0.35 m),
  --max-co C (default 0.2), --end-time (default 0.22), --workdir DIR (default a fresh
  temporary directory; it must not exist or be empty). Runs on one core.

Results measured (OpenFOAM v1912 Debian package; see the table printed by the script)
    Run on this 2-core machine, one core, to t = 0.22 s. Z_bot % vs M&M at its T values:

      T    M&M   a/dx=40      a/dx=80      40 slip floor  40 maxCo 0.1  40 sigma 0.07
    0.41  1.11  1.119 +0.8%  1.124 +1.2%  1.120 +0.9%    1.119 +0.8%   1.117 +0.6%
    0.84  1.23  1.410 +14.7  1.410 +14.6  1.420 +15.5    1.411 +14.7   1.402 +14.0
    1.19  1.44  1.721 +19.5  1.724 +19.7  1.735 +20.5    1.721 +19.5   1.708 +18.6
    1.43  1.67  1.966 +17.7  1.973 +18.1  1.982 +18.7    1.965 +17.6   1.956 +17.1
    1.63  1.89  2.194 +16.1  2.198 +16.3  2.205 +16.7    2.193 +16.0   2.180 +15.3
    1.82  2.11  2.422 +14.8  2.425 +14.9  2.431 +15.2    2.422 +14.8   2.406 +14.0
    2.20  2.56  2.912 +13.7  2.915 +13.9  2.922 +14.2    2.912 +13.7   2.894 +13.1
    2.50  3.00  3.324 +10.8  3.332 +11.1  3.342 +11.4    3.326 +10.9   3.311 +10.4
    2.96  3.67  4.006 +9.1   4.013 +9.3   4.026 +9.7     4.012 +9.3    3.989 +8.7
    interFoam wall time: 126 s (1427 steps), 1912 s (3516 steps), 124 s, 252 s, 168 s.

    Least-squares delay dT that makes Z_bot(T - dT) fit M&M in 0.8 < T < 1.8: 0.284 (40),
    0.286 (80), 0.297 (40 slip), 0.284 (40 maxCo 0.1), 0.273 (40 sigma 0.07); rms misfit
    in Z after the shift about 0.02. The other front definitions (Z_row3, Z_ext, Z_a01, Z_int)
    lie 0 to 1.7 percentage points ahead of Z_bot at a/dx = 40 and 0 to 0.7 at a/dx = 80.
"""

import argparse
import bisect
import csv
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

A = 0.1            # column width [m]
G = 9.81
LENGTH = 5 * A     # tank length [m]
WRITE_INTERVAL = 0.005
KEYS = ["Z_bot", "Z_row3", "Z_ext", "Z_a01", "Z_int"]

# Martin & Moyce (1952), a = 2.25 in column, (T, Z).
MM = [(0.0, 1.0), (0.41, 1.11), (0.84, 1.23), (1.19, 1.44), (1.43, 1.67), (1.63, 1.89),
      (1.82, 2.11), (1.97, 2.33), (2.20, 2.56), (2.32, 2.78), (2.50, 3.00), (2.64, 3.22),
      (2.82, 3.44), (2.96, 3.67)]


def die(msg):
    sys.stderr.write("dam_break_vof_reference: error: " + msg + "\n")
    sys.exit(2)


def interp(x, xs, ys):
    """Linear interpolation in increasing xs; None outside the range."""
    if x < xs[0] or x > xs[-1]:
        return None
    k = bisect.bisect_right(xs, x)
    if k >= len(xs):
        return ys[-1]
    k = max(k, 1)
    x0, x1, y0, y1 = xs[k - 1], xs[k], ys[k - 1], ys[k]
    return y0 if x1 == x0 else y0 + (y1 - y0) * (x - x0) / (x1 - x0)


def mm_z(T):
    return interp(T, [p[0] for p in MM], [p[1] for p in MM])


# ----------------------------------------------------------------------------- environment

def foam_env(bashrc_opt):
    env = dict(os.environ)
    env["OMP_NUM_THREADS"] = "1"
    if not env.get("WM_PROJECT_DIR"):
        cands = [bashrc_opt] if bashrc_opt else []
        cands += ["/usr/share/openfoam/etc/bashrc", "/usr/lib/openfoam/etc/bashrc"]
        bashrc = next((c for c in cands if c and os.path.isfile(c)), None)
        if bashrc:
            try:
                out = subprocess.run(["bash", "-c", '. "$0" >/dev/null 2>&1; env -0', bashrc],
                                     stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                                     env=env, timeout=120).stdout
                for item in out.split(b"\0"):
                    if b"=" in item:
                        k, v = item.decode(errors="replace").split("=", 1)
                        env[k] = v
            except (OSError, subprocess.SubprocessError):
                pass
            if not env.get("WM_PROJECT_DIR"):
                env["WM_PROJECT_DIR"] = os.path.dirname(os.path.dirname(bashrc))
        env["OMP_NUM_THREADS"] = "1"
    for tool in ("blockMesh", "setFields", "interFoam"):
        if shutil.which(tool, path=env.get("PATH")) is None:
            die("'%s' not found on PATH. Install OpenFOAM (Debian package openfoam, v1912) with "
                "`ISPHDEM_REFERENCE=1 bash scripts/setup.sh`, or source its etc/bashrc before "
                "running." % tool)
    if not env.get("WM_PROJECT_DIR") or not os.path.isfile(
            os.path.join(env["WM_PROJECT_DIR"], "etc", "controlDict")):
        die("OpenFOAM found but its etc/controlDict is not: set WM_PROJECT_DIR or pass "
            "--foam-bashrc PATH/etc/bashrc (Debian: /usr/share/openfoam/etc/bashrc).")
    return env


# ----------------------------------------------------------------------------- case files

def header(cls, obj, loc=None):
    loc_line = '    location    "%s";\n' % loc if loc else ""
    return ("FoamFile\n{\n    version     2.0;\n    format      ascii;\n"
            "    class       %s;\n%s    object      %s;\n}\n\n" % (cls, loc_line, obj))


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def write_case(d, p):
    nx, ny, dx, H = p["nx"], p["ny"], p["dx"], p["height"]
    L = LENGTH
    write(os.path.join(d, "system/blockMeshDict"), header("dictionary", "blockMeshDict") + f"""
convertToMeters 1;

vertices
(
    (0 0 0) ({L} 0 0) ({L} {H} 0) (0 {H} 0)
    (0 0 {dx}) ({L} 0 {dx}) ({L} {H} {dx}) (0 {H} {dx})
);

blocks
(
    hex (0 1 2 3 4 5 6 7) ({nx} {ny} 1) simpleGrading (1 1 1)
);

edges ();

boundary
(
    leftWall    {{ type wall;  faces ((0 4 7 3)); }}
    rightWall   {{ type wall;  faces ((2 6 5 1)); }}
    lowerWall   {{ type wall;  faces ((1 5 4 0)); }}
    atmosphere  {{ type patch; faces ((3 7 6 2)); }}
    frontAndBack {{ type empty; faces ((0 3 2 1) (4 5 6 7)); }}
);

mergePatchPairs ();
""")
    write(os.path.join(d, "system/controlDict"), header("dictionary", "controlDict", "system") + f"""
application       interFoam;
startFrom         startTime;
startTime         0;
stopAt            endTime;
endTime           {p["end_time"]};
deltaT            1e-05;
writeControl      adjustable;
writeInterval     {WRITE_INTERVAL};
purgeWrite        0;
writeFormat       ascii;
writePrecision    8;
writeCompression  off;
timeFormat        general;
timePrecision     6;
runTimeModifiable no;
adjustTimeStep    yes;
maxCo             {p["max_co"]};
maxAlphaCo        {p["max_co"]};
maxDeltaT         1e-3;
""")
    write(os.path.join(d, "system/fvSchemes"), header("dictionary", "fvSchemes", "system") + """
ddtSchemes           { default Euler; }
gradSchemes          { default Gauss linear; }
divSchemes
{
    div(rhoPhi,U)    Gauss linearUpwind grad(U);
    div(phi,alpha)   Gauss vanLeer;
    div(phirb,alpha) Gauss linear;
    div(((rho*nuEff)*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes     { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes        { default corrected; }
""")
    write(os.path.join(d, "system/fvSolution"), header("dictionary", "fvSolution", "system") + """
solvers
{
    "alpha.water.*"
    {
        nAlphaCorr      2;
        nAlphaSubCycles 1;
        cAlpha          1;
        MULESCorr       yes;
        nLimiterIter    3;
        solver          smoothSolver;
        smoother        symGaussSeidel;
        tolerance       1e-8;
        relTol          0;
    }
    "pcorr.*"   { solver PCG; preconditioner DIC; tolerance 1e-5; relTol 0; }
    p_rgh       { solver PCG; preconditioner DIC; tolerance 1e-7; relTol 0.05; }
    p_rghFinal  { solver PCG; preconditioner DIC; tolerance 1e-7; relTol 0; }
    "(U|UFinal)" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-6; relTol 0; }
}

PIMPLE
{
    momentumPredictor        no;
    nOuterCorrectors         1;
    nCorrectors              3;
    nNonOrthogonalCorrectors 0;
}

relaxationFactors { equations { ".*" 1; } }
""")
    write(os.path.join(d, "system/setFieldsDict"), header("dictionary", "setFieldsDict", "system") + f"""
defaultFieldValues ( volScalarFieldValue alpha.water 0 );
regions
(
    boxToCell
    {{
        box (-1 -1 -1) ({A} {2 * A} 1);
        fieldValues ( volScalarFieldValue alpha.water 1 );
    }}
);
""")
    write(os.path.join(d, "constant/g"), header("uniformDimensionedVectorField", "g", "constant") +
          f"dimensions [0 1 -2 0 0 0 0];\nvalue (0 {-G} 0);\n")
    write(os.path.join(d, "constant/transportProperties"),
          header("dictionary", "transportProperties", "constant") + f"""
phases (water air);
water {{ transportModel Newtonian; nu 1e-06;   rho 1000; }}
air   {{ transportModel Newtonian; nu 1.48e-05; rho 1; }}
sigma {p["sigma"]};
""")
    write(os.path.join(d, "constant/turbulenceProperties"),
          header("dictionary", "turbulenceProperties", "constant") + "simulationType laminar;\n")

    floor_u = "slip" if p["slip"] else "noSlip"
    write(os.path.join(d, "0/U"), header("volVectorField", "U", "0") + f"""
dimensions    [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{{
    leftWall     {{ type noSlip; }}
    rightWall    {{ type noSlip; }}
    lowerWall    {{ type {floor_u}; }}
    atmosphere   {{ type pressureInletOutletVelocity; value uniform (0 0 0); }}
    frontAndBack {{ type empty; }}
}}
""")
    write(os.path.join(d, "0/p_rgh"), header("volScalarField", "p_rgh", "0") + """
dimensions    [1 -1 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
    "(leftWall|rightWall|lowerWall)" { type fixedFluxPressure; value uniform 0; }
    atmosphere   { type totalPressure; p0 uniform 0; }
    frontAndBack { type empty; }
}
""")
    write(os.path.join(d, "0/alpha.water"), header("volScalarField", "alpha.water", "0") + """
dimensions    [0 0 0 0 0 0 0];
internalField uniform 0;
boundaryField
{
    "(leftWall|rightWall|lowerWall)" { type zeroGradient; }
    atmosphere   { type inletOutlet; inletValue uniform 0; value uniform 0; }
    frontAndBack { type empty; }
}
""")


def run_tool(d, env, cmd):
    log = os.path.join(d, "log." + cmd[0])
    t0 = time.monotonic()
    with open(log, "w") as f:
        try:
            rc = subprocess.run(cmd + ["-case", d], stdout=f, stderr=subprocess.STDOUT,
                                env=env, cwd=d).returncode
        except OSError as e:
            die("could not start %s: %s" % (cmd[0], e))
    wall = time.monotonic() - t0
    with open(log) as f:
        text = f.read()
    if rc != 0 or "FOAM FATAL" in text or not re.search(r"^End\s*$", text, re.M):
        tail = "\n".join(text.splitlines()[-30:])
        die("%s failed (exit code %d); log %s ends with:\n%s" % (cmd[0], rc, log, tail))
    return wall, text


# ----------------------------------------------------------------------------- fields

def read_scalar_field(path, ncells):
    with open(path) as f:
        text = f.read()
    m = re.search(r"internalField\s+uniform\s+([-+0-9.eE]+)\s*;", text)
    if m:
        return [float(m.group(1))] * ncells
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(", text)
    if not m:
        die("cannot parse internalField of %s (need ASCII, uncompressed)" % path)
    n = int(m.group(1))
    end = text.index(")", m.end())
    vals = [float(v) for v in text[m.end():end].split()]
    if n != ncells or len(vals) != ncells:
        die("%s has %d/%d values, mesh has %d cells" % (path, n, len(vals), ncells))
    return vals


def crossing(row, dx, thr):
    """Largest x where row >= thr, interpolated to the thr crossing towards the next cell."""
    idx = [i for i, v in enumerate(row) if v >= thr]
    if not idx:
        return None
    i = idx[-1]
    xc = (i + 0.5) * dx
    if i == len(row) - 1:
        return xc + 0.5 * dx
    a0, a1 = row[i], row[i + 1]
    return xc + (a0 - thr) / (a0 - a1) * dx if a0 > a1 else xc


def front_at(alpha, nx, dx):
    rows = [alpha[j * nx:(j + 1) * nx] for j in range(3)]
    xs = [crossing(r, dx, 0.5) for r in rows]
    z_bot = xs[0]
    z_row3 = max(x for x in xs if x is not None) if any(x is not None for x in xs) else None
    z_ext = None
    pts = [((j + 0.5) * dx, x) for j, x in enumerate(xs) if x is not None]
    if len(pts) >= 2:
        ym = sum(p[0] for p in pts) / len(pts)
        xm = sum(p[1] for p in pts) / len(pts)
        syy = sum((p[0] - ym) ** 2 for p in pts)
        slope = sum((p[0] - ym) * (p[1] - xm) for p in pts) / syy
        z_ext = xm - slope * ym
    z_a01 = crossing(rows[0], dx, 0.1)
    z_int = dx * sum(rows[0])
    f = lambda x: None if x is None else x / A
    return f(z_bot), f(z_row3), f(z_ext), f(z_a01), f(z_int)


def time_dirs(d):
    out = []
    for name in os.listdir(d):
        try:
            t = float(name)
        except ValueError:
            continue
        if os.path.isfile(os.path.join(d, name, "alpha.water")):
            out.append((t, name))
    return sorted(out)


def time_shift(Ts, Zs, lo=0.8, hi=1.8):
    """dT such that Z_vof(T - dT) best matches M&M at its points in (lo, hi)."""
    pts = [(T, Z) for T, Z in MM if lo < T < hi]
    # Pointwise: T at which the VOF front first reaches each M&M Z.
    point = []
    for T, Z in pts:
        tv = None
        for k in range(1, len(Ts)):
            if Zs[k - 1] is not None and Zs[k] is not None and Zs[k - 1] < Z <= Zs[k]:
                tv = Ts[k - 1] + (Ts[k] - Ts[k - 1]) * (Z - Zs[k - 1]) / (Zs[k] - Zs[k - 1])
                break
        point.append((T, Z, None if tv is None else T - tv))
    good = [(T, Z) for T, Z in zip(Ts, Zs) if Z is not None]
    tt, zz = [g[0] for g in good], [g[1] for g in good]
    best = None
    for k in range(-500, 1001):
        dT = k * 0.001
        res = [interp(T - dT, tt, zz) for T, _ in pts]
        if any(r is None for r in res):
            continue
        s = sum((r - Z) ** 2 for r, (_, Z) in zip(res, pts))
        if best is None or s < best[1]:
            best = (dT, s)
    rms = math.sqrt(best[1] / len(pts)) if best else None
    return point, (best[0] if best else None), rms


def extract(d, p, walls):
    nx, ny, dx = p["nx"], p["ny"], p["dx"]
    ncells = nx * ny
    tds = time_dirs(d)
    if len(tds) < 2:
        die("no written time directories with alpha.water in %s" % d)
    scale = math.sqrt(2 * G / A)
    rows = []
    for t, name in tds:
        alpha = read_scalar_field(os.path.join(d, name, "alpha.water"), ncells)
        zb, z3, ze, z01, zi = front_at(alpha, nx, dx)
        T = t * scale
        zm = mm_z(T)
        pct = None if (zb is None or zm is None) else 100.0 * (zb - zm) / zm
        rows.append(dict(t=t, T=T, Z_bot=zb, Z_row3=z3, Z_ext=ze, Z_a01=z01, Z_int=zi, Z_MM=zm, pct=pct))

    fmt = lambda v, w=7, n=3: ("%*.*f" % (w, n, v)) if v is not None else " " * (w - 3) + "n/a"
    print()
    print("Dam break 2D, interFoam, a/dx = %d (%d x %d cells), %s floor, sigma = %g, maxCo = %g"
          % (p["cells_per_a"], nx, ny, "slip" if p["slip"] else "no-slip", p["sigma"],
             p["max_co"]))
    print("Z = x_front/a, T = t sqrt(2g/a); Z_bot = alpha>=0.5 in bottom row (primary),")
    print("Z_row3 = max over 3 bottom rows, Z_ext = rows 1-3 extrapolated to y=0, Z_a01 = alpha>=0.1,")
    print("Z_int = dx * sum(alpha) over the bottom row / a; diff = Z_bot vs Z_MM")
    print()
    print("   t[s]       T   Z_bot  Z_row3   Z_ext   Z_a01   Z_int    Z_MM  diff[%]")
    for r in rows:
        print("%7.4f %7.3f %s %s %s %s %s %s %s" % (r["t"], r["T"], fmt(r["Z_bot"]), fmt(r["Z_row3"]),
              fmt(r["Z_ext"]), fmt(r["Z_a01"]), fmt(r["Z_int"]), fmt(r["Z_MM"]), fmt(r["pct"], 8, 1)))

    Ts = [r["T"] for r in rows]
    print()
    print("At the Martin & Moyce times (VOF interpolated in T), percent vs M&M:")
    print("     T   Z_MM   Z_bot  diff%  Z_row3  diff%   Z_ext  diff%   Z_a01  diff%   Z_int  diff%")
    for T, Z in MM[1:]:
        if T > Ts[-1]:
            break
        line = "%6.2f %6.2f" % (T, Z)
        for key in KEYS:
            pairs = [(r["T"], r[key]) for r in rows if r[key] is not None]
            zv = interp(T, [q[0] for q in pairs], [q[1] for q in pairs])
            line += " %s %s" % (fmt(zv), fmt(None if zv is None else 100 * (zv - Z) / Z, 6, 1))
        print(line)

    print()
    print("Time shift dT (VOF delayed by dT to match M&M in 0.8 < T < 1.8):")
    for key in KEYS:
        point, dT, rms = time_shift(Ts, [r[key] for r in rows])
        pts = ", ".join("T=%.2f: %s" % (T, "n/a" if s is None else "%.3f" % s) for T, _, s in point)
        print("  %-6s least-squares dT = %s (rms Z misfit %s); pointwise %s"
              % (key, fmt(dT, 6, 3), fmt(rms, 6, 3), pts))

    csv_path = os.path.join(d, "front.csv")
    with open(csv_path, "w", newline="") as f:
        w = csv.writer(f)
        keys = ["t", "T"] + KEYS + ["Z_MM", "pct"]
        w.writerow(["t_s", "T", "Z_bottom_row_a05", "Z_max_3rows_a05", "Z_extrap_y0_a05",
                    "Z_bottom_row_a01", "Z_bottom_row_integral", "Z_MartinMoyce",
                    "pct_diff_bottom_row"])
        for r in rows:
            w.writerow(["" if r[k] is None else "%.6g" % r[k] for k in keys])
    print()
    if walls:
        print("Wall time: " + ", ".join("%s %.1f s" % kv for kv in walls))
    print("CSV: %s\nCase: %s" % (csv_path, d))


# ----------------------------------------------------------------------------- main

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cells-per-a", type=int, default=40, help="cells per column width a (default 40)")
    ap.add_argument("--slip", action="store_true", help="free-slip floor (default no-slip walls)")
    ap.add_argument("--sigma", type=float, default=0.0, help="surface tension [N/m], default 0")
    ap.add_argument("--height", type=float, default=0.35, help="tank height [m], default 0.35")
    ap.add_argument("--max-co", type=float, default=0.2, help="maxCo and maxAlphaCo (default 0.2)")
    ap.add_argument("--end-time", type=float, default=0.22, help="end time [s] (default 0.22)")
    ap.add_argument("--workdir", help="case directory (default: a fresh temporary directory)")
    ap.add_argument("--foam-bashrc", help="OpenFOAM etc/bashrc if WM_PROJECT_DIR is not set")
    ap.add_argument("--extract-only", action="store_true",
                    help="only extract the front from an existing --workdir")
    args = ap.parse_args()

    if args.extract_only:
        if not args.workdir or not os.path.isfile(os.path.join(args.workdir, "params.json")):
            die("--extract-only needs --workdir DIR of an earlier run (with params.json)")
        d = os.path.abspath(args.workdir)
        with open(os.path.join(d, "params.json")) as f:
            p = json.load(f)
        extract(d, p, None)
        return

    if not 4 <= args.cells_per_a <= 400:
        die("--cells-per-a must be between 4 and 400 (got %d)" % args.cells_per_a)
    if not 2.2 * A <= args.height <= 1.0:
        die("--height must be between %.2f and 1.0 m" % (2.2 * A))
    if not 0.0 <= args.sigma <= 1.0:
        die("--sigma must be between 0 and 1 N/m")
    if not 0.01 <= args.max_co <= 1.0:
        die("--max-co must be between 0.01 and 1")
    if not 0.0 < args.end_time <= 0.3:
        die("--end-time must be in (0, 0.3] s (the front reaches the far wall near 0.3 s)")

    env = foam_env(args.foam_bashrc)
    if args.workdir:
        d = os.path.abspath(args.workdir)
        if os.path.exists(d) and (not os.path.isdir(d) or os.listdir(d)):
            die("--workdir %s exists and is not an empty directory" % d)
        os.makedirs(d, exist_ok=True)
    else:
        d = tempfile.mkdtemp(prefix="dam_break_vof_%d_" % args.cells_per_a)

    n = args.cells_per_a
    dx = A / n
    ny = int(round(args.height / dx))
    p = dict(cells_per_a=n, nx=5 * n, ny=ny, dx=dx, height=ny * dx, slip=args.slip,
             sigma=args.sigma, max_co=args.max_co, end_time=args.end_time)
    write_case(d, p)
    with open(os.path.join(d, "params.json"), "w") as f:
        json.dump(p, f, indent=1)
    print("Case in %s: %d x %d cells, dx = %.5g m" % (d, p["nx"], p["ny"], dx), flush=True)

    walls = []
    t_all = time.monotonic()
    for cmd in (["blockMesh"], ["setFields"], ["interFoam"]):
        print("running %s ..." % cmd[0], flush=True)
        wall, text = run_tool(d, env, cmd)
        walls.append((cmd[0], wall))
        if cmd[0] == "blockMesh":
            m = re.search(r"nCells:\s*(\d+)", text)
            if m and int(m.group(1)) != p["nx"] * p["ny"]:
                die("blockMesh made %s cells, expected %d" % (m.group(1), p["nx"] * p["ny"]))
        if cmd[0] == "interFoam":
            steps = len(re.findall(r"^Time = ", text, re.M))
            print("interFoam: %d time steps, %.1f s wall" % (steps, wall), flush=True)
    walls.append(("total", time.monotonic() - t_all))
    extract(d, p, walls)


if __name__ == "__main__":
    main()
