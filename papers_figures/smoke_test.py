#!/usr/bin/python3
"""ctest smoke renders (papers_figures/CMakeLists.txt):

  smoke_test.py 2d --skelconv BIN --out DIR   draws one 2-D figure twice (quick
      resolution, image on): the PNG is 640 px wide, not blank, and the two runs
      give the same bytes;
  smoke_test.py 3d --sphere BIN --out DIR     writes a UV sphere with
      skelconv::write_mesh as binary and as ASCII PLY, renders both with POV-Ray:
      the same pixels from both files, twice the same bytes, the sphere drawn
      (centre coloured, corners background), and the same silhouette as
      POV-Ray's own isosurface{} of the sphere (the camera and axis conventions);
  smoke_test.py 3d-mesh --skelconv BIN --out DIR   draws one registered shaded
      figure (Hubert 2012 Figure 6 (3-D): `skelconv mesh` + POV-Ray) twice at
      quick resolution, image on: 640 px wide, drawn, the same bytes."""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "render3d"))

import matplotlib  # noqa: E402
import numpy as np  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FIGURE_2D = "hubert2012_fig03"
FIGURE_3D = "hubert2012_fig06_3d"
SIZE_3D = (160, 120)


def fail(message):
    print(f"smoke_test: FAIL: {message}", file=sys.stderr)
    sys.exit(1)


def read(path):
    with open(path, "rb") as handle:
        return handle.read()


def smoke_figure(args, name):
    """Draws the registered figure twice (quick, image on): (PNG path, pixels) after checking
    that it is 640 px wide, not blank, and the same bytes both times."""
    images = []
    for run in ("a", "b"):
        out = os.path.join(args.out, run)
        subprocess.run([sys.executable, os.path.join(HERE, "run.py"), "--skelconv", args.skelconv, "--out", out,
                        "--only", name, "--quick"], check=True)
        images.append(os.path.join(out, f"{name}.png"))
    pixels = plt.imread(images[0])
    if pixels.shape[1] != 640:
        fail(f"{images[0]} is {pixels.shape[1]} px wide, not 640")
    if pixels[..., :3].std() < 0.05:
        fail(f"{images[0]} looks blank")
    if read(images[0]) != read(images[1]):
        fail(f"two runs of {name} gave different PNG bytes")
    return images[0], pixels


def smoke_2d(args):
    _, pixels = smoke_figure(args, FIGURE_2D)
    print(f"smoke_test 2d: {FIGURE_2D} ok, {pixels.shape[1]}×{pixels.shape[0]}, deterministic")


def smoke_3d(args):
    from ply import PlyError, read_ply
    from povray import render
    os.makedirs(args.out, exist_ok=True)
    pngs = []
    for encoding in ("binary", "ascii"):
        mesh = os.path.join(args.out, f"sphere_{encoding}.ply")
        subprocess.run([args.sphere, mesh, "--rings", "16"] + (["--ascii"] if encoding == "ascii" else []), check=True)
        vertices, normals, faces = read_ply(mesh)
        if normals is None or len(faces) == 0:
            fail(f"{mesh}: no normals or no faces read")
        for run in ("a", "b") if encoding == "binary" else ("a",):
            png = os.path.join(args.out, f"sphere_{encoding}_{run}.png")
            render(vertices, normals, faces, png, *SIZE_3D)
            pngs.append(png)
    truncated = os.path.join(args.out, "truncated.ply")
    with open(truncated, "wb") as handle:
        handle.write(read(os.path.join(args.out, "sphere_binary.ply"))[:-5])
    try:
        read_ply(truncated)
        fail("a truncated PLY was read without an error")
    except PlyError as error:
        print(f"smoke_test 3d: truncated PLY refused: {error}")
    if read(pngs[0]) != read(pngs[1]):
        fail("two renders of the same mesh gave different bytes")
    if read(pngs[0]) != read(pngs[2]):
        fail("the binary and the ASCII PLY of the same mesh rendered differently")
    # POV-Ray's own isosurface of the same sphere, same camera: the silhouettes must agree
    from povray import framing, isosurface, render_scene, scene
    centre, radius = framing(vertices)
    iso_png = os.path.join(args.out, "sphere_isosurface.png")
    body = isosurface("x*x + y*y + (z - 0.5)*(z - 0.5) - 1", [-1.1, -1.1, -0.6], [1.1, 1.1, 1.6])
    render_scene(scene(body, centre, radius, *SIZE_3D), iso_png, *SIZE_3D)
    mesh_mask = plt.imread(pngs[0])[..., :3].min(axis=2) < 0.99
    iso_mask = plt.imread(iso_png)[..., :3].min(axis=2) < 0.99
    differ = float(np.mean(mesh_mask != iso_mask))
    if differ > 0.01:
        fail(f"mesh and isosurface silhouettes differ on {differ:.1%} of the pixels")
    pixels = plt.imread(pngs[0])[..., :3]
    h, w = pixels.shape[:2]
    centre, corner = pixels[h // 2, w // 2], pixels[0, 0]
    if corner.min() < 0.99:
        fail(f"corner pixel {corner} is not the white background")
    if abs(float(centre[0]) - float(centre[2])) < 0.1:
        fail(f"centre pixel {centre} is not the surface colour")
    print(f"smoke_test 3d: sphere rendered {w}×{h}, binary = ASCII, deterministic, "
          f"silhouette = POV-Ray isosurface's on {1 - differ:.2%} of the pixels")


def smoke_3d_mesh(args):
    _, pixels = smoke_figure(args, FIGURE_3D)
    drawn = float(np.mean(pixels[..., :3].min(axis=2) < 0.99))
    if not 0.05 < drawn < 0.9:
        fail(f"{FIGURE_3D}: the surfaces cover {drawn:.1%} of the picture")
    print(f"smoke_test 3d-mesh: {FIGURE_3D} ok, {pixels.shape[1]}×{pixels.shape[0]} ({drawn:.1%} drawn), "
          "deterministic")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("which", choices=("2d", "3d", "3d-mesh"))
    parser.add_argument("--skelconv")
    parser.add_argument("--sphere")
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    {"2d": smoke_2d, "3d": smoke_3d, "3d-mesh": smoke_3d_mesh}[args.which](args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
