"""Zanni et al. 2013, Table 1: mesher times. Ours: `skelconv mesh` (CGAL
Mesh_3 + Newton projection, exact normals) on the skeletons of our figs 19b
and 20c, on fig 20c at a finer facet size (~100k triangles), on an ant
of our own (24 SCALIS segments, Cauchy kernel; drawn as the table's image),
and on the ant of Figure 1 (the paper's class: SCALIS segments and triangles,
compact kernel of degree 6; the paper's own ant is not given), beside the paper's (a non-adaptive marching-triangles mesher). Times depend on the
machine and its load: the gallery prints them; the checks are on the meshes
(closed manifolds, triangle counts) and, in full runs only (run.py --check
without --quick: scripts/figures.sh, the main job's figures stage), on the
speed goals."""
import os
import platform
import re
import subprocess

from figlib import ant as fig1_ant, surface3d
from figlib.claims import Claim
from figlib.figure import Figure, load_skeleton
from figures import zanni2013_fig19, zanni2013_fig20

PAPER_MACHINE = "Intel Core 2 Duo, 2.4 GHz, 1 core used, 2 GB RAM"
PAPER_ROWS = {"Fig. 19(b)": ("4 545", "0.03 s"), "Fig. 20(c)": ("3 912", "0.03 s"),
              "Ant (medium resolution)": ("94 953", "3.58 s"), "Ant head (high resolution)": ("64 756", "1.71 s")}
# The paper's ant at medium resolution: 94 953 triangles in 3.58 s on its machine.
PAPER_ANT_RATE = 94_953 / 3.58          # triangles per second
# Goal: our ant (same class: a few dozen segments, compact-free Cauchy SCALIS) meshed at least as
# fast per triangle as the paper's 2008 single core. Checked only in full runs (not --quick: a
# coarse mesh's rate says little; the main job's figures stage runs run.py --check in full) and
# expected to fall short today: the check asserts the shortfall, so a mesher that reaches the goal
# is noticed.
RATE_GOAL = 1.0
# The ant of Figure 1, meshed as that figure meshes it (one CGAL thread, like the paper's one core).
COMPACT_ANT_SIZE, COMPACT_ANT_DISTANCE = 0.25, 0.004
LARGE_TRIANGLES = 50_000      # the fine mesh must be of the ~100k-triangle class
ANT = "zanni_table1_ant.json"  # our ant: gaster, petiole, thorax, head, 6 two-segment legs, antennae, mandibles

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Table", number="1",
    caption="Running times of a non-adaptive \"Marching Triangles\" on an Intel Core 2 Duo (2.4 GHz, 1 core used) "
            "with 2 GB of RAM.",
    original_caption="Temps d'exécution d'un \"Marching Triangle\" non-adaptatif sur un Intel Core 2 Duo (2.4 GHz, "
                     "1 coeur utilisé) équipé de 2 Go de mémoire vive.",
    section="our meshes of our skeletons of figs 19b and 20c and of two ants of our own, a Cauchy 4 one and the "
            "compact-6 ant of Figure 1 (segments and triangles, the paper's class; the paper's skeletons are not given, "
            "nor its ant); the image is the Cauchy ant's mesh",
    skeletons=[ANT], kernel="SCALIS Cauchy 4, σ = 1", iso="1", view="the fixed camera of render3d",
    size=(640, 300))


def machine():
    """The CPU model from lscpu, and the core count."""
    try:
        out = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
        model = next(line.split(":", 1)[1].strip() for line in out.splitlines() if line.startswith("Model name"))
    except (OSError, StopIteration):
        model = platform.processor() or "unknown CPU"
    return model


def field_time(m):
    """(seconds, evaluations) of the field from `skelconv mesh`'s line
    `time: T s (field F s in N evaluations, summed over the threads)`."""
    match = re.search(r"field ([0-9.]+) s in ([0-9]+) evaluations", m.stats.get("time", ""))
    if not match:
        raise surface3d.MeshError(f"{m.command}: no field time in its output: {m.stats.get('time')!r}")
    return float(match.group(1)), int(match.group(2))


def draw(ctx):
    coarse, fine = ctx.res(0.05, 0.2), ctx.res(0.03, 0.1)
    fig20c = zanni2013_fig20.branching("(c)", zanni2013_fig20.TAU / 2 ** 0.5)[0]
    # the large row with the grid method: CGAL took over 90 s for it at size 0.02 on our machine
    rows = [("Fig. 19(b)", "fig19b", zanni2013_fig19.v_skeleton("sum"), coarse, "cgal"),
            ("Fig. 20(c)", "fig20c", fig20c, coarse, "cgal"),
            ("Fig. 20(c), grid", "fig20c", fig20c, coarse, "grid"),
            ("Fig. 20(c), finer, grid", "fig20c", fig20c, fine, "grid"),
            ("Ant (ours, 24 segments), grid", "ant", load_skeleton(ANT), ctx.res(0.05, 0.2), "grid"),
            ("Ant of Fig. 1 (ours, compact 6: 34 segments, 4 triangles)", "ant_fig1",
             {"primitives": fig1_ant.primitives()}, ctx.res(COMPACT_ANT_SIZE, 0.5), "cgal")]
    lines = [f"Our machine: {machine()}, {os.cpu_count()} cores (`lscpu`; the build machine, shared with other "
             f"jobs while these times were taken: load average {os.getloadavg()[0]:.1f} when the table started). "
             "`--method cgal` runs on 1 thread, `--method grid` (OpenVDB) on "
             f"every core. The paper's: {PAPER_MACHINE}. **Times are machine- and load-dependent**; the "
             "meshers differ too (the paper's marching triangles is non-adaptive; ours refines Delaunay "
             "triangulations and projects every vertex with the exact gradient).", "",
             "| skeleton | paper: triangles | paper: time | ours: command | ours: triangles | ours: time (s) "
             "| field evaluations |", "|---|---|---|---|---|---|---|"]
    meshes = []
    for name, stem, skeleton, size, method in rows:
        distance = ctx.res(COMPACT_ANT_DISTANCE, 0.02) if stem == "ant_fig1" else None
        m = surface3d.mesh(ctx, skeleton, 1.0, size, stem, method=method, distance=distance)
        meshes.append(m)
        paper = PAPER_ROWS.get(name, ("—", "—"))
        evaluations = field_time(m)[1]
        lines.append(f"| {name} | {paper[0]} | {paper[1]} | `{m.command}` | {m.stats['triangles']} | "
                     f"{m.seconds:.2f} | {evaluations} |")
    for name in ("Ant (medium resolution)", "Ant head (high resolution)"):
        lines.append(f"| {name} | {PAPER_ROWS[name][0]} | {PAPER_ROWS[name][1]} | — (the paper's ant is not "
                     "given; ours are the rows above) | | | |")
    ant, compact = meshes[-2], meshes[-1]
    seconds, evaluations = field_time(ant)
    per_evaluation = seconds / evaluations
    lines += ["", f"Our cost grows with the number of primitives: every one is evaluated at every point (no "
                  f"spatial culling; the Cauchy kernel has no compact support). The ant's field costs "
                  f"{per_evaluation * 1e6:.1f} µs per evaluation of its 24 segments (field time ÷ evaluations)."]
    ctx.markdown = "\n".join(lines)
    surface3d.panels(ctx, [(ant, f"our ant, 24 SCALIS segments: {ant.stats['triangles']} triangles "
                                 f"(--method grid --size {rows[-2][3]:g})")], FIGURE.size)
    ctx.log("\n" + ctx.markdown)
    large = int(meshes[-3].stats["triangles"])
    rate = int(ant.stats["triangles"]) / ant.seconds
    compact_rate = int(compact.stats["triangles"]) / compact.seconds
    timing = [] if ctx.quick else [Claim(
        f"(goal) our ant meshes at ≥ {RATE_GOAL:g} × the paper's rate ({PAPER_ANT_RATE:,.0f} triangles/s on "
        f"{PAPER_MACHINE})",
        f"{rate:,.0f} triangles/s ({ant.stats['triangles']} in {ant.seconds:.2f} s, --method grid on "
        f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}): {rate / PAPER_ANT_RATE:.3f} × the paper's",
        rate >= RATE_GOAL * PAPER_ANT_RATE,
        note="a wall-clock rate: measured under the load shown (full runs only; ctest does not time)"),
        Claim(f"(goal) the ant of Fig. 1, the paper's skeleton class, meshes at ≥ {RATE_GOAL:g} × the paper's rate "
              f"on one thread as the paper used one core",
              f"{compact_rate:,.0f} triangles/s ({compact.stats['triangles']} in {compact.seconds:.2f} s, --method cgal, "
              f"1 thread, load average {os.getloadavg()[0]:.1f}): {compact_rate / PAPER_ANT_RATE:.3f} × the paper's",
              compact_rate >= RATE_GOAL * PAPER_ANT_RATE, expect_agreement=False,
              note="a known shortfall: CGAL's Delaunay refinement with exact projection is slower per triangle than "
                   "a non-adaptive marching triangles; the compact supports keep the field's share small "
                   "(the field time is in the table)")]
    return timing + [Claim("(ours) every mesh of the table is a closed manifold",
                  ", ".join(f"{m.stats['triangles']} triangles closed {m.stats['closed']}" for m in meshes),
                  all(m.closed for m in meshes)),
            Claim("(ours) the finer mesh is of the paper's large class (~100k triangles)",
                  f"{large} triangles (at least {LARGE_TRIANGLES} asked; quick runs use a coarser size)",
                  large >= (LARGE_TRIANGLES if not ctx.quick else 1000))]
