"""What the Python package costs over the C++ library, on the scaling benchmark's `smooth`
input (random points on the rose r = 1 + 0.3 cos 5t, in order along it), n = 10^6 by default.

Two parts, each a median over the repetitions:
  binding  the wall time of curvebench.reconstruct(points) against `timing_ms["total"]` of
           the same call: Algorithm::reconstruct's own clock, in the same process, on the same
           points, so the ratio is exactly what the binding adds (argument conversion,
           parameter JSON, GIL release, the result object), and a shared host's load weighs
           on both alike.
  build    the module links the libraries built position independent with hidden symbols;
           with --curvebench and --module-build-curvebench (`ninja -C build/python/<wheel
           tag> curvebench` builds the executable with the module's flags), the CPU time of
           `curvebench reconstruct` on the same points file from each build, runs alternating
           (CPU time, as the Google Benchmark suite measures, so that other processes on the
           host do not enter it; it includes reading the points and writing the JSON, the same
           in both).
Not a test: it prints tables. Usage (from the repository root, after the set-up):
  .venv/bin/python harness/bench/python_overhead.py [--n 1000000] [--repetitions 7]
      [--algorithm labeling ...] [--curvebench build/harness/curvebench
       --module-build-curvebench build/python/<wheel tag>/harness/curvebench]
"""
import argparse
import os
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


def cli_cpu_seconds(executable, points_path, output, algorithm):
    child = subprocess.Popen([executable, "reconstruct", "--algorithm", algorithm, "--input", points_path, "--output", output],
                             stdout=subprocess.DEVNULL)
    _, status, usage = os.wait4(child.pid, 0)
    if status != 0:
        raise SystemExit(f"{executable} reconstruct --algorithm {algorithm} failed")
    return usage.ru_utime + usage.ru_stime


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--n", type=int, default=1_000_000)
    parser.add_argument("--repetitions", type=int, default=7)
    parser.add_argument("--algorithm", action="append", help="repeatable; default: labeling")
    parser.add_argument("--curvebench", help="the executable of the executables' build")
    parser.add_argument("--module-build-curvebench", help="the executable built with the module's flags")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    points = smooth_rose(args.n, args.seed)
    algorithms = args.algorithm or ["labeling"]

    print(f"binding: n = {args.n}, {args.repetitions} repetitions, medians of wall time in ms")
    print("| algorithm | python call | C++ reconstruct in the call | python / C++ |")
    print("|---|---|---|---|")
    for algorithm in algorithms:
        python_call(points, algorithm)  # warm: page in the library and the allocator's arenas
        calls = [python_call(points, algorithm) for _ in range(args.repetitions)]
        wall = statistics.median(c[0] for c in calls)
        inside = statistics.median(c[1] for c in calls)
        print(f"| {algorithm} | {wall:.1f} | {inside:.1f} | {wall / inside:.4f} |", flush=True)

    if not (args.curvebench and args.module_build_curvebench):
        return
    print(f"\nbuild: `curvebench reconstruct`, n = {args.n}, {args.repetitions} runs each, alternating, median CPU s")
    print("| algorithm | executables' build | module's build | module / executables |")
    print("|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        points_path, output = pathlib.Path(work) / "points.xy", pathlib.Path(work) / "r.json"
        curvebench.write_points(points_path, points)
        for algorithm in algorithms:
            plain, module = [], []
            for _ in range(args.repetitions):
                plain.append(cli_cpu_seconds(args.curvebench, points_path, output, algorithm))
                module.append(cli_cpu_seconds(args.module_build_curvebench, points_path, output, algorithm))
            a, b = statistics.median(plain), statistics.median(module)
            print(f"| {algorithm} | {a:.3f} | {b:.3f} | {b / a:.4f} |", flush=True)


if __name__ == "__main__":
    main()
