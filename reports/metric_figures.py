"""Figures of the summary's conditions:
  - metrics_by_condition: L2 error, edge F1, curve recall and Hausdorff side by side, the median
    of every method under every condition (a heat map per metric);
  - error_vs_runtime: per condition, each parameter setting's median error against its median
    runtime, one point per setting, with each grid's front (as ann-benchmarks draws them);
  - medial_axis_dominant_points: the distributions of medial-axis Hausdorff, CR and ISE.
Each returns None when there is nothing to draw."""
from __future__ import annotations

import collections
import math
import pathlib

import numpy as np

from reports.conditions import condition_rows
from reports.parameter_settings import default_setting, setting_key, settings_by_algorithm, shared_inputs
from reports.robust_statistics import quartiles
from reports.style import SavedFigure, algorithm_color, algorithm_marker, plt, save_figure, sorted_algorithms
from reports.summary_table import ACCURACY_METRICS, DISTRIBUTIONS_FIGURE, HEATMAP_FIGURE, ConditionSummary, \
    run_value, setting_choice_metric
from reports.sweep_results import SweepRow

# Colour scale of each metric: 0 to this value (L2 above 1 is a wrong region larger than the true one).
_SCALE_TOP = {"l2_error": 1.0, "edge_f1": 1.0, "curve_recall": 1.0, "hausdorff": 0.1}
BEST_OF_GRID = "best of grid"


def _method_rows(summaries: list[ConditionSummary]) -> list[tuple[str, bool]]:
    """(algorithm, best-of-grid) rows of the heat maps: every algorithm at its default, and a
    method with a grid once more at its best setting per condition."""
    algorithms = sorted_algorithms({v.algorithm for s in summaries for v in s.variants})
    gridded = {v.algorithm for s in summaries for v in s.variants if not v.default or "best of" in v.label}
    return [row for a in algorithms for row in ([(a, False), (a, True)] if a in gridded else [(a, False)])]


def _variant_for(summary: ConditionSummary, algorithm: str, best_of_grid: bool):
    of_algorithm = [v for v in summary.variants if v.algorithm == algorithm]
    if not of_algorithm:
        return None
    chosen = [v for v in of_algorithm if not v.default] if best_of_grid else [v for v in of_algorithm if v.default]
    return (chosen or of_algorithm)[0]


def metrics_by_condition_figure(summaries: list[ConditionSummary], out_dir: pathlib.Path) -> SavedFigure | None:
    metrics = [m for m in ACCURACY_METRICS if any(line.measure == m.name for s in summaries for line in s.lines)]
    if not metrics:
        return None
    methods = _method_rows(summaries)
    conditions = [s.name for s in summaries]
    columns = min(2, len(metrics))
    grid_rows = math.ceil(len(metrics) / columns)
    width = 0.8 * len(conditions) + 2.8
    fig, axes = plt.subplots(grid_rows, columns, squeeze=False,
                             figsize=(width * columns, (0.3 * len(methods) + 1.5) * grid_rows))
    for ax, metric in zip(axes.flat, metrics):
        medians = np.full((len(methods), len(conditions)), np.nan)
        notes = {}  # (row, column) -> the default's median on the best setting's inputs
        for column, summary in enumerate(summaries):
            line = next((line for line in summary.lines if line.measure == metric.name), None)
            if line is None:
                continue
            for row, (algorithm, best_of_grid) in enumerate(methods):
                variant = _variant_for(summary, algorithm, best_of_grid)
                if variant is not None and variant.label in line.comparison.statistics:
                    medians[row, column] = line.comparison.statistics[variant.label].median
                    if variant.label in line.default_on_same_inputs:
                        notes[(row, column)] = line.default_on_same_inputs[variant.label]
        top = _SCALE_TOP[metric.key]
        colours = plt.get_cmap("RdYlGn" if metric.higher_is_better else "RdYlGn_r")
        shown = np.where(np.isfinite(medians), np.clip(medians, 0, top), np.nan)
        ax.imshow(shown, cmap=colours, vmin=0, vmax=top, aspect="auto")
        for row in range(len(methods)):
            for column in range(len(conditions)):
                value = medians[row, column]
                if np.isnan(value):
                    text = "-"
                elif math.isinf(value):
                    text = "failed"
                else:
                    text = f"{value:.2g}"
                if (row, column) in notes:
                    text += f"\n(default {notes[(row, column)]:.2g})"
                # Both ends of the colour map are dark: light text there.
                share = shown[row, column] / top if np.isfinite(shown[row, column]) else 0.5
                dark = share < 0.2 or share > 0.8
                ax.text(column, row, text, ha="center", va="center", fontsize=6.5,
                        color="white" if dark else "#111111")
        ax.set_xticks(range(len(conditions)), [c.replace(" ", "\n") for c in conditions], fontsize=7.5)
        ax.set_yticks(range(len(methods)), [f"{a} ({BEST_OF_GRID})" if best else a for a, best in methods],
                      fontsize=7.5)
        ax.grid(False)
        direction = "higher is better" if metric.higher_is_better else "lower is better"
        ax.set_title(f"{metric.name}: median ({direction}; colour 0 to {top:g})")
    for ax in list(axes.flat)[len(metrics):]:
        ax.set_axis_off()
    fig.tight_layout()
    runs = ", ".join(f"{s.name} {s.runs}" for s in summaries)
    caption = ("The summary's metrics side by side: the median over every run of a method under each condition "
               "(a failed run counts as the worst value; 'failed' where half the runs failed; '-' where the metric "
               "is undefined for the method, such as edge F1 for a method with vertices of its own or L2 on open "
               f"curves). Runs per condition (all methods): {runs}. A method with a parameter grid has a second "
               f"row, '{BEST_OF_GRID}', at the setting with the best median of the condition's first defined metric "
               "(L2, else curve recall, else Hausdorff) over the inputs all its settings ran; the summary table names "
               "the setting and on how many inputs it ran. A grid may cover only some of the inputs its default "
               "runs on: its cell then shows in brackets the default's median on the same inputs, which is the fair "
               "comparison with the default. Chosen on the same runs it is scored on, that row is an optimistic "
               "bound. Metrics are defined in reports/README.md.")
    return save_figure(fig, out_dir, HEATMAP_FIGURE, "Accuracy metrics by condition", caption)


def _pareto_front(points: list[tuple[float, float]], higher_is_better: bool) -> list[tuple[float, float]]:
    """The points no other point beats on both time and error, by increasing time."""
    front = []
    for x, y in sorted(points, key=lambda p: (p[0], -p[1] if higher_is_better else p[1])):
        if not front or (y > front[-1][1] if higher_is_better else y < front[-1][1]):
            front.append((x, y))
    return front


def error_runtime_figure(rows: list[SweepRow], out_dir: pathlib.Path) -> SavedFigure | None:
    by_condition = condition_rows(rows)
    all_settings = settings_by_algorithm(rows)
    panels = []
    for name, chosen in by_condition.items():
        metric = setting_choice_metric(chosen)
        if metric is None:
            continue
        points = collections.defaultdict(list)  # algorithm -> (milliseconds, median, default of a grid)
        groups = collections.defaultdict(list)
        for r in chosen:
            groups[(r.algorithm, setting_key(r.parameters))].append(r)
        # A grid's settings are placed by the inputs they all ran (the default may run on more).
        shared = {algorithm: shared_inputs([g for (a, _), g in groups.items() if a == algorithm])
                  for algorithm in {a for a, _ in groups}}
        for (algorithm, key), group in groups.items():
            group = [r for r in group if r.input_key in shared[algorithm]]
            values = [v for v in (run_value(r, metric) for r in group) if v is not None]
            seconds = [r.seconds for r in group if r.ok and r.seconds is not None]
            if not values or not seconds:
                continue
            median = quartiles(values)[0]
            if math.isfinite(median):
                default = (len(all_settings[algorithm]) > 1
                           and setting_key(default_setting(algorithm, all_settings[algorithm])) == key)
                points[algorithm].append((float(np.median(seconds)) * 1000, median, default))
        if points:
            panels.append((name, metric, points))
    if not panels:
        return None
    columns = min(3, len(panels))
    grid_rows = math.ceil(len(panels) / columns)
    fig, axes = plt.subplots(grid_rows, columns, figsize=(5.2 * columns, 4.0 * grid_rows + 0.8), squeeze=False)
    legend = {}
    for ax, (name, metric, points) in zip(axes.flat, panels):
        for algorithm in sorted_algorithms(points):
            found = points[algorithm]
            color, marker = algorithm_color(algorithm), algorithm_marker(algorithm)
            handle = ax.scatter([p[0] for p in found], [p[1] for p in found], color=color, marker=marker, s=28,
                                zorder=3, label=algorithm)
            legend.setdefault(algorithm, handle)
            defaults = [p for p in found if p[2]]
            ax.scatter([p[0] for p in defaults], [p[1] for p in defaults], facecolor="none", edgecolor="black",
                       s=90, linewidths=0.9, zorder=4)
            if len(found) > 1:
                front = _pareto_front([(p[0], p[1]) for p in found], metric.higher_is_better)
                ax.plot([p[0] for p in front], [p[1] for p in front], color=color, linewidth=1.2, zorder=2)
        overall = _pareto_front([(p[0], p[1]) for found in points.values() for p in found], metric.higher_is_better)
        ax.step([p[0] for p in overall], [p[1] for p in overall], where="post", color="#999999", linestyle="--",
                linewidth=1, zorder=1)
        ax.set_xscale("log")
        ax.set_xlabel("median runtime per run (ms)")
        ax.set_ylabel(f"median {metric.name}")
        ax.set_title(name)
        ax.grid(True, which="both", alpha=0.25)
    for ax in list(axes.flat)[len(panels):]:
        ax.set_axis_off()
    labels = sorted_algorithms(legend)
    fig.legend([legend[label] for label in labels], labels, loc="upper center", ncol=min(len(labels), 7),
               frameon=False)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.55 / fig.get_figheight()))
    caption = ("What each parameter setting costs: one point per algorithm and setting under each condition, at the "
               "median of its runs' reconstruction time (the algorithm's own timing_ms total, without evaluation) "
               "and the median of the condition's first defined metric (L2 error, else curve recall, else Hausdorff; "
               "a failed run counts as the worst value); the settings of one grid over the inputs they all ran. "
               "Ringed: the default setting of a method run with a grid. A line joins the "
               "settings of one algorithm's grid that no other of its settings beats on both time and error; the "
               "grey dashed steps are the front over all methods. The times are taken inside each sweep run on a "
               "shared machine and are indicative only: speed is measured by the benchmark (runtime against n).")
    return save_figure(fig, out_dir, "error_vs_runtime", "Error against runtime, one point per setting", caption)


def medial_axis_and_dominant_points_figure(rows: list[SweepRow], out_dir: pathlib.Path) -> SavedFigure | None:
    """Box plots over every finished run of the methods that produce them: medial-axis Hausdorff,
    CR and ISE (log axes: one run far out shows as one far point, not as a moved average)."""
    panels = [("medial_axis_hausdorff", "medial-axis Hausdorff / diagonal"),
              ("compression_ratio", "CR = points / dominant points"),
              ("integral_square_error", "ISE (squared input units)")]
    drawn = []
    for key, label in panels:
        by_algorithm = collections.defaultdict(list)
        for r in rows:
            value = r.metric(key) if r.ok else None
            if value is not None and value > 0:
                by_algorithm[r.algorithm].append(value)
        if by_algorithm:
            drawn.append((key, label, by_algorithm))
    if not drawn:
        return None
    fig, axes = plt.subplots(1, len(drawn), figsize=(4.6 * len(drawn), 4.2), squeeze=False)
    texts = []
    for ax, (key, label, by_algorithm) in zip(axes[0], drawn):
        algorithms = sorted_algorithms(by_algorithm)
        boxes = ax.boxplot([by_algorithm[a] for a in algorithms], whis=(5, 95), patch_artist=True,
                           flierprops={"markersize": 3, "alpha": 0.5})
        for patch, algorithm in zip(boxes["boxes"], algorithms):
            patch.set_facecolor(algorithm_color(algorithm))
            patch.set_alpha(0.55)
        ax.set_xticks(range(1, len(algorithms) + 1), algorithms, rotation=20, fontsize=8)
        ax.set_yscale("log")
        ax.set_title(label)
        texts.append(f"{label}: " + ", ".join(f"{a} {len(by_algorithm[a])} runs" for a in algorithms))
    fig.tight_layout()
    caption = ("Distributions behind the summary's medial-axis and dominant-point lines, over every finished run "
               "with a positive value (log axes leave out zeros: an ISE of 0 is a perfect fit): boxes are the "
               "25-75% range with the median, whiskers 5-95%, dots the runs beyond. " + "; ".join(texts) + ".")
    return save_figure(fig, out_dir, DISTRIBUTIONS_FIGURE, "Medial axis and dominant points", caption)
