#!/usr/bin/env python3
"""Writes a copy of a polygon sweep report with one region made worse.

    worsen_polygon_report.py IN.json OUT.json REGION FACTOR

Every cell of REGION gets its max_f multiplied by FACTOR: the purpose-built
broken input that shows compare_polygon_report.py failing on that region
alone (ctest verify_compare_polygon_catches_worsened).
"""
import json
import sys

source, target, region, factor = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
with open(source, encoding="utf-8") as file:
    report = json.load(file)
hit = [c for c in report["cells"] if c["region"] == region]
if not hit:
    sys.exit(f"worsen_polygon_report: no cell of region {region} in {source}")
for cell in hit:
    # Above the comparison's floor even where the baseline's error is 0.
    cell["max_f"] = max(cell["max_f"] * factor, 1e-12)
with open(target, "w", encoding="utf-8") as file:
    json.dump(report, file, indent=1)
