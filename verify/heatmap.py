#!/usr/bin/python3
"""Heat map of a skelconv-verify JSON report (a sweep or a merged one).

    /usr/bin/python3 verify/heatmap.py REPORT.json OUT.png [--precision double|extended]

One row of panels per kernel family, one panel for f and one for |grad f|:
regions (rows) against kernel degrees (columns), colour = log10 of the worst
relative error over the weight degrees. The colour scale is fixed (1e-17 to
1e-6 in double, 1e-34 to 1e-18 in binary128) so that two reports' maps can be
compared by eye; each cell also prints its value. A generic cell above its
asserted target is outlined in red. Matplotlib's Agg backend, no metadata in
the PNG: the same report gives the same bytes. See docs/verify.md.
"""
import argparse
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend choice)
from matplotlib.patches import Rectangle  # noqa: E402

# The order of verify/regions.hpp (all_regions); regions a newer verifier adds
# are appended in name order.
REGION_ORDER = ["generic", "near_line_beside", "near_line_beyond", "near_ends", "far", "support_boundary",
                "support_grazing"]
# Fixed colour ranges (log10): double from below its rounding (2^-52 = 2.2e-16)
# to the worst regions of the default sweep (1.4e-8) with room; binary128 from
# its rounding (2^-112 = 1.9e-34) to above the reference's flag threshold (1e-20).
COLOUR_RANGE = {"double": (-17.0, -6.0), "extended": (-34.0, -18.0)}
# An error of exactly 0 is drawn at the bottom of the scale.
ZERO_EXPONENT = -40.0


def fail(message):
    print(f"heatmap.py: {message}", file=sys.stderr)
    sys.exit(2)


def worst_errors(report, precision):
    """{family: {(region, degree): (f, grad)}}, max over weight degrees."""
    table = {}
    for index, cell in enumerate(report.get("cells", [])):
        try:
            stats = cell[precision]
            key = (cell["region"], int(cell["degree"]))
            values = [stats["max_rel_f"], stats["max_rel_grad"]]
            family = cell["family"]
        except (KeyError, TypeError, ValueError) as error:
            fail(f"cells[{index}]: missing or invalid {error}")
        # null = an infinite (non-finite) error in the report
        values = [math.inf if v is None else float(v) for v in values]
        old = table.setdefault(family, {}).get(key, (0.0, 0.0))
        table[family][key] = (max(old[0], values[0]), max(old[1], values[1]))
    if not table:
        fail("the report has no cells")
    return table


def exponent(value):
    if value == 0:
        return ZERO_EXPONENT
    return 0.0 if math.isinf(value) else math.log10(value)


def draw_panel(axes, cells, regions, degrees, which, limits, target):
    grid = [[math.nan] * len(degrees) for _ in regions]
    for (region, degree), values in cells.items():
        grid[regions.index(region)][degrees.index(degree)] = exponent(values[which])
    image = axes.imshow(grid, cmap="viridis", vmin=limits[0], vmax=limits[1], aspect="auto")
    for r, region in enumerate(regions):
        for d, degree in enumerate(degrees):
            value = cells.get((region, degree))
            if value is None:
                continue
            e = grid[r][d]
            label = "0" if e == ZERO_EXPONENT else ("inf" if math.isinf(value[which]) else f"{value[which]:.0e}")
            label = label.replace("e-0", "e-").replace("e-", "e−")
            shade = "white" if e < (limits[0] + limits[1]) / 2 else "black"
            axes.text(d, r, label, ha="center", va="center", fontsize=5.5, color=shade)
            if target is not None and region == "generic" and not value[which] <= target:
                axes.add_patch(Rectangle((d - 0.5, r - 0.5), 1, 1, fill=False, edgecolor="red", linewidth=2))
    axes.set_xticks(range(len(degrees)), [str(d) for d in degrees], fontsize=7)
    axes.set_yticks(range(len(regions)), regions, fontsize=7)
    axes.set_xlabel("kernel degree i", fontsize=8)
    return image


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("report")
    parser.add_argument("png")
    parser.add_argument("--precision", choices=["double", "extended"], default="double")
    args = parser.parse_args()
    try:
        with open(args.report, encoding="utf-8") as file:
            report = json.load(file)
    except (OSError, json.JSONDecodeError) as error:
        fail(f"{args.report}: {error}")
    if report.get("tool") != "skelconv-verify":
        fail(f"{args.report}: not a skelconv-verify report")
    settings = report.get("settings", {})
    targets = (settings.get("target_generic_f"), settings.get("target_generic_grad"))
    if args.precision == "extended":
        targets = (None, None)  # the targets are for double
    table = worst_errors(report, args.precision)
    limits = COLOUR_RANGE[args.precision]

    families = sorted(table)
    figure, axes = plt.subplots(len(families), 2, figsize=(16, 1.2 + 2.4 * len(families)),
                               squeeze=False, layout="constrained")
    for row, family in enumerate(families):
        cells = table[family]
        present = {region for region, _ in cells}
        regions = [r for r in REGION_ORDER if r in present] + sorted(present - set(REGION_ORDER))
        degrees = sorted({degree for _, degree in cells})
        for which, name in enumerate(["f", "|∇f|"]):
            image = draw_panel(axes[row][which], cells, regions, degrees, which, limits, targets[which])
            axes[row][which].set_title(f"{family}: log10 worst relative error of {name}", fontsize=9)
    precision = "double" if args.precision == "double" else "binary128"
    figure.suptitle(f"skelconv-verify, generated code in {precision}: seed {settings.get('seed')}, "
                    f"commit {str(settings.get('commit', '?'))[:12]}, "
                    f"{report.get('summary', {}).get('samples')} samples "
                    "(red outline: generic cell above its target)", fontsize=10)
    figure.colorbar(image, ax=axes, shrink=0.6, label="log10 relative error")
    figure.savefig(args.png, dpi=110, metadata={"Software": None})


if __name__ == "__main__":
    main()
