#!/usr/bin/python3
"""The main job's summary page (scripts/main_job.sh): one HTML page and its
Markdown twin saying, for each result of the run, what was checked and
whether it holds.

  summary_page.py --out DIR --stages STAGES.tsv --sweep SWEEP.json
                  --polygon-sweep POLYGON.json --scalis-report GTEST.json
                  --opcounts generated/opcounts.csv --figures FIGURES_DIR

STAGES.tsv: one line per stage, "name<TAB>seconds<TAB>status" (status 0 is
passed). The figures folder is `papers_figures/run.py --out`'s: claims.json
and one PNG per figure, copied next to the page. An input that is missing is
reported as missing on the page (and makes the verdict "incomplete"), never
skipped in silence.
"""
import argparse
import csv
import html
import json
import os
import shutil
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "bench"))
sys.path.insert(0, os.path.join(ROOT, "papers_figures"))
from summarize import OUTPUTS, PAPER_TABLE4, fmt_ops  # noqa: E402  (the paper's Table 4: one copy)
from figures.zanni2013_table4 import FUNCTIONS  # noqa: E402  (each row's generated function)

OUTPUT_LABELS = {"f": "f", "grad": "∇f", "f_and_grad": "f and ∇f"}
# A goal the code does not meet yet: reported as measured, not a failure.
SHORTFALL = "shortfall"
OUTPUT_LABELS = {"f": "f", "grad": "∇f", "f_and_grad": "f and ∇f"}


def read_stages(path):
    stages = []
    if path and os.path.exists(path):
        with open(path) as handle:
            for line in handle:
                parts = line.rstrip("\n").split("\t")
                if len(parts) == 3:
                    stages.append((parts[0], int(parts[1]), int(parts[2])))
    return stages


def load_json(path):
    if not path or not os.path.exists(path):
        return None
    with open(path) as handle:
        return json.load(handle)


def segment_accuracy(sweep):
    """{(family, region): (cells, points, max rel f, max rel ∇f, cells above target)} over double results."""
    table = {}
    for cell in sweep["cells"]:
        key = (cell["family"], cell["region"])
        cells, points, worst_f, worst_g, above = table.get(key, (0, 0, 0.0, 0.0, 0))
        d = cell["double"]
        table[key] = (cells + 1, points + cell["points"], max(worst_f, d["max_rel_f"]),
                      max(worst_g, d["max_rel_grad"]),
                      above + (1 if d["f_above_generic_target"] or d["grad_above_generic_target"] else 0))
    return table


def polygon_accuracy(sweep):
    table = {}
    for cell in sweep["cells"]:
        key = (cell["family"], cell["region"])
        cells, points, worst_f, worst_g = table.get(key, (0, 0, 0.0, 0.0))
        table[key] = (cells + 1, points + cell["points"], max(worst_f, cell["max_f"]), max(worst_g, cell["max_grad"]))
    return table


def opcount_rows(path):
    counts = {}
    with open(path) as handle:
        for row in csv.DictReader(handle):
            counts[row["function"]] = tuple(int(row[k]) for k in ("add", "mul", "div", "sqrt", "atan", "log"))
    return counts


class Page:
    """Markdown and HTML written side by side."""

    def __init__(self):
        self.md, self.html = [], []

    def heading(self, text, level=2):
        self.md.append("#" * level + " " + text + "\n")
        self.html.append(f"<h{level}>{html.escape(text)}</h{level}>")

    def para(self, text):
        self.md.append(text + "\n")
        self.html.append(f"<p>{html.escape(text)}</p>")

    def table(self, header, rows):
        self.md.append("| " + " | ".join(header) + " |")
        self.md.append("|" + "---|" * len(header))
        for row in rows:
            self.md.append("| " + " | ".join(str(c) for c in row) + " |")
        self.md.append("")
        cells = "".join(f"<th>{html.escape(h)}</th>" for h in header)
        body = "".join("<tr>" + "".join(f"<td>{html.escape(str(c))}</td>" for c in row) + "</tr>" for row in rows)
        self.html.append(f"<table><thead><tr>{cells}</tr></thead><tbody>{body}</tbody></table>")

    def image(self, src, alt):
        self.md.append(f"![{alt}]({src})\n")
        self.html.append(f'<p><a href="{html.escape(src)}"><img src="{html.escape(src)}" alt="{html.escape(alt)}" '
                         f'style="max-width:100%"></a></p>')


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True)
    parser.add_argument("--stages")
    parser.add_argument("--sweep")
    parser.add_argument("--polygon-sweep")
    parser.add_argument("--scalis-report")
    parser.add_argument("--opcounts", required=True)
    parser.add_argument("--figures")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)

    page = Page()
    verdicts = []   # (result, what was checked, holds: True / False / None for missing)

    stages = read_stages(args.stages)
    for name, _, status in stages:
        if name.startswith("regenerat"):
            verdicts.append(("the generated kernels", "regenerated and diffed byte for byte against generated/",
                             status == 0))

    sweep = load_json(args.sweep)
    if sweep:
        s = sweep["summary"]
        verdicts.append(("segment kernels (f, ∇f)",
                         f"{s['samples']:,} samples in {s['items_run']} work items against float128 quadrature "
                         "of the definition; the generic-region targets in every cell",
                         bool(s["generic_passed"]) and s["exclusion_cells_failing"] == 0))
    else:
        verdicts.append(("segment kernels (f, ∇f)", "sweep report missing", None))
    polygon = load_json(args.polygon_sweep)
    if polygon:
        verdicts.append(("polygon kernels (f, ∇f)",
                         f"{sum(c['points'] for c in polygon['cells']):,} samples against float128 quadrature",
                         polygon["exclusion_cells_failing"] == 0
                         and all(c["max_f"] <= polygon["generic_target"] for c in polygon["cells"]
                                 if c["region"] == "generic")))
    else:
        verdicts.append(("polygon kernels (f, ∇f)", "sweep report missing", None))
    scalis = load_json(args.scalis_report)
    if scalis:
        verdicts.append(("SCALIS segments (f, ∇f)",
                         f"{scalis['tests']} tests (generic samples of every family and degree against quadrature "
                         "of the definition)", scalis["tests"] > 0 and scalis["failures"] == 0 and scalis["errors"] == 0))
    else:
        verdicts.append(("SCALIS segments (f, ∇f)", "test report missing", None))

    counts = opcount_rows(args.opcounts)
    op_rows, below, compared, generated = [], 0, 0, 0
    for label, _, paper in PAPER_TABLE4:
        for output, theirs in zip(OUTPUTS, paper):
            ours = counts.get(f"{FUNCTIONS[label]}_{output}")
            if ours is None:
                op_rows.append((label, OUTPUT_LABELS[output], fmt_ops(theirs), "not generated", ""))
                continue
            generated += 1
            compared += 1
            ratio = sum(ours[:3]) / sum(theirs[:3])
            below += ratio <= 1
            op_rows.append((label, OUTPUT_LABELS[output], fmt_ops(theirs), fmt_ops(ours), f"{ratio:.2f}×"))
    # Every cell generated is a check; at or below the paper's count is a goal
    # not met yet (reported as a shortfall, which does not fail the job).
    verdicts.append(("operation counts (Zanni et al. 2013, Table 4): every cell generated",
                     f"{generated} of {3 * len(PAPER_TABLE4)} (row, output) cells have a generated function",
                     generated == 3 * len(PAPER_TABLE4)))
    verdicts.append(("operation counts (Zanni et al. 2013, Table 4): at or below the paper's",
                     f"+, ×, / at or below the paper's in {below} of {compared} cells (a goal)",
                     True if below == compared else SHORTFALL))

    figures = load_json(os.path.join(args.figures, "claims.json")) if args.figures else None
    if figures:
        for fig in figures:
            claims = fig["claims"]
            good = sum(1 for c in claims if c["agrees"] == c["expected"])
            verdicts.append((fig["heading"], f"{len(claims)} claims checked, {good} as expected",
                             good == len(claims)))
    else:
        verdicts.append(("the papers' figures", "claims.json missing", None))

    failed = [v for v in verdicts if v[2] is False]
    missing = [v for v in verdicts if v[2] is None]
    shortfalls = [v for v in verdicts if v[2] == SHORTFALL]
    overall = "FAILED" if failed else ("INCOMPLETE" if missing else "all checks hold")

    page.heading("skelconv main job: summary", 1)
    holding = len(verdicts) - len(failed) - len(missing) - len(shortfalls)
    page.para(f"Verdict: {overall} ({holding} of {len(verdicts)} results hold"
              + (f", {len(failed)} fail" if failed else "") + (f", {len(missing)} missing" if missing else "")
              + (f", {len(shortfalls)} goals not met yet" if shortfalls else "") + ").")
    if stages:
        page.heading("Stages")
        page.table(["stage", "seconds", "status"],
                   [(n, s, "passed" if st == 0 else f"FAILED ({st})") for n, s, st in stages]
                   + [("total", sum(s for _, s, _ in stages), "")])
    page.heading("Results")
    page.table(["result", "what was checked", "holds"],
               [(r, what, {True: "yes", False: "NO", None: "missing", SHORTFALL: "not yet (a goal)"}[ok])
                for r, what, ok in verdicts])

    if sweep:
        page.heading("Accuracy of the segment kernels, per family and region")
        page.para("Max relative error of f and of ∇f (Euclidean norm) in double against float128 quadrature of the "
                  "definition integral, over every kernel degree and weight degree of the family.")
        acc = segment_accuracy(sweep)
        page.table(["family", "region", "cells", "samples", "max rel. error f", "max rel. error ∇f", "cells above target"],
                   [(f, r, c, f"{p:,}", f"{wf:.2e}", f"{wg:.2e}", above)
                    for (f, r), (c, p, wf, wg, above) in sorted(acc.items())])
    if polygon:
        page.heading("Accuracy of the polygon kernels, per family and region")
        acc = polygon_accuracy(polygon)
        page.table(["family", "region", "cells", "samples", "max rel. error f", "max rel. error ∇f"],
                   [(f, r, c, f"{p:,}", f"{wf:.2e}", f"{wg:.2e}") for (f, r), (c, p, wf, wg) in sorted(acc.items())])

    page.heading("Operation counts beside Zanni et al. 2013, Table 4")
    page.para("Per evaluation: +, ×, / then (√, atan, ln). Ours: the generic path of the generated function "
              "(generated/opcounts.csv), counted on the straight-line program after common subexpressions are "
              "removed; the ratio compares the +, ×, / totals.")
    page.table(["row", "output", "paper", "ours", "ours / paper"], op_rows)

    if figures:
        page.heading("The papers' figures and tables")
        images = os.path.join(args.out, "figures")
        os.makedirs(images, exist_ok=True)
        for fig in figures:
            page.heading(fig["heading"], 3)
            png = os.path.join(args.figures, fig["name"] + ".png")
            if os.path.exists(png):
                shutil.copyfile(png, os.path.join(images, fig["name"] + ".png"))
                page.image(f"figures/{fig['name']}.png", fig["heading"])
            page.table(["claim", "measured", "agrees", "as expected"],
                       [(c["statement"], c["measured"], "yes" if c["agrees"] else "no",
                         "yes" if c["agrees"] == c["expected"] else "NO") for c in fig["claims"]])

    with open(os.path.join(args.out, "index.md"), "w") as handle:
        handle.write("\n".join(page.md) + "\n")
    style = ("body{font-family:sans-serif;max-width:1200px;margin:2em auto;padding:0 1em}"
             "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #bbb;padding:3px 8px;"
             "text-align:left;vertical-align:top}th{background:#eee}")
    with open(os.path.join(args.out, "index.html"), "w") as handle:
        handle.write("<!DOCTYPE html><html><head><meta charset='utf-8'><title>skelconv main job</title>"
                     f"<style>{style}</style></head><body>" + "\n".join(page.html) + "</body></html>\n")
    print(f"summary: {overall}; {os.path.join(args.out, 'index.html')}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
