#!/usr/bin/env python3
"""`skelconv skeletonize --report-image` on a small mesh, checked as a picture.

Usage: check_report_image.py SKELCONV MESH OUT_DIR LAYOUT [skeletonize options...]

LAYOUT is the layout the mesh must get: `square` (a shape about as long as
wide) or `wide` (a long one, laid across the picture). Runs the command
twice and checks that
  * both runs write the same bytes (same input, same picture);
  * the file is a PNG of the expected layout, 8-bit RGB: square, 3 × 2
    square panels (1,308 × 952 pixels); wide, 2 × 3 panels 630 pixels wide
    and at least 140 high (1,296 pixels wide), in which the shape spans
    at least 80% of each panel's width (it lies across, not a sliver);
  * every panel shows something: at least 2% of its pixels are not the
    white background (an empty camera, a surface drawn behind the far
    plane or a panel pasted off the picture fails here);
  * the two surface columns are coloured by the sequential map (some of
    their pixels are far from grey) and the skeleton column holds its
    orange sheets or dark red tubes.
Standard library only (the PNG decoded by tests/read_png.py).
"""
import pathlib
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
from read_png import read_png  # noqa: E402  (tests/read_png.py)

PANEL, GAP, TITLE = 420, 12, 36
# square: 3 panels of 420 + 4 gaps of 12; title 36 + 2 × 420 + footer 76
SQUARE_WIDTH, SQUARE_HEIGHT = 3 * PANEL + 4 * GAP, TITLE + 2 * PANEL + 76
# wide: 2 panels of 630 + 3 gaps; title 36 + 3 × (a label 24 + the panel) + footer 76 + a bar line 24
WIDE_PANEL, LABEL, WIDE_WIDTH, WIDE_EXTRA = 630, 24, 2 * 630 + 3 * GAP, TITLE + 3 * 24 + 76 + 24


def panels(layout, height):
    """(name, x0, y0, width, height, skip) of the six panels; skip: rows at the top holding a label."""
    kinds = ["input", "skeleton", "result"]
    if layout == "square":
        return [(kinds[k] + ["/front", "/back"][v], GAP + k * (PANEL + GAP), TITLE + v * PANEL, PANEL, PANEL, 24)
                for v in range(2) for k in range(3)]
    ph = (height - WIDE_EXTRA) // 3
    return [(kinds[k] + ["/front", "/back"][v], GAP + v * (WIDE_PANEL + GAP), TITLE + k * (LABEL + ph) + LABEL,
             WIDE_PANEL, ph, 0) for v in range(2) for k in range(3)]


def panel_pixels(rows, x0, y0, w, h, skip):
    for y in range(y0 + skip, y0 + h, 2):
        line = rows[y]
        for x in range(x0, x0 + w, 2):
            yield x, (line[3 * x], line[3 * x + 1], line[3 * x + 2])


def main():
    skelconv, mesh, out, layout = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3]), sys.argv[4]
    if layout not in ("square", "wide"):
        print(f"LAYOUT must be square or wide, not {layout!r}")
        return 2
    out.mkdir(parents=True, exist_ok=True)
    images = []
    for run in (1, 2):
        image = out / f"report_{run}.png"
        image.unlink(missing_ok=True)
        subprocess.run([skelconv, "skeletonize", mesh, "-o", str(out / f"skeleton_{run}.json"), "--quiet",
                        "--report-image", str(image)] + sys.argv[5:], check=True, stdout=subprocess.DEVNULL)
        images.append(image.read_bytes())
    failures = []
    if images[0] != images[1]:
        failures.append("two runs on the same input wrote different pictures")
    width, height, channels, rows = read_png(images[0])
    expected_width = SQUARE_WIDTH if layout == "square" else WIDE_WIDTH
    wide_ok = layout == "wide" and (height - WIDE_EXTRA) % 3 == 0 and (height - WIDE_EXTRA) // 3 >= 140
    if channels != 3 or width != expected_width or (layout == "square" and height != SQUARE_HEIGHT) or \
            (layout == "wide" and not wide_ok):
        failures.append(f"picture is {width} × {height} × {channels}, not the {layout} layout")
    else:
        for name, x0, y0, w, h, skip in panels(layout, height):
            sampled = list(panel_pixels(rows, x0, y0, w, h, skip))
            pixels = [p for _, p in sampled]
            drawn = [p for p in pixels if p != (255, 255, 255)]
            if len(drawn) < 0.02 * len(pixels):
                failures.append(f"panel {name}: only {len(drawn)} of {len(pixels)} pixels drawn")
            if not name.startswith("skeleton"):
                coloured = [p for p in drawn if max(p) - min(p) > 60]
                if len(coloured) < 0.01 * len(pixels):
                    failures.append(f"panel {name}: not coloured by distance ({len(coloured)} coloured pixels)")
                if layout == "wide":
                    xs = [x for x, p in sampled if p != (255, 255, 255)]
                    span = (max(xs) - min(xs)) / w if xs else 0.0
                    if span < 0.8:
                        failures.append(f"panel {name}: the shape spans {span:.0%} of the panel's width, not across it")
            else:
                warm = [p for p in drawn if p[0] > p[2] + 60]
                if not warm:
                    failures.append(f"panel {name}: no sheet or tube drawn")
            print(f"{name}: {len(drawn)} of {len(pixels)} sampled pixels drawn")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
