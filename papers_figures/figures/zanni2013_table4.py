"""Zanni et al. 2013, Table 4: operation counts of the analytic formulas.
Produced by the benchmarks (scripts/bench.sh, docs/bench.md): this entry
includes §6 of bench/results/SUMMARY.md as it was last committed, and checks
that the paper's numbers printed there are the ones in docs/mathematics.md §4."""
import os
import re

from figlib.claims import Claim
from figlib.figure import HERE, Figure

SUMMARY = os.path.join(os.path.dirname(HERE), "bench", "results", "SUMMARY.md")
SECTION = "## 6."
# The paper's Table 4 (docs/mathematics.md §4), f column: +, ×, / (√, atan, ln).
PAPER_F = {"SCALIS Cauchy 4": "29, 38, 4 (1,2,1)", "SCALIS inverse 3": "25, 33, 5 (5,0,1)",
           "SCALIS compact 4": "43, 82, 3 (0,0,1)", "SCALIS compact 6": "71, 144, 3 (0,0,1)",
           "classical inverse 3, linear weight": "18, 20, 4 (2,0,0)",
           "classical Cauchy 4, linear weight": "21, 26, 4 (1,2,0)",
           "classical Cauchy 4, cubic weight": "27, 34, 4 (1,2,1)"}

FIGURE = Figure(
    paper="Zanni et al. 2013", kind="Table", number="4",
    caption="Number of operations needed to evaluate the analytic formulas of each kernel.",
    original_caption="Nombres d'opérations nécessaires pour les évaluations des formules analytiques associées à "
                     "chaque noyau.",
    section="our counts come from the benchmarks (scripts/bench.sh): "
            "[bench/results/SUMMARY.md](../bench/results/SUMMARY.md) §6, included below",
    size=None)


# Ours within 10 % of the paper's +, ×, / total would count as the same cost.
SAME_COST = 1.1


def section_text():
    with open(SUMMARY) as handle:
        text = handle.read()
    start = text.index(SECTION)
    end = text.find("\n## ", start + 1)
    return text[start:end if end > 0 else None]


def gallery_markdown(text):
    """The section without its heading, its relative links pointing into bench/results/ from the gallery."""
    body = text.split("\n", 1)[1].strip()
    return re.sub(r"\]\((?!https?:|\.\./|#)([^)]+)\)", r"](../bench/results/\1)", body)


def draw(ctx):
    text = section_text()
    table = [line for line in text.splitlines() if line.startswith("|")]
    ctx.markdown = "From bench/results/SUMMARY.md §6:\n\n" + gallery_markdown(text)
    found, ratios = {}, {}
    for line in table:
        cells = [c.strip() for c in line.strip("|").split("|")]
        if len(cells) > 5 and cells[1] == "f" and cells[0] in PAPER_F:
            found[cells[0]] = cells[2]
            if cells[5].endswith("×"):
                ratios[cells[0]] = float(cells[5][:-1])
    mismatched = [k for k, v in PAPER_F.items() if found.get(k) != v]
    return [Claim("the paper's operation counts (Table 4, f column) as the bench summary quotes them",
                  f"{len(PAPER_F) - len(mismatched)} of {len(PAPER_F)} rows match docs/mathematics.md §4"
                  + (f"; differing: {', '.join(mismatched)}" if mismatched else ""),
                  not mismatched),
            Claim("the closed forms cost the paper's operation counts (f)",
                  "ours / paper, +, ×, / total of the generic path: " +
                  ("; ".join(f"{k} {v:g}×" for k, v in ratios.items()) if ratios else "no row generated yet"),
                  bool(ratios) and max(ratios.values()) <= SAME_COST, expect_agreement=False,
                  note="our generated functions also evaluate the conditions that pick a numerically stable "
                       "form; SUMMARY.md §6 splits our count by section")]
