#!/usr/bin/python3
"""The float error of one generated GLSL kernel beyond an end of its segment,
near the segment's line: where the surface of a ray-marched skeleton has its
caps (docs/view.md, "Float").

    probe_beyond_end.py KERNEL [--w 1,0,0,0] [--s 1] [--R 1.5]

KERNEL is a function of generated/glsl/ without its suffix, e.g.
segment_inverse_i3_w0. The segment runs from (-1,0,0) to (1,0,0); P = (x, y, 0)
for x beyond the end B = (1,0,0) and lateral offsets y from 0 (on the line)
to 0.6. Prints f of the shader (headless Chromium, as check_glsl_numeric.py,
whose page and reference quadrature it uses) against the reference, and the
relative error. A measurement, not a test.
"""
import argparse
import html
import json
import math
import pathlib
import re
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import check_glsl_numeric as numeric  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("kernel")
    ap.add_argument("--w", default="1,0,0,0")
    ap.add_argument("--s", type=float, default=1.0)
    ap.add_argument("--R", type=float, default=1.5)
    ap.add_argument("--chromium", default="/usr/bin/chromium")
    args = ap.parse_args()
    family, degree, wdeg = re.match(r"segment_(\w+?)_i(\d+)_w(\d+)$", args.kernel).groups()
    folder = pathlib.Path(__file__).resolve().parents[2] / "generated" / "glsl"
    source = next((src for _, _, _, name, src in numeric.kernels(folder) if name == args.kernel), None)
    if source is None:
        sys.exit(f"probe_beyond_end: no {args.kernel} in {folder}")
    w = [float(v) for v in args.w.split(",")] + [0.0] * 4
    points = [(x, y, 0.0) for x in (1.1, 1.3, 1.6, 2.0) for y in (0.0, 1e-4, 1e-2, 0.1, 0.3, 0.6)]
    rows, flat = [], []
    for p in points:
        row = np.array([-1, 0, 0, 1, 0, 0, *p, *w[:4], args.s, args.R], dtype=np.float64)
        clip = numeric.clip(row[0:3], row[3:6], row[6:9], row[14]) or (0.0, 0.0)
        rows.append(row)
        flat += [*row[:15], clip[0], clip[1], 0, 0, 0]
    with tempfile.TemporaryDirectory() as scratch:
        page = pathlib.Path(scratch) / "page.html"
        page.write_text(numeric.PAGE % json.dumps([{"name": args.kernel, "source": source, "inputs": flat}]))
        run = subprocess.run([args.chromium, *numeric.CHROMIUM_FLAGS, f"--user-data-dir={scratch}/profile",
                              "--dump-dom", page.as_uri()], capture_output=True, text=True)
    found = re.search(r"RESULTS (.*) END", html.unescape(run.stdout))
    if not found:
        sys.exit("probe_beyond_end: no result (chromium stderr tail):\n" + run.stderr[-2000:])
    values = json.loads(found.group(1))[args.kernel]
    print(f"{args.kernel}: P = (x, y, 0) beyond B = (1, 0, 0)")
    for k, (p, row) in enumerate(zip(points, rows)):
        f_ref = numeric.reference(family, int(degree), int(wdeg), row)[0]
        f = values[4 * k] if values[4 * k] is not None else math.nan  # JSON null: NaN
        print(f"x {p[0]:.1f} y {p[1]:<7g} f {f:<13.6g} reference {f_ref:<13.6g} relative error {abs(f - f_ref) / abs(f_ref):.2e}")


if __name__ == "__main__":
    main()
