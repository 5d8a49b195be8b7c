#!/usr/bin/python3
"""Draws the registered figures and tables, checks their claims, and writes
the gallery. Used by scripts/figures.sh (everything, full resolution) and by
ctest (one figure, --quick --check). docs/figures.md explains the layout.

The gallery is written from one record per figure, papers_figures/results/NAME.json
(its claims and extra markdown; committed with the image, no times in it):
  --gallery PATH            draws the figures (all, or --only some), refreshes
                            their records and images, then rewrites the gallery
                            from every registered figure's record;
  --gallery-only PATH       rewrites the gallery from the records alone (seconds,
                            nothing drawn; a figure without a record is an error
                            naming the command that makes it).
The gallery links an interactive page (`skelconv view`, docs/view.md) per
skeleton file a figure lists, papers_figures/views/NAME.html: --gallery
writes them, and so does --views alone (with --skelconv; seconds)."""
import argparse
import concurrent.futures
import importlib
import json
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from figlib import gallery, plot  # noqa: E402
from figlib.claims import Claim  # noqa: E402
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


def record_paths(gallery_path, name):
    """(record JSON, committed image) of a figure, beside the gallery."""
    root = os.path.dirname(os.path.abspath(gallery_path))
    return os.path.join(root, "results", f"{name}.json"), os.path.join(root, "images", f"{name}.png")


def save_record(gallery_path, result):
    """Writes the figure's record and copies its image beside the gallery (same results, same bytes)."""
    record_path, image_path = record_paths(gallery_path, result["name"])
    os.makedirs(os.path.dirname(record_path), exist_ok=True)
    os.makedirs(os.path.dirname(image_path), exist_ok=True)
    if result["image"]:
        shutil.copyfile(result["image"], image_path)
    record = {"name": result["name"], "image": os.path.basename(image_path) if result["image"] else None,
              "markdown": result["markdown"],
              "claims": [{"statement": c.statement, "measured": c.measured, "agrees": c.agrees,
                          "expect_agreement": c.expect_agreement, "note": c.note} for c in result["claims"]]}
    with open(record_path + ".tmp", "w") as handle:
        json.dump(record, handle, indent=1, ensure_ascii=False)
        handle.write("\n")
    os.replace(record_path + ".tmp", record_path)


def load_record(gallery_path, name):
    """The gallery's view of a figure from its record (None if it has none)."""
    record_path, _ = record_paths(gallery_path, name)
    if not os.path.exists(record_path):
        return None
    with open(record_path) as handle:
        record = json.load(handle)
    return {"name": name, "figure": importlib.import_module(f"figures.{name}").FIGURE,
            "image": record["image"], "markdown": record["markdown"],
            "claims": [Claim(**c) for c in record["claims"]]}


def listed_skeletons():
    """Every skeleton file a registered figure lists, once each, sorted."""
    return sorted({s for name in registered() for s in importlib.import_module(f"figures.{name}").FIGURE.skeletons})


def write_views(skelconv, gallery_path):
    """The `skelconv view` page of every listed skeleton, beside the gallery in views/."""
    root = os.path.dirname(os.path.abspath(gallery_path))
    os.makedirs(os.path.join(root, "views"), exist_ok=True)
    for skeleton in listed_skeletons():
        page = os.path.join(root, "views", gallery.view_name(skeleton))
        run = subprocess.run([skelconv, "view", os.path.join(HERE, "skeletons", skeleton), "-o", page],
                             capture_output=True, text=True)
        if run.returncode != 0:
            print(f"run.py: skelconv view {skeleton} failed: {run.stderr.strip()}", file=sys.stderr)
            return 1
        mode = [line for line in run.stdout.splitlines() if line.startswith("mode:")]
        print(f"views/{gallery.view_name(skeleton)}: {mode[0] if mode else ''}")
    return 0


def write_gallery(gallery_path, compare=False):
    """Rewrites the gallery from the records of every registered figure (2 if one
    has none). compare: write nothing, return 1 unless the file already holds that
    text and every record's image exists (the ctest that the committed gallery is current)."""
    records = [(name, load_record(gallery_path, name)) for name in registered()]
    missing = [name for name, r in records if r is None]
    if missing:
        print("run.py: no record yet for " + ", ".join(missing) + "; draw them first: scripts/figures.sh --only "
              + " ".join(missing) + " --gallery", file=sys.stderr)
        return 2
    results = [r for _, r in records]
    if not compare:
        gallery.write(gallery_path, results, pending())
        print(f"wrote {gallery_path} ({len(records)} figures and tables)")
        return 0
    images = [r["image"] for r in results if r["image"]]
    absent = [i for i in images if not os.path.exists(record_paths(gallery_path, os.path.splitext(i)[0])[1])]
    root = os.path.dirname(os.path.abspath(gallery_path))
    absent += [f"views/{gallery.view_name(s)}" for s in listed_skeletons()
               if not os.path.exists(os.path.join(root, "views", gallery.view_name(s)))]
    with open(gallery_path) as handle:
        current = handle.read() == gallery.text(results, pending())
    if absent or not current:
        print(f"run.py: {gallery_path} is not what its records give" + (f"; images or views missing: {', '.join(absent)}"
              if absent else "") + ": run scripts/figures.sh --gallery-only", file=sys.stderr)
        return 1
    print(f"{gallery_path}: current ({len(records)} records, {len(images)} images)")
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--skelconv", help="the skelconv binary (needed unless --gallery-only)")
    parser.add_argument("--out", help="results folder (PNGs, claims.json; needed unless --gallery-only)")
    parser.add_argument("--only", nargs="*", help="module names (default: every registered one)")
    parser.add_argument("--jobs", type=int, default=1, help="figures drawn at a time, each in its own process")
    parser.add_argument("--quick", action="store_true", help="reduced resolution (ctest)")
    parser.add_argument("--no-images", action="store_true", help="check claims only")
    parser.add_argument("--check", action="store_true", help="exit 1 unless every claim is as expected "
                        "(with --gallery-only: unless the gallery is what the records give; nothing written)")
    parser.add_argument("--gallery", help="refresh the drawn figures' records and images beside this GALLERY.md, "
                                          "then rewrite it")
    parser.add_argument("--gallery-only", metavar="GALLERY", help="rewrite this GALLERY.md from the records, "
                                                                  "drawing nothing")
    parser.add_argument("--views", metavar="GALLERY", help="write the `skelconv view` pages beside this GALLERY.md "
                                                           "(views/), drawing nothing (needs --skelconv)")
    args = parser.parse_args()
    if args.views:
        if not args.skelconv:
            parser.error("--views needs --skelconv")
        return write_views(args.skelconv, args.views)
    if args.gallery_only:
        return write_gallery(args.gallery_only, compare=args.check)
    if not args.skelconv or not args.out:
        parser.error("--skelconv and --out are needed to draw")
    if args.jobs < 1:
        parser.error("--jobs must be at least 1")
    if args.gallery and (args.quick or args.no_images):
        print("run.py: --gallery needs full-resolution images (no --quick, no --no-images)", file=sys.stderr)
        return 2
    os.makedirs(args.out, exist_ok=True)
    plot.print_size(not args.quick)
    names = args.only or registered()
    unknown = [n for n in names if n not in registered()]
    if unknown:
        print(f"run.py: not registered in figures.txt: {', '.join(unknown)}", file=sys.stderr)
        return 2
    start = time.monotonic()
    results = []
    # Each figure is independent of the others (its own files, its own
    # `skelconv` processes): with --jobs N they run N at a time in worker
    # processes; results, records and the gallery keep figures.txt's order.
    with concurrent.futures.ProcessPoolExecutor(max_workers=args.jobs) as pool:
        futures = [pool.submit(run_one, name, args) for name in names]
        for k, (name, future) in enumerate(zip(names, futures), 1):
            results.append(future.result())
            print(f"[{k}/{len(names)}] {name} done in {results[-1]['seconds']:.1f} s "
                  f"({time.monotonic() - start:.0f} s so far)", flush=True)
    elapsed = time.monotonic() - start
    summary = [{"name": r["name"], "heading": r["figure"].heading, "seconds": round(r["seconds"], 1),
                "claims": [{"statement": c.statement, "measured": c.measured, "agrees": c.agrees,
                            "expected": c.expect_agreement} for c in r["claims"]]} for r in results]
    with open(os.path.join(args.out, "claims.json"), "w") as handle:
        json.dump(summary, handle, indent=1)
    status = 0
    if args.gallery:           # written even when a claim is not as expected: the gallery shows it
        for r in results:
            save_record(args.gallery, r)
        status = write_views(args.skelconv, args.gallery) or write_gallery(args.gallery)
    bad = [(r["name"], c.statement) for r in results for c in r["claims"] if not c.as_expected]
    print(f"{len(results)} figures/tables, {sum(len(r['claims']) for r in results)} claims, "
          f"{len(bad)} not as expected, {elapsed:.1f} s")
    if args.check and bad:
        for name, statement in bad:
            print(f"claim not as expected: {name}: {statement}", file=sys.stderr)
        return 1
    return status


if __name__ == "__main__":
    sys.exit(main())
