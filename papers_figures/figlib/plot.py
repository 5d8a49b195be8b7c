"""Plotting conventions shared by every figure: Agg backend, one font size,
one colour cycle, 100 dpi (so the pixel size is the Figure.size), and PNGs
without timestamps or software tags (same input, same bytes)."""
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

DPI = 100
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


def save(fig, path, size):
    """Writes fig as PNG at exactly size pixels, without metadata."""
    if path is None:
        plt.close(fig)
        return
    fig.set_size_inches(size[0] / DPI, size[1] / DPI)
    fig.savefig(path, dpi=DPI, metadata={"Software": None}, format="png")
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
