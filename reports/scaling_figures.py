"""Runtime and memory against n on log-log axes, one panel per benchmark input, each
algorithm with its fitted slope beside the bare Delaunay construction (the floor)."""
from __future__ import annotations

import math
import pathlib

import numpy as np

from reports.scaling_results import DELAUNAY, ScalingRun, ScalingSuite
from reports.style import DELAUNAY_COLOR, SavedFigure, algorithm_color, algorithm_marker, plt, save_figure, \
    sorted_algorithms

# The slope is fitted over n >= this (where fixed costs no longer dominate) when at least two
# sizes qualify, else over all sizes.
SLOPE_FIT_MIN_N = 10_000


def log_log_slope(ns, values) -> float | None:
    """Least-squares slope of log(value) against log(n); None with fewer than two points."""
    points = [(n, v) for n, v in zip(ns, values) if v is not None and v > 0]
    large = [(n, v) for n, v in points if n >= SLOPE_FIT_MIN_N]
    points = large if len(large) >= 2 else points
    if len(points) < 2:
        return None
    x = np.log10([n for n, _ in points])
    y = np.log10([v for _, v in points])
    return float(np.polyfit(x, y, 1)[0])


def _series(runs: list[ScalingRun], algorithm: str, input_name: str, value):
    chosen = sorted((run for run in runs if run.algorithm == algorithm and run.input == input_name
                     and run.skip_reason is None), key=lambda run: run.n)
    pairs = [(run.n, value(run)) for run in chosen]
    return [n for n, v in pairs if v is not None and v > 0], [v for _, v in pairs if v is not None and v > 0]


def _scaling_figure(suite: ScalingSuite, value, ylabel: str, title_word: str):
    inputs = suite.inputs()
    fig, axes = plt.subplots(1, len(inputs), figsize=(6.2 * len(inputs), 4.8), squeeze=False, sharey=True)
    for ax, input_name in zip(axes[0], inputs):
        ns, values = _series(suite.runs, DELAUNAY, input_name, value)
        if ns:
            slope = log_log_slope(ns, values)
            label = "bare Delaunay (floor)" + (f", slope {slope:.2f}" if slope is not None else "")
            ax.plot(ns, values, color=DELAUNAY_COLOR, linestyle="--", linewidth=2.5, label=label, zorder=3)
        for algorithm in sorted_algorithms(suite.algorithms()):
            ns, values = _series(suite.runs, algorithm, input_name, value)
            if not ns:
                continue
            slope = log_log_slope(ns, values)
            label = algorithm + (f", slope {slope:.2f}" if slope is not None else "")
            ax.plot(ns, values, color=algorithm_color(algorithm), marker=algorithm_marker(algorithm), markersize=5,
                    linewidth=1.6, label=label)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("number of points n")
        ax.set_title(f"{title_word}: {input_name} curve")
        ax.grid(True, which="both", alpha=0.25)
        ax.legend(loc="lower right")
    axes[0][0].set_ylabel(ylabel)
    fig.tight_layout()
    return fig


def _what_was_run(suite: ScalingSuite) -> str:
    sizes = suite.sizes()
    exponents = [round(math.log10(n)) for n in sizes]
    size_text = ", ".join(f"10^{e}" if 10 ** e == n else str(n) for e, n in zip(exponents, sizes))
    context = suite.context
    machine = f"{context.get('num_cpus', '?')} CPUs at {context.get('mhz_per_cpu', '?')} MHz"
    first_skipped = {}  # (algorithm, input) -> its smallest skipped run; the larger n follow from it
    for run in sorted(suite.runs, key=lambda run: run.n):
        if run.skip_reason is not None:
            first_skipped.setdefault((run.algorithm, run.input), run)
    skipped_text = ""
    if first_skipped:
        listed = "; ".join(f"{run.algorithm} on {run.input} from n={run.n:,} ({run.skip_reason})"
                           for run in first_skipped.values())
        skipped_text = f" Not run: {listed}."
    return (f"curvebench_benchmark ({suite.source.name}, {context.get('date', 'undated')}, {machine}): "
            f"the bare CGAL Delaunay construction and {len(suite.algorithms())} algorithms with default parameters "
            f"on the inputs {', '.join(suite.inputs())} (points on the rose r = 1 + 0.3 cos 5t in order along it; the noisy one moved "
            f"along the normal by Gaussian noise of half the mean spacing; the shuffled one in random order) at n = {size_text}.{skipped_text}")


def runtime_figure(suite: ScalingSuite, out_dir: pathlib.Path) -> SavedFigure:
    fig = _scaling_figure(suite, lambda run: run.seconds, "CPU seconds per reconstruction", "Runtime")
    caption = (_what_was_run(suite) + " Thread CPU time of one reconstruction (mean over Google Benchmark's "
               f"iterations). Slopes are least-squares fits of log time against log n over n >= {SLOPE_FIT_MIN_N:,}: "
               "1 is linear; the dashed line is the Delaunay triangulation every Voronoi-based method starts with.")
    return save_figure(fig, out_dir, "scaling_runtime", "Runtime against n", caption)


def memory_figure(suite: ScalingSuite, out_dir: pathlib.Path) -> SavedFigure:
    fig = _scaling_figure(suite, lambda run: run.reconstruction_mib, "peak memory of the reconstruction (MiB)",
                          "Memory")
    caption = (_what_was_run(suite) + " Memory: each run was repeated once in a fresh process; shown is its peak "
               "resident memory (VmHWM) minus the same process's peak before the reconstruction (executable, "
               "libraries and the points), so each point is that run's own need. Slopes fitted as for runtime.")
    return save_figure(fig, out_dir, "scaling_memory", "Memory against n", caption)
