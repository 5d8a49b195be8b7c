#!/usr/bin/python3
"""Draws the registered figures and tables, checks their claims, and writes
the gallery. Used by scripts/figures.sh (everything, full resolution) and by
ctest (one figure, --quick --check). docs/figures.md explains the layout."""
import argparse
import importlib
import json
import os
import shutil
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from figlib import gallery  # noqa: E402
from figlib.field import Field  # noqa: E402
from figlib.figure import Context  # noqa: E402


def registered():
    """Module names listed in figures.txt, in order (# starts a comment)."""
    names = []
    with open(os.path.join(HERE, "figures.txt")) as handle:
        for line in handle:
            name = line.split("#", 1)[0].strip()
            if name:
                names.append(name)
    return names


def pending():
    """(heading, what it waits for) from pending.txt: 'HEADING | REASON' lines."""
    rows = []
    with open(os.path.join(HERE, "pending.txt")) as handle:
        for line in handle:
            line = line.strip()
            if line and not line.startswith("#"):
                heading, _, reason = line.partition("|")
                rows.append((heading.strip(), reason.strip()))
    return rows


def run_one(name, args):
    module = importlib.import_module(f"figures.{name}")
    fig = module.FIGURE
    image = None
    if fig.size is not None and not args.no_images:
        image = os.path.join(args.out, f"{name}.png")
    ctx = Context(skelconv=args.skelconv, quick=args.quick, image_path=image,
                  log=lambda msg: print(f"  [{name}] {msg}", flush=True))
    start = time.monotonic()
    calls, points = Field.calls, Field.points
    claims = module.draw(ctx)
    elapsed = time.monotonic() - start
    print(f"  [{name}] {Field.calls - calls} skelconv eval runs, {Field.points - points} points", flush=True)
    for c in claims:
        mark = "ok " if c.as_expected else "FAIL"
        print(f"  [{name}] {mark} {'agrees' if c.agrees else 'disagrees'}: {c.statement} -- {c.measured}",
              flush=True)
    return {"name": name, "figure": fig, "image": image, "claims": claims,
            "markdown": ctx.markdown, "seconds": elapsed}


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--skelconv", required=True, help="the skelconv binary")
    parser.add_argument("--out", required=True, help="results folder (PNGs, claims.json)")
    parser.add_argument("--only", nargs="*", help="module names (default: every registered one)")
    parser.add_argument("--quick", action="store_true", help="reduced resolution (ctest)")
    parser.add_argument("--no-images", action="store_true", help="check claims only")
    parser.add_argument("--check", action="store_true", help="exit 1 unless every claim is as expected")
    parser.add_argument("--gallery", help="write GALLERY.md here and copy the PNGs beside it in images/")
    args = parser.parse_args()
    if args.gallery and args.only:
        print("run.py: --gallery needs a full run (no --only): the gallery lists every figure", file=sys.stderr)
        return 2
    os.makedirs(args.out, exist_ok=True)
    names = args.only or registered()
    unknown = [n for n in names if n not in registered()]
    if unknown:
        print(f"run.py: not registered in figures.txt: {', '.join(unknown)}", file=sys.stderr)
        return 2
    start = time.monotonic()
    results = []
    for k, name in enumerate(names, 1):
        print(f"[{k}/{len(names)}] {name}", flush=True)
        results.append(run_one(name, args))
        print(f"[{k}/{len(names)}] {name} done in {results[-1]['seconds']:.1f} s", flush=True)
    elapsed = time.monotonic() - start
    summary = [{"name": r["name"], "heading": r["figure"].heading, "seconds": round(r["seconds"], 1),
                "claims": [{"statement": c.statement, "measured": c.measured, "agrees": c.agrees,
                            "expected": c.expect_agreement} for c in r["claims"]]} for r in results]
    with open(os.path.join(args.out, "claims.json"), "w") as handle:
        json.dump(summary, handle, indent=1)
    if args.gallery:
        image_dir = os.path.join(os.path.dirname(os.path.abspath(args.gallery)), "images")
        os.makedirs(image_dir, exist_ok=True)
        for r in results:
            if r["image"]:
                shutil.copyfile(r["image"], os.path.join(image_dir, os.path.basename(r["image"])))
        gallery.write(args.gallery, results, pending())
        print(f"wrote {args.gallery}")
    bad = [(r["name"], c.statement) for r in results for c in r["claims"] if not c.as_expected]
    print(f"{len(results)} figures/tables, {sum(len(r['claims']) for r in results)} claims, "
          f"{len(bad)} not as expected, {elapsed:.1f} s")
    if args.check and bad:
        for name, statement in bad:
            print(f"claim not as expected: {name}: {statement}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
