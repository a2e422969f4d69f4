"""Figures of reconstruction quality from the sweep rows:
  - L2 error against sampling density for each shape and algorithm (the paper's Figure 16);
  - success rate against epsilon for each algorithm, with the theoretical bounds marked;
  - robustness: L2 error against noise and against the share of outliers.
Each returns None when the rows hold no run of its kind."""
from __future__ import annotations

import collections
import math
import pathlib

import numpy as np
from matplotlib.ticker import FixedFormatter, FixedLocator, NullLocator

from reports.style import BOUND_NOTES, THEORETICAL_EPSILON_BOUNDS, SavedFigure, algorithm_color, algorithm_marker, \
    format_values, plt, save_figure, sorted_algorithms, stacked_line_width
from reports.sweep_results import SweepRow

ORACLE_COLOR = "#444444"
ORACLE_LABEL = "samples joined in true order"


def density_rows(rows: list[SweepRow]) -> list[SweepRow]:
    """Clean runs (no noise, no outliers) of every shape sampled at two or more densities."""
    clean = [r for r in rows if r.noise == 0 and r.outliers == 0]
    levels = collections.defaultdict(set)
    for r in clean:
        levels[r.shape].add(r.sampling_level)
    return [r for r in clean if len(levels[r.shape]) >= 2]


def samples_per_level(rows: list[SweepRow]) -> dict[tuple[str, float], float]:
    """The median number of input points of each (shape, sampling level): the density axis."""
    points = collections.defaultdict(list)
    for r in rows:
        if r.input_points is not None:
            points[(r.shape, r.sampling_level)].append(r.input_points)
    return {key: float(np.median(values)) for key, values in points.items()}


def epsilon_rows(rows: list[SweepRow]) -> list[SweepRow]:
    """Clean epsilon-samples of smooth curves (the guarantee experiment)."""
    return [r for r in rows if r.epsilon is not None and r.noise == 0 and r.outliers == 0 and r.smooth]


def noise_rows(rows: list[SweepRow]) -> list[SweepRow]:
    """Runs without outliers whose settings vary the noise (noise-free runs of the same shapes included)."""
    noisy_shapes = {r.shape for r in rows if r.noise > 0 and r.outliers == 0}
    return [r for r in rows if r.shape in noisy_shapes and r.outliers == 0]


def outlier_rows(rows: list[SweepRow]) -> list[SweepRow]:
    """Noise-free runs of shapes that were also run with outliers."""
    shapes = {r.shape for r in rows if r.outliers > 0 and r.noise == 0}
    return [r for r in rows if r.shape in shapes and r.noise == 0]


def right_topology(r: SweepRow) -> bool:
    """A 2-manifold with as many components, all closed, as the truth has curves."""
    return (r.metric("manifold") == 1 and r.true_curves is not None and r.metric("components") == r.true_curves
            and r.metric("closed_components") == r.true_curves)


def _statistics(values: list[float]) -> tuple[float, float, float]:
    """Median and the 25th and 75th percentiles."""
    low, median, high = np.percentile(values, [25, 50, 75])
    return float(median), float(low), float(high)


def _failures_text(rows: list[SweepRow]) -> str:
    failed = collections.Counter((r.algorithm, r.status) for r in rows if not r.ok)
    if not failed:
        return "Every run finished."
    listed = ", ".join(f"{algorithm} {count} {status}" for (algorithm, status), count in sorted(failed.items()))
    return f"Runs without a result ({listed}) are left out of the curves."


def _runs_text(rows: list[SweepRow]) -> str:
    algorithms = sorted_algorithms({r.algorithm for r in rows})
    seeds = sorted({r.seed for r in rows})
    return (f"{len(rows)} sweep rows: {len(algorithms)} algorithms ({', '.join(algorithms)}), "
            f"{len({r.shape for r in rows})} shapes, seeds {format_values(seeds, '{:d}')}")


def _label_sampled_values(ax, values):
    """Ticks of a log x axis at exactly the values that were run, written as plain numbers."""
    ax.xaxis.set_major_locator(FixedLocator(values))
    ax.xaxis.set_major_formatter(FixedFormatter([f"{v:g}" for v in values]))
    ax.xaxis.set_minor_locator(NullLocator())


# L2 errors span orders of magnitude and exact reconstructions have L2 = 0: the axis is
# logarithmic above this value and linear below it, so that 0 shows.
L2_LINEAR_BELOW = 1e-4


def _l2_lines(ax, rows: list[SweepRow], algorithms: list[str], x_of):
    """One line per algorithm: the median L2 error of its successful runs at each x = x_of(row),
    with the band of _statistics around it."""
    for order, algorithm in enumerate(algorithms):
        by_x = collections.defaultdict(list)
        for r in rows:
            if r.ok and r.algorithm == algorithm and r.metric("l2_error") is not None:
                by_x[x_of(r)].append(r.metric("l2_error"))
        if not by_x:
            continue
        xs = sorted(by_x)
        stats = [_statistics(by_x[x]) for x in xs]
        color = algorithm_color(algorithm)
        ax.plot(xs, [s[0] for s in stats], color=color, marker=algorithm_marker(algorithm),
                markersize=4, linewidth=stacked_line_width(order, len(algorithms)), alpha=0.9, label=algorithm)
        ax.fill_between(xs, [s[1] for s in stats], [s[2] for s in stats], color=color, alpha=0.12, linewidth=0)


def _l2_axis(ax):
    ax.set_yscale("symlog", linthresh=L2_LINEAR_BELOW)
    ax.set_ylim(bottom=0)
    ax.set_ylabel("L2 error (sym. difference / true area)")


def l2_density_figure(rows: list[SweepRow], out_dir: pathlib.Path) -> SavedFigure | None:
    chosen = density_rows(rows)
    if not chosen:
        return None
    shapes = sorted({r.shape for r in chosen})
    algorithms = sorted_algorithms({r.algorithm for r in chosen})
    columns = min(3, len(shapes))
    grid_rows = math.ceil(len(shapes) / columns)
    fig, axes = plt.subplots(grid_rows, columns, figsize=(4.6 * columns, 3.6 * grid_rows + 0.5), squeeze=False)
    samples = samples_per_level(chosen)
    for ax, shape in zip(axes.flat, shapes):
        of_shape = [r for r in chosen if r.shape == shape]
        density = {r.sampling_level: samples.get((shape, r.sampling_level)) for r in of_shape}
        _oracle_line(ax, of_shape, lambda r: density[r.sampling_level])
        _l2_lines(ax, of_shape, algorithms, lambda r: density[r.sampling_level])
        ax.set_xscale("log")
        _l2_axis(ax)
        _label_sampled_values(ax, sorted({x for x in density.values() if x is not None}))
        ax.set_title(shape)
        ax.set_xlabel("number of samples")
        ax.grid(True, which="both", alpha=0.25)
    for ax in axes[:, 1:].flat:
        ax.set_ylabel("")
    for ax in list(axes.flat)[len(shapes):]:
        ax.set_axis_off()
    legend = {}
    for ax in list(axes.flat)[:len(shapes)]:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            legend.setdefault(label, handle)
    labels = sorted_algorithms(set(legend) - {ORACLE_LABEL}) + ([ORACLE_LABEL] if ORACLE_LABEL in legend else [])
    fig.legend([legend[label] for label in labels], labels, loc="upper center", ncol=min(len(labels), 7),
               frameon=False)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.4 / fig.get_figheight()))
    counts = sorted({r.count for r in chosen if r.epsilon is None})
    epsilons = sorted({r.epsilon for r in chosen if r.epsilon is not None})
    samplings = ([f"{format_values(counts, '{:d}')} points along arc length"] if counts else []) + \
        ([f"epsilon-samples at epsilon = {format_values(epsilons)}"] if epsilons else [])
    caption = (f"{_runs_text(chosen)}; each shape sampled as {' and '.join(samplings)}, without noise or outliers; "
               "the axis is the median number of samples at each setting. L2 error is the area of the symmetric difference between the true "
               "region and the even-odd fill of the reconstructed edges, over the true area; lines are medians over "
               "seeds, bands the 25-75% range. The dotted line joins the samples in their true order: the error the "
               f"sampling itself causes. The error axis is logarithmic above {L2_LINEAR_BELOW:g} and linear below, "
               f"so that an error of 0 shows. {_failures_text(chosen)}")
    return save_figure(fig, out_dir, "l2_vs_density", "L2 error against sampling density (cf. paper Fig. 16)",
                       caption)


def success_epsilon_figure(rows: list[SweepRow], out_dir: pathlib.Path) -> SavedFigure | None:
    chosen = epsilon_rows(rows)
    if not chosen:
        return None
    algorithms = sorted_algorithms({r.algorithm for r in chosen})
    panels = [("exact: edges = true adjacency", lambda r: r.metric("exact")),
              ("right topology: manifold, as many closed curves as the truth",
               lambda r: float(right_topology(r)))]
    fig, axes = plt.subplots(1, 2, figsize=(12.5, 5.2), sharey=True)
    epsilons = sorted({r.epsilon for r in chosen})
    for ax, (title, success) in zip(axes, panels):
        for order, algorithm in enumerate(algorithms):
            rates = []
            for epsilon in epsilons:
                runs = [r for r in chosen if r.algorithm == algorithm and r.epsilon == epsilon]
                outcomes = [success(r) if r.ok else 0.0 for r in runs]
                known = [o for o in outcomes if o is not None]
                rates.append(100 * float(np.mean(known)) if known else None)
            points = [(e, v) for e, v in zip(epsilons, rates) if v is not None]
            if points:
                ax.plot(*zip(*points), color=algorithm_color(algorithm), marker=algorithm_marker(algorithm),
                        markersize=4, linewidth=stacked_line_width(order, len(algorithms)), alpha=0.9,
                        label=algorithm)
        for algorithm, bound in THEORETICAL_EPSILON_BOUNDS.items():
            if algorithm in algorithms:
                ax.axvline(bound, color=algorithm_color(algorithm), linestyle="--", linewidth=1.2,
                           label=f"{algorithm} bound {bound:.3g} ({BOUND_NOTES[algorithm]})")
        ax.set_title(title)
        ax.set_xlabel("epsilon of the epsilon-sample")
        ax.set_ylim(-3, 103)
    axes[0].set_ylabel("successful runs (%)")
    handles, labels = axes[1].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=min(len(labels), 5), frameon=False)
    fig.tight_layout(rect=(0, 0.09, 1, 1))
    caption = (f"{_runs_text(chosen)}; epsilon-samples (every curve point within epsilon times the local feature "
               f"size of a sample, random steps) at epsilon = {format_values(epsilons)}, without noise or outliers, "
               "of smooth curves only (the bounds are for smooth curves; shapes with sharp corners are in the summary "
               "table). "
               "Left: share of runs whose edge set equals the true adjacency (interpolating methods only). Right: "
               "share whose output is a 2-manifold with the true number of closed curves. Dashed lines: the largest "
               "epsilon each method is proved (crust 0.252, NN-crust 1/3) or claimed (labeling 0.4) to reconstruct. "
               f"Failed runs count as unsuccessful. {_failures_text(chosen)}")
    return save_figure(fig, out_dir, "success_vs_epsilon", "Success rate against epsilon", caption)


def _oracle_line(ax, rows: list[SweepRow], setting):
    """The median error of the samples joined in their true order, per value of `setting`."""
    by_value = collections.defaultdict(list)
    for r in rows:
        value = setting(r)
        if r.oracle_l2_error is not None and value is not None:
            by_value[value].append(r.oracle_l2_error)
    if by_value:
        values = sorted(by_value)
        ax.plot(values, [float(np.median(by_value[v])) for v in values], color=ORACLE_COLOR, linestyle=":",
                linewidth=2, label=ORACLE_LABEL, zorder=5)


def _robustness_panel(ax, rows: list[SweepRow], setting, xlabel: str):
    levels_run = {setting(r) for r in rows}
    algorithms = sorted_algorithms({r.algorithm for r in rows})
    _l2_lines(ax, rows, algorithms, setting)
    _oracle_line(ax, rows, setting)
    _l2_axis(ax)
    _label_sampled_values(ax, sorted(levels_run))
    ax.set_xlabel(xlabel)
    ax.grid(True, which="both", alpha=0.25)


def robustness_figure(rows: list[SweepRow], out_dir: pathlib.Path) -> SavedFigure | None:
    noisy, with_outliers = noise_rows(rows), outlier_rows(rows)
    scale_names = {"lfs": "local feature size", "diagonal": "bounding-box diagonal"}
    # One panel per noise model and scale: a Gaussian level (standard deviation) and a uniform
    # one (half-width of the band) are different amounts of noise. Noise-free runs join each.
    model_names = {"gaussian": "standard deviation along the normal",
                   "uniform": "half-width of the uniform band along the normal"}
    kinds = sorted({(r.noise_model, r.noise_scale) for r in noisy if r.noise > 0})
    panels = [([r for r in noisy if r.noise_scale == scale and (r.noise == 0 or r.noise_model == model)],
               lambda r: r.noise, f"noise ({model_names.get(model, model)}, x {scale_names.get(scale, scale)})",
               "Noise" if len(kinds) == 1 else f"{model.capitalize()} noise")
              for model, scale in kinds]
    if with_outliers:
        panels.append((with_outliers, lambda r: 100 * r.outliers, "outliers (% of the curve samples)", "Outliers"))
    if not panels:
        return None
    fig, axes = plt.subplots(1, len(panels), figsize=(6.2 * len(panels), 4.6), squeeze=False)
    texts = []
    for ax, (chosen, setting, label, title) in zip(axes[0], panels):
        _robustness_panel(ax, chosen, setting, label)
        ax.set_title(f"{title}: median L2 error, 25-75% band")
        levels = sorted({setting(r) for r in chosen})
        texts.append(f"{title.lower()}: {_runs_text(chosen)} at levels {format_values(levels)}. "
                     f"{_failures_text(chosen)}")
    for ax in axes[0][1:]:
        ax.set_ylabel("")
    axes[0][-1].legend(loc="lower right")
    fig.tight_layout()
    caption = ("L2 error as the input degrades. " + " ".join(texts) + " Medians over shapes and seeds, bands the "
               "25-75% range; the dotted line joins the curve samples in their true order (the error of the sampling "
               f"itself). The error axis is logarithmic above {L2_LINEAR_BELOW:g} and linear below, so that an error "
               "of 0 shows.")
    return save_figure(fig, out_dir, "robustness", "Robustness to noise and outliers (cf. paper Fig. 12)", caption)
