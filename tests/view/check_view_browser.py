#!/usr/bin/python3
"""The page of `skelconv view` in a real browser: headless Chromium (WebGL2
on its software renderer SwiftShader) renders fixed views of a skeleton, and
the silhouette must match the projection of `skelconv mesh` of the same
skeleton seen by the same camera (intersection over union >= 0.98).

    check_view_browser.py SKELCONV SKELETON.json... [--out DIR] [--iou 0.98]
                          [--size 480x360] [--frames N] [--inject-fault]
                          [--timing-only]

Silhouettes: a pixel of the page is on the surface when it is not the white
background (the shading never reaches white in green and blue,
view_march.glsl); a pixel of the mesh's image when its centre lies in a
projected triangle (the page casts one ray through each pixel centre, no
anti-aliasing). The camera of both is the page's (yaw, pitch and distance
passed in the page's query string; basis() in view_template.html).

--frames N also renders N frames in the page and prints the mean frame time
(SwiftShader on this machine's CPU: an upper bound for any GPU).
--timing-only skips the silhouettes: only the frame time (--frames, default 10)
of each page, the measurement of docs/view.md's table.
--inject-fault renders the page at 0.8 x the file's iso (the page's own iso
parameter) against the mesh of the file's iso: the check must then fail, a
page silhouette larger than the mesh's (the main job runs both).
A view whose silhouettes differ prints "CHECK-FAILED: silhouette IoU ...
below ..., page larger/smaller than the mesh: NAME view K"; a blank page or
a mesh with no pixel prints "CHECK-FAILED: nothing to compare".
--out DIR keeps the screenshots and mask images (PNG) there.
Needs /usr/bin/chromium (Debian package chromium) and python3-numpy.
"""
import argparse
import json
import math
import os
import pathlib
import re
import struct
import subprocess
import sys
import tempfile
import zlib

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from read_png import read_png  # noqa: E402  (tests/read_png.py)

CHROMIUM_FLAGS = ["--headless=new", "--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                  "--no-sandbox", "--disable-gpu-sandbox", "--disable-background-networking",
                  "--disable-component-update", "--disable-sync", "--no-first-run", "--hide-scrollbars"]
DATA = re.compile(r'<script id="skeleton_data" type="application/json">\n(.*?)</script>', re.S)
# Fixed views (yaw, pitch in radians): oblique, from the top, from the side.
VIEWS = [(0.6, 0.5), (0.0, 1.45), (1.5707963, 0.0)]


def read_png_array(path):
    """The RGB channels of a PNG (what Chromium writes) as an array."""
    try:
        width, height, channels, rows = read_png(pathlib.Path(path).read_bytes())
    except ValueError as error:
        sys.exit(f"check_view_browser: {path}: {error}")
    image = np.frombuffer(b"".join(rows), dtype=np.uint8).astype(np.int32)
    return image.reshape(height, width, channels)[:, :, :3]


def write_mask_png(mask, path):
    """A black-on-white image of a boolean mask, for looking at."""
    height, width = mask.shape
    rows = b"".join(b"\x00" + bytes(np.where(mask[y], 0, 255).astype(np.uint8)) for y in range(height))
    chunk = lambda kind, body: struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    pathlib.Path(path).write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0))
                                   + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def read_obj(path):
    vertices, faces = [], []
    for line in pathlib.Path(path).read_text().splitlines():
        if line.startswith("v "):
            vertices.append([float(v) for v in line.split()[1:4]])
        elif line.startswith("f "):
            faces.append([int(v.split("/")[0]) - 1 for v in line.split()[1:4]])
    return np.array(vertices), np.array(faces)


def camera(data, yaw, pitch, distance):
    """basis() of view_template.html."""
    back = np.array([math.cos(pitch) * math.sin(yaw), math.sin(pitch), math.cos(pitch) * math.cos(yaw)])
    eye = np.array(data["centre"]) + distance * back
    forward = -back
    right = np.cross(forward, [0.0, 1.0, 0.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    return eye, right, up, forward


def mesh_mask(vertices, faces, data, view, width, height):
    """The pixels whose centre lies in a projected triangle of the mesh."""
    frame = data["frame"]
    page = (vertices - np.array(frame["centre"])) / frame["scale"]
    eye, right, up, forward = camera(data, *view)
    rel = page - eye
    z = rel @ forward
    tan_half = math.tan(0.5 * data["fov"])
    # The shader's ray: forward + tan_half (ndc.x right + ndc.y up) with
    # ndc = (2 fragcoord - resolution) / height.
    fx = (rel @ right) / (z * tan_half) * height / 2 + width / 2
    fy = height / 2 - (rel @ up) / (z * tan_half) * height / 2  # rows from the top
    mask = np.zeros((height, width), dtype=bool)
    for a, b, c in faces:
        xs, ys = fx[[a, b, c]], fy[[a, b, c]]
        x0, x1 = max(int(math.floor(xs.min() - 0.5)), 0), min(int(math.ceil(xs.max() - 0.5)), width - 1)
        y0, y1 = max(int(math.floor(ys.min() - 0.5)), 0), min(int(math.ceil(ys.max() - 0.5)), height - 1)
        if x1 < x0 or y1 < y0:
            continue
        px, py = np.meshgrid(np.arange(x0, x1 + 1) + 0.5, np.arange(y0, y1 + 1) + 0.5)
        e = [(xs[(k + 1) % 3] - xs[k]) * (py - ys[k]) - (ys[(k + 1) % 3] - ys[k]) * (px - xs[k]) for k in range(3)]
        inside = ((e[0] >= 0) & (e[1] >= 0) & (e[2] >= 0)) | ((e[0] <= 0) & (e[1] <= 0) & (e[2] <= 0))
        mask[y0:y1 + 1, x0:x1 + 1] |= inside
    return mask


def silhouette_iou(mesh, page):
    """Intersection over union of two silhouettes (boolean masks); 0 when
    both are empty."""
    union = np.count_nonzero(mesh | page)
    return np.count_nonzero(mesh & page) / union if union else 0.0


def screenshot(chromium, page, query, width, height, png, profile, dump=False):
    url = pathlib.Path(page).resolve().as_uri() + "?" + query
    mode = ["--dump-dom"] if dump else [f"--screenshot={png}"]
    run = subprocess.run([chromium, *CHROMIUM_FLAGS, f"--user-data-dir={profile}", f"--window-size={width},{height}",
                          *mode, url], capture_output=True, text=True, timeout=600)
    if dump:
        return run.stdout
    if not os.path.exists(png):
        sys.exit("check_view_browser: no screenshot (chromium stderr tail):\n" + run.stderr[-2000:])
    return None


def frame_time(args, page, data, name, scratch):
    dom = screenshot(args.chromium, page, f"panel=1&frames={args.frames}&size={args.width}x{args.height}", args.width, args.height, None,
                     pathlib.Path(scratch) / "profile", dump=True)
    found = re.search(r"frame_ms ([0-9.]+) at (\d+x\d+)", dom)
    print(f"check_view_browser: {name}: {len(data['primitives'])} primitives, {data.get('mode', '')}, "
          + (f"{found.group(1)} ms per frame at {found.group(2)} (SwiftShader)" if found else "no frame time"),
          flush=True)


def check_skeleton(args, skeleton, scratch, out):
    name = pathlib.Path(skeleton).stem
    page, obj = pathlib.Path(scratch) / (name + ".html"), pathlib.Path(scratch) / (name + ".obj")
    subprocess.run([args.skelconv, "view", skeleton, "-o", str(page)], check=True, capture_output=True)
    data = json.loads(DATA.search(page.read_text()).group(1).replace("<\\/", "</"))
    if args.timing_only:
        frame_time(args, page, data, name, scratch)
        return 1.0
    # A fine mesh: its facets are chords inside a convex surface, and the
    # default size (box diagonal / 50) leaves a ring of ~1 % of the pixels.
    # Size: 1/40 of the surface's extent (the first camera's framing radius).
    extent = data["distance"] * math.sin(0.5 * data["fov"]) / 1.25 * data["frame"]["scale"]
    subprocess.run([args.skelconv, "mesh", skeleton, "-o", str(obj), "--quiet", "--size", repr(extent / 40),
                    "--distance", repr(extent / 800)], check=True, capture_output=True)
    vertices, faces = read_obj(obj)
    width, height = args.width, args.height
    worst = 1.0
    for k, (yaw, pitch) in enumerate(VIEWS):
        query = f"overlay=0&panel=0&yaw={yaw}&pitch={pitch}&distance={data['distance']!r}"
        if args.inject_fault:
            query += f"&iso={0.8 * data['iso']!r}"
        png = pathlib.Path(out) / f"{name}_view{k}.png"
        if png.exists():
            png.unlink()
        screenshot(args.chromium, page, query, width, height, png, pathlib.Path(scratch) / "profile")
        page_mask = (read_png_array(png)[:, :, 1:] < 250).any(axis=2)
        mask = mesh_mask(vertices, faces, data, (yaw, pitch, data["distance"]), width, height)
        write_mask_png(mask ^ page_mask, pathlib.Path(out) / f"{name}_view{k}_difference.png")
        iou = silhouette_iou(mask, page_mask)
        worst = min(worst, iou)
        page_px, mesh_px = np.count_nonzero(page_mask), np.count_nonzero(mask)
        print(f"check_view_browser: {name} view {k} (yaw {yaw}, pitch {pitch}): IoU {iou:.4f} "
              f"(page {page_px} px, mesh {mesh_px} px)")
        # A blank page (a shader that failed) or an empty mesh compares
        # nothing: a failure of its own, not a silhouette mismatch.
        if page_px == 0 or mesh_px == 0:
            print(f"CHECK-FAILED: nothing to compare: {name} view {k}: page {page_px} px, mesh {mesh_px} px")
        elif iou < args.iou:
            print(f"CHECK-FAILED: silhouette IoU {iou:.4f} below {args.iou}, page "
                  f"{'larger' if page_px > mesh_px else 'smaller'} than the mesh: {name} view {k}")
    if args.frames:
        frame_time(args, page, data, name, scratch)
    return worst


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("skelconv")
    ap.add_argument("skeletons", nargs="+")
    ap.add_argument("--out", default=None)
    ap.add_argument("--iou", type=float, default=0.98)
    ap.add_argument("--size", default="480x360")
    ap.add_argument("--frames", type=int, default=0)
    ap.add_argument("--chromium", default="/usr/bin/chromium")
    ap.add_argument("--inject-fault", action="store_true")
    ap.add_argument("--timing-only", action="store_true")
    args = ap.parse_args()
    if args.timing_only and not args.frames:
        args.frames = 10
    args.width, args.height = (int(v) for v in args.size.split("x"))
    if not os.path.exists(args.chromium):
        sys.exit(f"check_view_browser: {args.chromium} not found (Debian package chromium)")
    with tempfile.TemporaryDirectory() as scratch:
        out = args.out or scratch
        os.makedirs(out, exist_ok=True)
        worst = min(check_skeleton(args, s, scratch, out) for s in args.skeletons)
    print(f"check_view_browser: worst IoU {worst:.4f} (required >= {args.iou})")
    sys.exit(0 if worst >= args.iou else 1)


if __name__ == "__main__":
    main()
