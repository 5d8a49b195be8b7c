#!/usr/bin/env python3
"""The Python module's field paths against the C++ batch API, in one run.

Usage: PYTHONPATH=build/release/python python3 bench/python_field_timing.py \
           build/release/bench/skelconv_bench_public_path

For the one-segment skeletons of bench/public_path_bench.cpp (SCALIS Cauchy 4
and classical Cauchy 4, s = 1) on the same kind of points (uniform in the
segment's box grown by one length), one thread:
  - Skeleton.field(points, threads=1) on 200,000 points, ns per point;
  - Skeleton.value_and_gradient(point), one call per point, ns per call;
  - the C++ benchmark's batch_into/kind:K/primitives:1 (the same C++ path
    as Skeleton.field) and generated_f_and_grad
    (run here, so all numbers come from this one run), and the ratios.
Speed is reported as ratios only; nothing is asserted.
"""
import json
import subprocess
import sys
import time

import numpy as np
import skelconv

SEGMENTS = {
    0: {"type": "scalis_segment", "a": [0, 0, 0], "b": [1, 0.2, 0], "radius": [0.3, 0.2],
        "kernel": {"family": "cauchy", "degree": 4, "sigma": 1.0}},
    1: {"type": "segment", "a": [0, 0, 0], "b": [1, 0.2, 0], "kernel": {"family": "cauchy", "degree": 4, "s": 1.0}},
}


def best_of(repeats, run):
    """The shortest of `repeats` timings of run(), in seconds."""
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        run()
        best = min(best, time.perf_counter() - start)
    return best


def cpp_times(bench):
    """ns per primitive and point of the C++ benchmark's batch and generated runs."""
    out = subprocess.run([bench, "--benchmark_filter=(generated_f_and_grad|batch_into)/kind:./primitives:1$",
                          "--benchmark_format=json", "--benchmark_min_time=0.2"],
                         check=True, capture_output=True, text=True).stdout
    return {b["name"]: b["ns_per_primitive_point"] for b in json.loads(out)["benchmarks"]}


def main():
    cpp = cpp_times(sys.argv[1]) if len(sys.argv) > 1 else {}
    rng = np.random.default_rng(4)
    for kind, segment in SEGMENTS.items():
        skeleton = skelconv.Skeleton([segment])
        points = np.array([-1.0, -1.0, -1.0]) + rng.random((200_000, 3)) * np.array([3.0, 2.2, 2.0])
        field_ns = best_of(3, lambda: skeleton.field(points, threads=1)) / len(points) * 1e9
        single = points[:20_000].tolist()
        call_ns = best_of(3, lambda: [skeleton.value_and_gradient(p) for p in single]) / len(single) * 1e9
        line = f"kind {kind} ({segment['type']}): field {field_ns:.1f} ns/point, value_and_gradient {call_ns:.0f} ns/call"
        batch = cpp.get(f"batch_into/kind:{kind}/primitives:1")
        generated = cpp.get(f"generated_f_and_grad/kind:{kind}/primitives:1")
        if batch and generated:
            line += (f"; C++ batch {batch:.1f}, generated {generated:.1f} ns: field/batch {field_ns / batch:.2f}, "
                     f"field/generated {field_ns / generated:.2f}, call/generated {call_ns / generated:.1f}")
        print(line)


if __name__ == "__main__":
    main()
