#!/usr/bin/env python3
"""How far `skelconv skeletonize` moves when the same shape is rotated or renumbered.

Writes, for each OFF mesh, rotated copies (a random axis and angle per
seed) and renumbered copies (the vertices and the triangles in a random
order, each triangle's corners turned by a random step, its orientation
kept), all with fixed seeds, runs `skelconv skeletonize COPY -o OUT.json
--report R.json --report-stages result --measure-divisions 120` on the
original and every copy, and prints one row per run: Hausdorff and RMS (%
of the diagonal), χ in → out, components in → out, primitives, seconds,
and whether the skeleton file is the same bytes as the original's.

A rotation changes every coordinate by a rounding and the axis-aligned
bounding box (hence the diagonal every length is relative to), so its
result may move; a renumbering changes no coordinate, so a reconstruction
that does not depend on the file's order gives the same bytes.

Scaled copies (--scale FACTOR, repeatable) multiply every coordinate by
FACTOR and move the shape far from the origin, by a fixed-seed direction
times 100 scaled diagonals: every length the reconstruction uses is
relative to the diagonal, so its relative numbers (H, RMS, χ, components,
primitives) should be the original's up to the roundings of the scaling
and of the coordinates' larger exponent.

    copies_spread.py SKELCONV WORKDIR [--rotations N] [--renumberings N] [--scale F]... SHAPE[:ROT[:REN]]...

A SHAPE is a path, or a name under $CGAL_MESHES (default data/meshes: CGAL's
sample meshes, from /usr/share/doc/libcgal-dev/data.tar.gz of libcgal-demo); ROT and REN override the counts for that shape.
"""
import argparse
import hashlib
import json
import os
import pathlib
import subprocess
import sys
import time

import numpy as np

# CGAL's sample meshes, unpacked from the Debian package libcgal-demo:
#   tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C DIR  (then DIR/data/meshes)
CGAL_MESHES = pathlib.Path(os.environ.get("CGAL_MESHES", "data/meshes"))


def read_off(path):
    words = []
    for line in path.read_text().splitlines():
        line = line.split("#", 1)[0].split()
        words.extend(line)
    if not words[0].upper().endswith("OFF"):
        raise SystemExit(f"{path}: not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    # COFF: each vertex line carries its colour, RGBA, after x y z (CGAL's
    # dino); the copies are written without it.
    width = 7 if words[0].upper() == "COFF" else 3
    at = 4
    v = np.array(words[at:at + width * nv], dtype=float).reshape(nv, width)[:, :3]
    at += width * nv
    faces = []
    for _ in range(nf):
        n = int(words[at])
        faces.append([int(w) for w in words[at + 1:at + 1 + n]])
        at += 1 + n
    return v, faces


def write_off(path, v, faces):
    lines = ["OFF", f"{len(v)} {len(faces)} 0"]
    lines += ["%.17g %.17g %.17g" % tuple(p) for p in v]
    lines += [" ".join(str(x) for x in [len(f)] + list(f)) for f in faces]
    path.write_text("\n".join(lines) + "\n")


def rotation(seed, axis=None, angle=None):
    if axis is None:
        rng = np.random.default_rng(seed)
        axis = rng.normal(size=3)
        angle = rng.uniform(0.2, np.pi)
    axis = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k, axis, angle


def scaled(v, factor, seed):
    """v times factor, moved by 100 scaled diagonals in a fixed-seed direction."""
    rng = np.random.default_rng(2000 + seed)
    direction = rng.normal(size=3)
    direction /= np.linalg.norm(direction)
    diagonal = np.linalg.norm(v.max(axis=0) - v.min(axis=0))
    return v * factor + direction * (100 * factor * diagonal)


def renumbered(v, faces, seed):
    rng = np.random.default_rng(1000 + seed)
    perm = rng.permutation(len(v))  # new index of old vertex i: perm[i]
    nv = np.empty_like(v)
    nv[perm] = v
    order = rng.permutation(len(faces))
    out = []
    for fi in order:
        f = [int(perm[i]) for i in faces[fi]]
        s = int(rng.integers(len(f)))
        out.append(f[s:] + f[:s])
    return nv, out


def run(binary, mesh, out, extra):
    out.mkdir(parents=True, exist_ok=True)
    skeleton, report = out / "skeleton.json", out / "report.json"
    t0 = time.time()
    p = subprocess.run([binary, "skeletonize", str(mesh), "-o", str(skeleton), "--report", str(report),
                        "--report-stages", "result", "--measure-divisions", "120", *extra],
                       capture_output=True, text=True)
    seconds = time.time() - t0
    (out / "log.txt").write_text(p.stderr + p.stdout)
    if p.returncode != 0:
        return {"rc": p.returncode, "seconds": seconds}
    r = json.loads(report.read_text())
    s = r["stages"][-1]
    return {"rc": 0, "H": 100 * s["hausdorff"], "RMS": 100 * s["rms"],
            "chi": (r["input_euler_characteristic"], s["euler_characteristic"]),
            "comp": (r["input_components"], s["components"]), "prims": sum(s["primitives"].values()),
            "stage": s["name"], "seconds": seconds,
            "digest": hashlib.sha256(skeleton.read_bytes()).hexdigest()[:12]}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("skelconv")
    ap.add_argument("workdir", type=pathlib.Path)
    ap.add_argument("shapes", nargs="+")
    ap.add_argument("--rotations", type=int, default=2)
    ap.add_argument("--renumberings", type=int, default=1)
    ap.add_argument("--axis-angle", action="append", default=[], metavar="X,Y,Z,RADIANS",
                    help="one more rotated copy of every shape, about this axis by this angle")
    ap.add_argument("--scale", action="append", type=float, default=[], metavar="FACTOR",
                    help="one more copy of every shape, scaled by FACTOR and moved 100 scaled diagonals away")
    ap.add_argument("--extra", default="", help="more options for skeletonize, one string")
    a = ap.parse_args()
    extra = a.extra.split()
    print("| shape | copy | H / RMS % | χ | components | primitives | s | same bytes |")
    print("|---|---|---|---|---|---|---|---|")
    failed = 0
    for spec in a.shapes:
        name, *counts = spec.split(":")
        path = pathlib.Path(name)
        if not path.exists():
            path = CGAL_MESHES / name
        if not path.exists():
            path = CGAL_MESHES / (name + ".off")
        rotations = int(counts[0]) if len(counts) > 0 else a.rotations
        renumberings = int(counts[1]) if len(counts) > 1 else a.renumberings
        v, faces = read_off(path)
        stem = path.stem
        copies = [("original", path)]
        for seed in range(renumberings):
            m = a.workdir / stem / f"renumbered{seed}.off"
            m.parent.mkdir(parents=True, exist_ok=True)
            write_off(m, *renumbered(v, faces, seed))
            copies.append((f"renumbered {seed}", m))
        for seed in range(rotations):
            r, axis, angle = rotation(seed)
            m = a.workdir / stem / f"rotated{seed}.off"
            m.parent.mkdir(parents=True, exist_ok=True)
            write_off(m, v @ r.T, faces)
            copies.append((f"rotated {seed} ({angle:.2f} rad about {np.round(axis, 2).tolist()})", m))
        for k, spec_rot in enumerate(a.axis_angle):
            x, y, z, angle = (float(w) for w in spec_rot.split(","))
            r, axis, angle = rotation(None, (x, y, z), angle)
            m = a.workdir / stem / f"rotated_given{k}.off"
            m.parent.mkdir(parents=True, exist_ok=True)
            write_off(m, v @ r.T, faces)
            copies.append((f"rotated given{k} ({angle:.2f} rad about {np.round(axis, 2).tolist()})", m))
        for k, factor in enumerate(a.scale):
            m = a.workdir / stem / f"scaled{k}.off"
            m.parent.mkdir(parents=True, exist_ok=True)
            write_off(m, scaled(v, factor, k), faces)
            copies.append((f"scaled {k} (×{factor:g}, moved 100 diagonals)", m))
        first = None
        for label, m in copies:
            res = run(a.skelconv, m, a.workdir / stem / label.split(" (")[0].replace(" ", ""), extra)
            if res["rc"] != 0:
                print(f"| {stem} | {label} | exit {res['rc']} | | | | {res['seconds']:.0f} | |", flush=True)
                failed += 1
                continue
            if first is None:
                first = res
            same = "yes" if res["digest"] == first["digest"] else "no"
            chi, comp = res["chi"], res["comp"]
            mark = "" if chi[0] == chi[1] and comp[0] == comp[1] else " **"
            print(f"| {stem} | {label} | {res['H']:.2f} / {res['RMS']:.3f} | {chi[0]} → {chi[1]}{mark} | "
                  f"{comp[0]} → {comp[1]} | {res['prims']} {res['stage']} | {res['seconds']:.0f} | {same} |",
                  flush=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
