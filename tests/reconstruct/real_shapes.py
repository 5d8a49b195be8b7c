#!/usr/bin/env python3
"""The real-shape table of docs/reconstruction_medial.md, measured.

Runs `skelconv skeletonize` with --method curve and with --method medial on
closed meshes a user would try (CGAL's sample meshes from the Debian package
libcgal-demo, and the test shapes of tests/data/reconstruct), each with
--report --report-stages result, and prints one Markdown row per shape: the
two-sided Hausdorff and RMS distances (% of the bounding-box diagonal), the
Euler characteristic in and out, the primitives and the seconds of each path,
the path `--method auto` keeps (the one whose surface keeps the Euler
characteristic, then the smaller Hausdorff distance: reconstruct.cpp,
choose_between) and whether that meets the goal for a reconstruction (H <= 1%, RMS <=
0.2%, the Euler characteristic kept). Refused meshes get their message.

The table between the markers in the docs must be what this run measures
(times aside, which vary): the test fails otherwise, so the docs cannot drift
from the code. `--write` rewrites the docs' table instead.

    real_shapes.py SKELCONV DOCS WORKDIR [--write]
"""
import json
import pathlib
import re
import subprocess
import sys
import tarfile
import time

CGAL_DATA = pathlib.Path("/usr/share/doc/libcgal-dev/data.tar.gz")  # package libcgal-demo
# (file, what it is); the CGAL meshes are 1,200-6,500 vertices.
CGAL_SHAPES = [
    ("hand.off", "a fist, scanned"),
    ("homer.off", "a cartoon character"),
    ("dino.off", "a toy dinosaur"),
    ("blobby.off", "a blob"),
    ("femur.off", "a bone"),
    ("fandisk.off", "a CAD part, sharp edges"),
    ("elk.off", "a CAD part with a hole"),
    ("cow.off", "a toy cow"),
    ("head.off", "a cartoon head"),
]
TEST_SHAPES = [
    ("sphere.ply", "a sphere"),
    ("cube.ply", "a cube, 8 vertices"),
    ("tetrahedron.obj", "a tetrahedron, 4 vertices"),
    ("tripod.ply", "a tripod of tubes"),
    ("torus.ply", "a torus"),
]
BEGIN, END = "<!-- real-shapes table: tests/reconstruct/real_shapes.py -->", "<!-- end of the real-shapes table -->"


def run(skelconv, mesh, method, work):
    out = work / f"{mesh.stem}_{method}"
    start = time.monotonic()
    p = subprocess.run([skelconv, "skeletonize", str(mesh), "-o", f"{out}.json", "--method", method, "--report",
                        f"{out}_report.json", "--report-stages", "result", "--quiet"], capture_output=True, text=True)
    seconds = time.monotonic() - start
    if p.returncode == 2:
        # "skelconv: error: PATH: message": the message, without the path.
        return {"refused": p.stderr.strip().split(": ", 3)[-1]}
    if p.returncode != 0:
        sys.exit(f"skelconv skeletonize {mesh} --method {method} exited {p.returncode}:\n{p.stderr}")
    report = json.loads(pathlib.Path(f"{out}_report.json").read_text())
    stage = report["stages"][-1]
    return {"stage": stage["name"], "h": 100 * stage["hausdorff"], "rms": 100 * stage["rms"],
            "chi_in": report["input_euler_characteristic"], "chi_out": stage["euler_characteristic"],
            "primitives": sum(stage["primitives"].values()), "seconds": seconds}


def cell(r):
    kept = "" if r["chi_out"] == r["chi_in"] else f", χ {r['chi_out']}"
    return f"{r['h']:.2f} / {r['rms']:.3f}{kept} ({r['primitives']} {r['stage']})"


def row(name, what, curve, medial):
    if "refused" in curve:
        return f"| {name} | {what} | refused: {curve['refused']} | | | |", None
    keeps = lambda r: r["chi_out"] == r["chi_in"]
    medial_wins = keeps(medial) != keeps(curve) and keeps(medial) or (
        keeps(medial) == keeps(curve) and medial["h"] < curve["h"])
    best = medial if medial_wins else curve
    goal = "yes" if best["h"] <= 1.0 and best["rms"] <= 0.2 and keeps(best) else "no"
    times = f"{curve['seconds']:.0f} s / {medial['seconds']:.0f} s"
    return (f"| {name} | {what} | χ {curve['chi_in']} | {cell(curve)} | {cell(medial)} | "
            f"{'medial' if medial_wins else curve['stage']} | {goal} |", times)


def main():
    skelconv, docs, work = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    write = "--write" in sys.argv[4:]
    if not CGAL_DATA.exists():
        sys.exit(f"{CGAL_DATA} is missing: install the Debian package libcgal-demo "
                 "(scripts/install_dependencies.sh --checks does)")
    work.mkdir(parents=True, exist_ok=True)
    with tarfile.open(CGAL_DATA) as archive:
        for name, _ in CGAL_SHAPES:
            member = archive.getmember(f"data/meshes/{name}")
            (work / name).write_bytes(archive.extractfile(member).read())
    data = pathlib.Path(__file__).resolve().parent.parent / "data" / "reconstruct"
    shapes = [(work / n, n, w) for n, w in CGAL_SHAPES] + [(data / n, n, w) for n, w in TEST_SHAPES]
    lines = ["| input | what | χ in | curve: H / RMS % | medial: H / RMS % | auto keeps | goal met |",
             "|---|---|---|---|---|---|---|"]
    for path, name, what in shapes:
        print(f"real_shapes: {name} ...", file=sys.stderr, flush=True)
        curve = run(skelconv, path, "curve", work)
        medial = curve if "refused" in curve else run(skelconv, path, "medial", work)
        line, times = row(name, what, curve, medial)
        print(line + (f"   [curve / medial: {times}]" if times else ""), flush=True)
        lines.append(line)
    table = "\n".join(lines)
    text = docs.read_text()
    table += "\n"
    pattern = re.compile(re.escape(BEGIN) + r"\n(.*?)" + re.escape(END), re.S)
    found = pattern.search(text)
    if found is None:
        sys.exit(f"{docs}: no table between the markers {BEGIN} and {END}")
    if write:
        docs.write_text(text[:found.start(1)] + table + text[found.end(1):])
        print(f"real_shapes: wrote the table of {docs}")
    elif found.group(1) != table:
        sys.exit(f"{docs}: its table differs from this run's; if the code changed on purpose, rerun with --write.\n"
                 f"measured:\n{table}\ndocumented:\n{found.group(1)}")
    else:
        print(f"real_shapes: {docs} holds this run's table")


if __name__ == "__main__":
    main()
