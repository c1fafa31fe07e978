#!/usr/bin/env python3
"""Checks that includes between the project's rooms point the allowed way (docs/architecture.md).

    check_layout.py [--root DIR] [--liggghts-include DIR] [--doc FILE] [--graph] [--self-test]

Every #include in sph/, liggghts_fix/ and coupling/ is resolved to the room that holds the file:
`#include "io/snapshot.hpp"` is the io room, a bare name is looked up beside the including file,
then in sph/, coupling/ and liggghts_fix/, then among the LIGGGHTS headers (the room `LIGGGHTS`);
<mpi.h> is the room `MPI`. An include a room may not make is reported with its file and line, and
the exit status is 1, as it is for a source of more than 500 lines. --graph prints the room graph that the includes draw (a Mermaid flowchart);
--doc FILE checks that FILE holds exactly that graph between its `rooms:begin` and `rooms:end`
markers, so the picture in the docs cannot go stale. --self-test shows on a made-up tree that
each rule catches a wrong-way include. Standard library only: runs with any python3.
"""
import argparse
import os
import re
import sys
import tempfile

# Who may include whom. Tests, bench/ and examples/ are not rooms: they may include anything.
ALLOWED = {
    "sph": set(),  # the ISPH library: no coupling, no LIGGGHTS, no MPI
    "sph_petsc": {"sph", "PETSc", "MPI"},  # the PPE on PETSc + hypre, registered with sph/
    "sph_mpi": {"sph", "MPI"},  # the fluid over MPI ranks: shared rows; RCB, migration, halo
    "liggghts_fix": {"LIGGGHTS", "MPI"},
    "coupling": {"sph"},  # the seam: DemState and the CouplingStage interface
    "case": {"sph"},
    "io": {"coupling", "sph", "MPI"},  # snapshots written by the ranks together (parallel HDF5)
    "dem": {"coupling", "liggghts_fix", "LIGGGHTS", "MPI", "sph"},
    "unresolved": {"coupling", "case", "sph"},
    "resolved": {"coupling", "case", "sph"},
    "study": {"case", "io", "coupling", "sph"},  # result.json, [reference], isphdem study
    "run": {"case", "io", "dem", "unresolved", "resolved", "study", "coupling", "sph", "sph_petsc",
            "sph_mpi", "MPI"},
}
COUPLING_ROOMS = ["case", "io", "dem", "unresolved", "resolved", "study", "run"]
SOURCE = (".cpp", ".hpp", ".h")
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
MAX_LINES = 500  # a source longer than this holds more than one concept: split it
DOC_BEGIN = "<!-- rooms:begin (scripts/check_layout.py --graph) -->"
DOC_END = "<!-- rooms:end -->"


def room_of(root, path):
    rel = os.path.relpath(path, root).split(os.sep)
    if rel[0] == "coupling" and len(rel) > 2 and rel[1] in COUPLING_ROOMS:
        return rel[1]
    return rel[0]


def sources(root):
    for top in ("sph", "sph_petsc", "sph_mpi", "liggghts_fix", "coupling"):
        for d, _, files in os.walk(os.path.join(root, top)):
            for f in sorted(files):
                if f.endswith(SOURCE):
                    yield os.path.join(d, f)


def resolve(root, path, bracket, name, liggghts_headers):
    """The room an include names, or None for a system or third-party header."""
    if bracket == "<":
        if name == "mpi.h":
            return "MPI"
        if name.startswith("petsc"):
            return "PETSc"
        return "LIGGGHTS" if name in liggghts_headers else None
    first = name.split("/")[0]
    if first in COUPLING_ROOMS and os.path.exists(os.path.join(root, "coupling", name)):
        return first
    for d in (os.path.dirname(path), os.path.join(root, "sph"), os.path.join(root, "sph_petsc"),
              os.path.join(root, "sph_mpi"), os.path.join(root, "coupling"),
              os.path.join(root, "liggghts_fix")):
        candidate = os.path.join(d, name)
        if os.path.exists(candidate):
            return room_of(root, candidate)
    if name in liggghts_headers:
        return "LIGGGHTS"
    return "?"


def scan(root, liggghts_include):
    liggghts_headers = set()
    if liggghts_include and os.path.isdir(liggghts_include):
        liggghts_headers = set(os.listdir(liggghts_include))
    edges, problems = {}, []
    for path in sources(root):
        own = room_of(root, path)
        with open(path, encoding="utf-8") as f:
            lines = f.readlines()
        if len(lines) > MAX_LINES:
            problems.append(f"{os.path.relpath(path, root)}: {len(lines)} lines, more than "
                            f"{MAX_LINES}: split it by concept (docs/architecture.md)")
        for number, line in enumerate(lines, 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            target = resolve(root, path, m.group(1), m.group(2), liggghts_headers)
            where = f"{os.path.relpath(path, root)}:{number}"
            if target is None or target == own:
                continue
            if target == "?":
                problems.append(f'{where}: cannot find "{m.group(2)}" in any room; include it '
                                f'by room ("io/snapshot.hpp") or pass --liggghts-include')
                continue
            edges[(own, target)] = edges.get((own, target), 0) + 1
            if target not in ALLOWED.get(own, set()):
                may = ", ".join(sorted(ALLOWED.get(own, set()))) or "no other room"
                problems.append(f"{where}: {own}/ includes {m.group(2)} ({target}), but "
                                f"{own}/ may include only {may} (docs/architecture.md)")
    return edges, problems


def graph(edges):
    def node(r):
        return {"coupling": "seam[coupling/ root: DemState, CouplingStage]",
                "LIGGGHTS": "LIGGGHTS([LIGGGHTS 3.8])", "MPI": "MPI([MPI])",
                "PETSc": "PETSc([PETSc + hypre])"}.get(r, f"{r}[{r}/]")

    lines = ["```mermaid", "flowchart LR"]
    named = set()
    for a, b in sorted(edges):
        na = node(a) if a not in named else a.replace("coupling", "seam")
        named.add(a)
        nb = node(b) if b not in named else b.replace("coupling", "seam")
        named.add(b)
        lines.append(f"  {na} --> {nb}")
    lines.append("```")
    return "\n".join(lines)


def self_test():
    """Each kind of wrong-way include in a made-up tree must be reported; a clean tree must not."""
    files = {
        "sph/ok.hpp": '#include "vec.hpp"\n#include <vector>\n',
        "sph/vec.hpp": "",
        "coupling/dem_state.hpp": '#include "vec.hpp"\n',
        "coupling/case/case_file.hpp": "",
        "coupling/resolved/pms.hpp": '#include "case/case_file.hpp"\n#include "dem_state.hpp"\n',
        "coupling/unresolved/drag.hpp": '#include "case/case_file.hpp"\n',
        "coupling/run/run.cpp": '#include "resolved/pms.hpp"\n#include "unresolved/drag.hpp"\n',
    }
    wrong = {
        "sph/bad_room.hpp": ('#include "case/case_file.hpp"\n', "sph/ includes case/case_file.hpp"),
        "sph/bad_liggghts.hpp": ('#include "lammps.h"\n', "sph/ includes lammps.h (LIGGGHTS)"),
        "sph/bad_mpi.hpp": ("#include <mpi.h>\n", "sph/ includes mpi.h (MPI)"),
        "sph/bad_petsc.hpp": ("#include <petscksp.h>\n", "sph/ includes petscksp.h (PETSc)"),
        "coupling/unresolved/bad.cpp": ('#include "resolved/pms.hpp"\n',
                                        "unresolved/ includes resolved/pms.hpp"),
        "coupling/resolved/bad.cpp": ('#include "unresolved/drag.hpp"\n',
                                      "resolved/ includes unresolved/drag.hpp"),
        "coupling/case/bad.cpp": ('#include "run/run.cpp"\n', "case/ includes run/run.cpp"),
        "coupling/io/bad.cpp": ('#include "nowhere.hpp"\n', 'cannot find "nowhere.hpp"'),
        "sph/long.cpp": ("//\n" * (MAX_LINES + 1), "more than 500"),
    }
    failures = []
    with tempfile.TemporaryDirectory() as root:
        lig = os.path.join(root, "liggghts_headers")
        os.makedirs(lig)
        open(os.path.join(lig, "lammps.h"), "w").close()

        def put(name, text):
            path = os.path.join(root, name)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w") as f:
                f.write(text)

        for name, text in files.items():
            put(name, text)
        _, problems = scan(root, lig)
        if problems:
            failures.append(f"clean tree reported {problems}")
        for name, (text, expected) in wrong.items():
            put(name, text)
            _, problems = scan(root, lig)
            if not any(name in p and expected in p for p in problems):
                failures.append(f"{name}: expected a problem with '{expected}', got {problems}")
            os.remove(os.path.join(root, name))
    for f in failures:
        print(f, file=sys.stderr)
    print(f"layout self-test: {len(wrong)} wrong-way includes planted, "
          f"{len(wrong) - len(failures)} caught")
    return 1 if failures else 0


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--root", default=os.path.dirname(here))
    ap.add_argument("--liggghts-include", default="/usr/include/liggghts")
    ap.add_argument("--doc", help="a Markdown file that must hold the current room graph")
    ap.add_argument("--graph", action="store_true", help="print the room graph and exit")
    ap.add_argument("--self-test", action="store_true", help="check the checker and exit")
    args = ap.parse_args()
    if args.self_test:
        return self_test()
    edges, problems = scan(args.root, args.liggghts_include)
    picture = graph(edges)
    if args.graph:
        print(picture)
        return 0
    if args.doc:
        text = open(args.doc, encoding="utf-8").read()
        if DOC_BEGIN not in text or DOC_END not in text:
            problems.append(f"{args.doc}: no room graph between '{DOC_BEGIN}' and '{DOC_END}'")
        else:
            shown = text.split(DOC_BEGIN, 1)[1].split(DOC_END, 1)[0].strip()
            if shown != picture:
                problems.append(f"{args.doc}: the room graph is out of date; replace it with the "
                                f"output of scripts/check_layout.py --graph")
    for p in problems:
        print(p, file=sys.stderr)
    n_edges = sum(edges.values())
    print(f"layout: {len(edges)} room arrows from {n_edges} includes, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
