"""Plotting conventions shared by every figure: Agg backend, one font size,
one colour cycle, a layout at 100 dpi (Figure.size is the layout in pixels at
that density), saved at least PRINT_WIDTH pixels wide (the layout scaled up:
fonts and lines keep their proportions), and PNGs without timestamps or
software tags (same input, same bytes)."""
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

DPI = 100
# Print size: every gallery image at least this wide, so that a figure shows at
# print resolution what its claim names (a thin primitive, a fold, a corner). A
# layout narrower than this is saved at a proportionally higher dpi. Quick runs
# (ctest's smoke renders) save the layout as it is: the same drawing, cheaper.
PRINT_WIDTH = 1600
_print = {"enabled": True}


def print_size(enabled):
    """Full runs save at print size (the default); run.py --quick turns it off."""
    _print["enabled"] = bool(enabled)
STYLE = {
    "font.size": 9,
    "axes.titlesize": 9,
    "axes.labelsize": 9,
    "legend.fontsize": 8,
    "xtick.labelsize": 8,
    "ytick.labelsize": 8,
    "lines.linewidth": 1.3,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "savefig.dpi": DPI,
    "path.simplify": False,
}
plt.rcParams.update(STYLE)

# Colours of the two formulations compared in Zanni's figures, and the skeleton.
CLASSICAL = "tab:blue"
SCALIS = "tab:red"
SKELETON = "black"


def new_figure(size, rows=1, cols=1, **kwargs):
    """A figure of size=(width_px, height_px) with rows × cols axes."""
    fig, axes = plt.subplots(rows, cols, figsize=(size[0] / DPI, size[1] / DPI), dpi=DPI, **kwargs)
    return fig, axes


def print_scale(size):
    """How much a layout of size=(width_px, height_px) is enlarged when saved (≥ 1)."""
    return max(1.0, PRINT_WIDTH / size[0]) if _print["enabled"] else 1.0


def save(fig, path, size):
    """Writes fig as PNG, the layout of size pixels enlarged by print_scale(size), without metadata."""
    if path is None:
        plt.close(fig)
        return
    fig.set_size_inches(size[0] / DPI, size[1] / DPI)
    fig.savefig(path, dpi=DPI * print_scale(size), metadata={"Software": None}, format="png")
    plt.close(fig)


def draw_segment(ax, a, b, **kwargs):
    style = {"color": SKELETON, "lw": 2.0, "solid_capstyle": "butt"}
    style.update(kwargs)
    ax.plot([a[0], b[0]], [a[1], b[1]], **style)


def contour_segments(ax, xs, ys, values, level, **kwargs):
    """Draws the level set {values = level} and returns its polylines (list of N×2 arrays)."""
    finite = values[np.isfinite(values)]
    if finite.size == 0 or not finite.min() < level < finite.max():
        return []                       # the level set is empty in this window
    cs = ax.contour(xs, ys, values, levels=[level], **kwargs)
    return [seg for seg in cs.allsegs[0] if len(seg) > 1]
