"""Opens every DIR/*.xdmf with ParaView's XDMF reader, as a user would, and checks it.

Run with pvpython (headless is fine):
    pvpython --force-offscreen-rendering tests/output/check_xdmf.py DIR \
        [--steps K] [--expect GROUP=POINTS:ARRAY[/COMPONENTS],...]...

Always checked, for every .xdmf: ParaView sees a time series with strictly ascending times, and
every step loads with points and with every point array holding one tuple per point.
--steps K: every .xdmf has K time steps.
--expect fluid=7:pressure,velocity/3,kind: DIR/fluid.xdmf exists and at its last time step has 7
points and (at least) these point arrays, with the given component counts where given.

Exit status 0 when everything holds, 1 otherwise (each failure is printed), 2 for bad usage.
"""
import argparse
import glob
import os
import sys

from paraview import servermanager
from paraview.simple import Delete, XDMFReader


def parse_expect(text):
    try:
        group, rest = text.split("=", 1)
        points, arrays = rest.split(":", 1) if ":" in rest else (rest, "")
        wanted = {}
        for item in filter(None, arrays.split(",")):
            name, _, comps = item.partition("/")
            wanted[name] = int(comps) if comps else None
        return group, int(points), wanted
    except ValueError:
        raise argparse.ArgumentTypeError("expected GROUP=POINTS:ARRAY[/N],..., got " + text)


def first_dataset(data):
    """The reader gives an unstructured grid, or a multiblock wrapping one."""
    if data is not None and data.IsA("vtkMultiBlockDataSet"):
        for i in range(data.GetNumberOfBlocks()):
            found = first_dataset(data.GetBlock(i))
            if found is not None:
                return found
        return None
    return data


def load(path):
    """(times, {time: (points, {array: components}, tuples_ok)}) as ParaView reads them."""
    reader = XDMFReader(FileNames=[os.path.abspath(path)])
    times = list(reader.TimestepValues or [])
    steps = {}
    for t in times:
        reader.UpdatePipeline(t)
        data = first_dataset(servermanager.Fetch(reader))
        if data is None:
            steps[t] = (0, {}, False)
            continue
        n = data.GetNumberOfPoints()
        pd = data.GetPointData()
        arrays = {}
        tuples_ok = True
        for i in range(pd.GetNumberOfArrays()):
            a = pd.GetArray(i)
            arrays[a.GetName()] = a.GetNumberOfComponents()
            tuples_ok = tuples_ok and a.GetNumberOfTuples() == n
        steps[t] = (n, arrays, tuples_ok)
    Delete(reader)
    return times, steps


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir")
    parser.add_argument("--steps", type=int)
    parser.add_argument("--expect", type=parse_expect, action="append", default=[])
    args = parser.parse_args()

    failures = []
    paths = sorted(glob.glob(os.path.join(args.dir, "*.xdmf")))
    if not paths:
        failures.append("no .xdmf in " + args.dir)
    last = {}
    for path in paths:
        name = os.path.basename(path)
        times, steps = load(path)
        if args.steps is not None and len(times) != args.steps:
            failures.append("%s: %d time steps, expected %d" % (name, len(times), args.steps))
        if any(b <= a for a, b in zip(times, times[1:])):
            failures.append("%s: times not strictly ascending: %s" % (name, times))
        for t in times:
            n, arrays, tuples_ok = steps[t]
            if n == 0:
                failures.append("%s: no points at time %r" % (name, t))
            if not tuples_ok:
                failures.append("%s: an array's length differs from the point count at time %r"
                                % (name, t))
        if times:
            last[os.path.splitext(name)[0]] = steps[times[-1]]
        print("%s: %d steps, times %s, last step %d points, arrays %s"
              % (name, len(times), times, last.get(os.path.splitext(name)[0], (0,))[0],
                 last.get(os.path.splitext(name)[0], (0, {}))[1]))

    for group, points, wanted in args.expect:
        if group not in last:
            failures.append("%s.xdmf: missing or without time steps" % group)
            continue
        n, arrays, _ = last[group]
        if n != points:
            failures.append("%s.xdmf: %d points at the last step, expected %d" % (group, n, points))
        for name, comps in wanted.items():
            if name not in arrays:
                failures.append("%s.xdmf: no point array %r (has %s)"
                                % (group, name, sorted(arrays)))
            elif comps is not None and arrays[name] != comps:
                failures.append("%s.xdmf: %r has %d components, expected %d"
                                % (group, name, arrays[name], comps))

    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
