"""Which method is best under which condition: one line per condition the results cover, each
naming the measure, the best algorithm, the runner-up and every algorithm's value."""
from __future__ import annotations

import collections
import dataclasses
import html
from typing import Callable

import numpy as np

from reports.accuracy_figures import corner_rows, density_rows, epsilon_rows, noise_rows, outlier_rows, \
    right_topology
from reports.scaling_results import DELAUNAY, ScalingSuite
from reports.style import format_values, sorted_algorithms
from reports.sweep_results import SweepRow


@dataclasses.dataclass
class SummaryLine:
    condition: str
    measure: str
    values: dict[str, float]  # per algorithm
    higher_is_better: bool
    value_format: str

    def ranking(self) -> list[str]:
        return sorted(self.values, key=lambda a: (-self.values[a] if self.higher_is_better else self.values[a], a))

    def formatted(self, algorithm: str) -> str:
        return self.value_format.format(self.values[algorithm])


def _mean_by_algorithm(rows: list[SweepRow], value: Callable[[SweepRow], float | None]) -> dict[str, float]:
    """Mean of `value` per algorithm; a run without a result counts as `value` None and is skipped."""
    values = collections.defaultdict(list)
    for r in rows:
        v = value(r) if r.ok else None
        if v is not None:
            values[r.algorithm].append(v)
    return {algorithm: float(np.mean(v)) for algorithm, v in values.items()}


def _mean_l2_line(experiment: str, rows: list[SweepRow]) -> SummaryLine:
    """The mean L2 error of each algorithm over these rows (lower is better)."""
    return SummaryLine(experiment, "mean L2 error", _mean_by_algorithm(rows, lambda r: r.metric("l2_error")),
                       False, "{:.2e}")


def _success_share(rows: list[SweepRow], success: Callable[[SweepRow], bool | None]) -> dict[str, float]:
    """Share of runs per algorithm that succeed; failed runs count as unsuccessful, runs for which
    success is undefined (None) are skipped."""
    outcomes = collections.defaultdict(list)
    for r in rows:
        outcome = success(r) if r.ok else False
        if outcome is not None:
            outcomes[r.algorithm].append(float(outcome))
    return {algorithm: 100 * float(np.mean(o)) for algorithm, o in outcomes.items()}


def _largest_all_exact_epsilon(rows: list[SweepRow]) -> dict[str, float]:
    """Per algorithm, the largest epsilon up to which every run (all smaller epsilons too) is exact."""
    result = {}
    for algorithm in {r.algorithm for r in rows}:
        runs = [r for r in rows if r.algorithm == algorithm]
        if any(r.ok and r.metric("exact") is None for r in runs):
            continue  # not an interpolating method: exactness is undefined
        largest = 0.0
        for epsilon in sorted({r.epsilon for r in runs}):
            if all(r.ok and r.metric("exact") == 1 for r in runs if r.epsilon == epsilon):
                largest = epsilon
            else:
                break
        result[algorithm] = largest
    return result


def summary_lines(rows: list[SweepRow], suite: ScalingSuite | None) -> list[SummaryLine]:
    lines = []
    clean = epsilon_rows(rows)
    if clean:
        lines.append(SummaryLine("Clean smooth curves (epsilon-samples)",
                                 f"largest epsilon (of {format_values({r.epsilon for r in clean})}) up to which "
                                 "every run is exact", _largest_all_exact_epsilon(clean), True, "{:.3g}"))
        single = [r for r in clean if r.true_curves == 1]
        several = [r for r in clean if (r.true_curves or 0) > 1]
        if single:
            lines.append(SummaryLine("One curve, all epsilons", "runs with the right topology (%)",
                                     _success_share(single, right_topology), True, "{:.0f}"))
        if several:
            lines.append(SummaryLine("Several curves", "runs with the right topology (%)",
                                     _success_share(several, right_topology), True, "{:.0f}"))
    dense = density_rows(rows)
    if dense:
        shapes = {r.shape for r in dense}
        sparsest = {shape: min(r.sampling_level for r in dense if r.shape == shape) for shape in shapes}
        densest = {shape: max(r.sampling_level for r in dense if r.shape == shape) for shape in shapes}
        lines.append(_mean_l2_line("Sparse sampling (sparsest setting of each shape)",
                                   [r for r in dense if r.sampling_level == sparsest[r.shape]]))
        lines.append(_mean_l2_line("Dense sampling (densest setting of each shape)",
                                   [r for r in dense if r.sampling_level == densest[r.shape]]))
    corners = corner_rows(rows)
    if corners:
        families = ", ".join(sorted({r.family for r in corners}))
        lines.append(SummaryLine(f"Sharp corners ({families}), all epsilons", "exact runs (%)",
                                 _success_share(corners, lambda r: None if r.metric("exact") is None
                                                else r.metric("exact") == 1), True, "{:.0f}"))
    noisy = noise_rows(rows)
    if noisy:
        for model in sorted({r.noise_model for r in noisy if r.noise > 0}):
            strongest = max(r.noise for r in noisy if r.noise_model == model)
            lines.append(_mean_l2_line(f"Noise ({model}, strongest level, {strongest:g})",
                                       [r for r in noisy if r.noise_model == model and r.noise == strongest]))
    with_outliers = outlier_rows(rows)
    if with_outliers:
        most = max(r.outliers for r in with_outliers)
        lines.append(_mean_l2_line(f"Outliers (most, {100 * most:g}%)",
                                   [r for r in with_outliers if r.outliers == most]))
    medial = _mean_by_algorithm(rows, lambda r: r.metric("medial_axis_hausdorff"))
    if medial:
        lines.append(SummaryLine("Medial axis", "mean Hausdorff distance to the true axis / diagonal", medial, False,
                                 "{:.3f}"))
    figure_of_merit = _mean_by_algorithm(rows, lambda r: r.metric("figure_of_merit"))
    if figure_of_merit:
        lines.append(SummaryLine("Dominant points", "mean FOM = CR / ISE", figure_of_merit, True, "{:.3g}"))
    if suite is not None:
        for input_name in suite.inputs():
            runs = [r for r in suite.runs if r.input == input_name and r.skip_reason is None and r.algorithm != DELAUNAY]
            if not runs:
                continue
            largest = max(r.n for r in runs)
            at_largest = [r for r in runs if r.n == largest]
            lines.append(SummaryLine(f"Speed, {input_name} curve, n = {largest:,}", "time / bare Delaunay time",
                                     {r.algorithm: r.times_delaunay for r in at_largest
                                      if r.times_delaunay is not None}, False, "{:.2f}x"))
            lines.append(SummaryLine(f"Memory, {input_name} curve, n = {largest:,}", "peak MiB of the reconstruction",
                                     {r.algorithm: r.reconstruction_mib for r in at_largest
                                      if r.reconstruction_mib is not None}, False, "{:.1f}"))
    return [line for line in lines if line.values]


def summary_table_html(lines: list[SummaryLine]) -> str:
    algorithms = sorted_algorithms({a for line in lines for a in line.values})
    head = "".join(f"<th>{html.escape(a)}</th>" for a in algorithms)
    body = []
    for line in lines:
        ranking = line.ranking()
        best = ranking[0]
        cells = []
        for algorithm in algorithms:
            if algorithm not in line.values:
                cells.append('<td class="missing">-</td>')
            elif line.values[algorithm] == line.values[best]:
                cells.append(f'<td class="best">{line.formatted(algorithm)}</td>')
            else:
                cells.append(f"<td>{line.formatted(algorithm)}</td>")
        winners = [a for a in ranking if line.values[a] == line.values[best]]
        runner_up = next((a for a in ranking if line.values[a] != line.values[best]), "-")
        direction = "higher is better" if line.higher_is_better else "lower is better"
        body.append(f"<tr><th scope=\"row\">{html.escape(line.condition)}</th><td>{html.escape(line.measure)} "
                    f"<span class=\"direction\">({direction})</span></td><td class=\"winner\">"
                    f"{html.escape(', '.join(winners))}</td><td>{html.escape(runner_up)}</td>{''.join(cells)}</tr>")
    return (f"<table class=\"summary\"><thead><tr><th>condition</th><th>measure</th><th>best</th>"
            f"<th>runner-up</th>{head}</tr></thead><tbody>{''.join(body)}</tbody></table>")
