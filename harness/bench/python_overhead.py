"""What the Python package costs over the C++ library: on the scaling benchmark's `smooth`
input (random points on the rose r = 1 + 0.3 cos 5t, in order along it), the wall time of
curvebench.reconstruct(points) against the time the C++ reconstruction itself takes.

Two C++ references, each a median over the repetitions:
  in-call  `timing_ms["total"]` of the same call: Algorithm::reconstruct's own clock, in
           the same process, on the same points, so the ratio is exactly what the binding
           adds (argument conversion, parameter JSON, GIL release, the result object).
  cli      `timing_ms.total` of `curvebench reconstruct` on the same points written to a
           file: the executable's build of the library (not position independent), so the
           ratio also holds what building the library for a shared module costs.
Not a test: it prints a table. Usage (from the repository root, after the set-up):
  .venv/bin/python harness/bench/python_overhead.py [--n 1000000] [--repetitions 7]
      [--algorithm labeling ...] [--curvebench build/harness/curvebench]
"""
import argparse
import json
import pathlib
import statistics
import subprocess
import tempfile
import time

import numpy as np

import curvebench


def smooth_rose(n, seed):
    """The benchmark's `smooth` input (harness/bench/scaling_benchmark.cpp)."""
    t = np.sort(np.random.default_rng(seed).uniform(0.0, 2.0 * np.pi, n))
    r = 1.0 + 0.3 * np.cos(5.0 * t)
    return np.ascontiguousarray(np.column_stack([r * np.cos(t), r * np.sin(t)]))


def python_call(points, algorithm):
    start = time.perf_counter()
    result = curvebench.reconstruct(points, algorithm=algorithm)
    return (time.perf_counter() - start) * 1e3, result.timing_ms["total"]


def cli_total(curvebench_bin, points_path, output, algorithm):
    subprocess.run([curvebench_bin, "reconstruct", "--algorithm", algorithm, "--input", points_path, "--output", output],
                   check=True, capture_output=True)
    return json.loads(pathlib.Path(output).read_text())["timing_ms"]["total"]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--n", type=int, default=1_000_000)
    parser.add_argument("--repetitions", type=int, default=7)
    parser.add_argument("--algorithm", action="append", help="repeatable; default: labeling")
    parser.add_argument("--curvebench", default="build/harness/curvebench", help="the executable ('' skips the cli column)")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    points = smooth_rose(args.n, args.seed)

    print(f"n = {args.n}, {args.repetitions} repetitions, medians in ms")
    print("| algorithm | python call | in-call C++ total | python / in-call | cli C++ total | python / cli |")
    print("|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        points_path = pathlib.Path(work) / "points.xy"
        if args.curvebench:
            curvebench.write_points(points_path, points)
        for algorithm in args.algorithm or ["labeling"]:
            python_call(points, algorithm)  # warm: page in the library and the allocator's arenas
            calls = [python_call(points, algorithm) for _ in range(args.repetitions)]
            wall = statistics.median(c[0] for c in calls)
            inside = statistics.median(c[1] for c in calls)
            row = f"| {algorithm} | {wall:.1f} | {inside:.1f} | {wall / inside:.4f} |"
            if args.curvebench:
                cli = statistics.median(cli_total(args.curvebench, points_path, pathlib.Path(work) / "r.json", algorithm)
                                        for _ in range(args.repetitions))
                row += f" {cli:.1f} | {wall / cli:.4f} |"
            else:
                row += " | |"
            print(row, flush=True)


if __name__ == "__main__":
    main()
