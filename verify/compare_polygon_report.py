#!/usr/bin/env python3
"""Compares a fresh polygon sweep report with a committed baseline.

    compare_polygon_report.py BASE.json NEW.json [--factor 2] [--floor 3.55e-15]

The polygon counterpart of `skelconv-verify compare` (verify/compare.hpp),
with the same rules, so every region is held to what the baseline showed,
not only the generic one the sweep's own verdict asserts:

- a (family, degree, region) cell of BASE missing from NEW, or compared on
  no point in NEW while BASE compared some, fails (coverage lost);
- max_f, max_grad or max_grad_component worse than factor x BASE fails, when
  above the floor (16 ulps of 1: below it an error tells nothing about the
  formula, as in CompareOptions::double_floor);
- any non-finite result where BASE had none fails;
- a cell whose exclusions went beyond the limits fails;
- a cell only in NEW is listed as new and does not fail.
- a BASE without any cell fails (a comparison of nothing proves nothing).

Exit status 0 when nothing failed, 1 otherwise (with the line
"CHECK-FAILED: worse or lost in regions: R, ..." naming every failing
region), 2 on unreadable input.
"""
import argparse
import json
import sys

MAXIMA = ("max_f", "max_grad", "max_grad_component")


def cells(path):
    try:
        with open(path, encoding="utf-8") as file:
            report = json.load(file)
        return {(c["family"], c["degree"], c["region"]): c for c in report["cells"]}
    except (OSError, ValueError, KeyError, TypeError) as error:
        print(f"compare_polygon_report: {path}: not a polygon sweep report ({error})", file=sys.stderr)
        sys.exit(2)


def failures(before, after, factor, floor):
    """The reasons a cell got worse, empty when it did not."""
    if after["points"] == 0 and before["points"] > 0:
        return ["no point compared"]
    reasons = []
    for name in MAXIMA:
        limit = max(factor * before[name], floor)
        if not after[name] <= limit:  # NaN fails too
            reasons.append(f"{name} {before[name]:.2e} -> {after[name]:.2e} (limit {limit:.2e})")
    if after["nonfinite"] > before["nonfinite"]:
        reasons.append(f"non-finite results {before['nonfinite']} -> {after['nonfinite']}")
    if not after["exclusions_within_limits"]:
        reasons.append(f"exclusions beyond the limits ({after['excluded']} excluded)")
    return reasons


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("base")
    parser.add_argument("new")
    parser.add_argument("--factor", type=float, default=2.0, help="allowed growth of a maximum (default 2)")
    parser.add_argument("--floor", type=float, default=16 * 2.0**-52, help="maxima below this never fail")
    args = parser.parse_args()
    base, new = cells(args.base), cells(args.new)
    failed, regions = 0, set()
    for key, before in sorted(base.items()):
        if key not in new:
            print(f"  lost: {key[0]} i={key[1]} {key[2]} (in BASE, not in NEW)")
            failed += 1
            regions.add(key[2])
            continue
        reasons = failures(before, new[key], args.factor, args.floor)
        if reasons:
            print(f"  worse: {key[0]} i={key[1]} {key[2]}: " + "; ".join(reasons))
            failed += 1
            regions.add(key[2])
    for key in sorted(set(new) - set(base)):
        print(f"  new: {key[0]} i={key[1]} {key[2]} (not in BASE)")
    print(f"compare: {len(base)} cells compared, {failed} worse or lost, factor {args.factor}, floor {args.floor:.2e}")
    if failed:
        print(f"CHECK-FAILED: worse or lost in regions: {', '.join(sorted(regions))}")
    if not base:
        print(f"CHECK-FAILED: no cell compared: {args.base} holds none")
    return 1 if failed or not base else 0


if __name__ == "__main__":
    sys.exit(main())
