#!/usr/bin/python3
"""render_mesh.py MESH.ply OUT.png [--size W H]: a shaded POV-Ray picture of a
mesh written by skelconv (docs/figures.md, "3-D figures")."""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ply import PlyError, read_ply  # noqa: E402
from povray import render  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("mesh")
    parser.add_argument("png")
    parser.add_argument("--size", nargs=2, type=int, default=(640, 480), metavar=("W", "H"))
    args = parser.parse_args()
    try:
        vertices, normals, faces = read_ply(args.mesh)
    except (OSError, PlyError) as error:
        print(f"render_mesh: {error}", file=sys.stderr)
        return 2
    if len(faces) == 0:
        print(f"render_mesh: {args.mesh}: the mesh has no triangles", file=sys.stderr)
        return 2
    try:
        render(vertices, normals, faces, args.png, *args.size)
    except RuntimeError as error:
        print(f"render_mesh: {error}", file=sys.stderr)
        return 1
    print(f"render_mesh: {args.png} ({len(vertices)} vertices, {len(faces)} triangles)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
