#!/usr/bin/env python3
"""`skelconv skeletonize --report-image` on a small mesh, checked as a picture.

Usage: check_report_image.py SKELCONV MESH OUT_DIR [skeletonize options...]

Runs the command twice and checks that
  * both runs write the same bytes (same input, same picture);
  * the file is a PNG of 3 × 2 panels (1,308 × 952 pixels, 8-bit RGB);
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

WIDTH, HEIGHT = 1308, 952  # 3 panels of 420 + 4 gaps of 12; title 36 + 2 × 420 + footer 76
PANEL, GAP, TITLE = 420, 12, 36


def panel_pixels(rows, column, row):
    x0, y0 = GAP + column * (PANEL + GAP), TITLE + row * PANEL
    # The panel's top-left corner holds the "front"/"back" label: skip it.
    for y in range(y0 + 24, y0 + PANEL, 2):
        line = rows[y]
        for x in range(x0, x0 + PANEL, 2):
            yield line[3 * x], line[3 * x + 1], line[3 * x + 2]


def main():
    skelconv, mesh, out = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3])
    out.mkdir(parents=True, exist_ok=True)
    images = []
    for run in (1, 2):
        image = out / f"report_{run}.png"
        image.unlink(missing_ok=True)
        subprocess.run([skelconv, "skeletonize", mesh, "-o", str(out / f"skeleton_{run}.json"), "--quiet",
                        "--report-image", str(image)] + sys.argv[4:], check=True, stdout=subprocess.DEVNULL)
        images.append(image.read_bytes())
    failures = []
    if images[0] != images[1]:
        failures.append("two runs on the same input wrote different pictures")
    width, height, channels, rows = read_png(images[0])
    if (width, height, channels) != (WIDTH, HEIGHT, 3):
        failures.append(f"picture is {width} × {height} × {channels}, expected {WIDTH} × {HEIGHT} RGB")
    else:
        for row in range(2):
            for column in range(3):
                pixels = list(panel_pixels(rows, column, row))
                drawn = [p for p in pixels if p != (255, 255, 255)]
                name = ["input", "skeleton", "result"][column] + ["/front", "/back"][row]
                if len(drawn) < 0.02 * len(pixels):
                    failures.append(f"panel {name}: only {len(drawn)} of {len(pixels)} pixels drawn")
                if column != 1:
                    coloured = [p for p in drawn if max(p) - min(p) > 60]
                    if len(coloured) < 0.01 * len(pixels):
                        failures.append(f"panel {name}: not coloured by distance ({len(coloured)} coloured pixels)")
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
