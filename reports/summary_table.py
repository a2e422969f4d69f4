"""Which method is best under which condition.

In:  the sweep rows (and the scaling benchmark, for speed and memory).
Out: per condition of reports/conditions.py, one line per accuracy metric (L2 error, edge F1,
     curve recall, Hausdorff): every method's median, interquartile range and share of runs
     within the metric's tolerance of the best on the same input (robust_statistics.py), the
     best and the runner-up, their head-to-head count on the inputs both ran, and whether that
     separates them; then whether the metrics agree. Lines for the medial axis and the dominant
     points follow, and for speed and memory. A method run with a parameter grid takes part
     twice: at its default and at the grid's best setting under the condition (chosen by the
     condition's first defined metric of L2 error, curve recall, Hausdorff).
"""
from __future__ import annotations

import collections
import dataclasses
import json
import math

import numpy as np

from reports.conditions import CONDITIONS, condition_rows
from reports.parameter_settings import changed_values_text, default_setting, setting_key, settings_by_algorithm, \
    shared_inputs
from reports.robust_statistics import Comparison, HeadToHead, Metric, compare, quartiles
from reports.scaling_results import DELAUNAY, ScalingSuite
from reports.style import sorted_algorithms
from reports.sweep_results import SweepRow

ACCURACY_METRICS = [
    Metric("l2_error", "L2 error", higher_is_better=False, tolerance=0.01),
    Metric("edge_f1", "edge F1", higher_is_better=True, tolerance=0.02),
    Metric("curve_recall", "curve recall", higher_is_better=True, tolerance=0.02),
    Metric("hausdorff", "Hausdorff / diagonal", higher_is_better=False, tolerance=0.005),
]
# The metric that picks a grid's best setting: the first of these the condition defines (L2 is
# undefined on open curves).
SETTING_CHOICE_METRICS = ["l2_error", "curve_recall", "hausdorff"]
MEDIAL_AXIS_METRIC = Metric("medial_axis_hausdorff", "medial-axis Hausdorff / diagonal", higher_is_better=False,
                            tolerance=0.005)
# FOM spans orders of magnitude: two runs tie within 5% of the larger.
FIGURE_OF_MERIT = Metric("figure_of_merit", "FOM = CR / ISE", higher_is_better=True, tolerance=0.05, relative=True)
HEATMAP_FIGURE = "metrics_by_condition"
DISTRIBUTIONS_FIGURE = "medial_axis_dominant_points"
# The best is separated from a method when it is better on at least this many more shared inputs
# than it is worse: one run turned from a win into a loss moves the difference by 2, so no single
# run can reverse a verdict.
SEPARATING_MARGIN = 3
# A method is ranked when it has a value (or a failure) on at least this share of the inputs.
RANKED_COVERAGE = 0.9


def run_value(r: SweepRow, metric: Metric) -> float | None:
    """The run's value of the metric; a failed run is the metric's worst value; None where the
    finished run does not define it."""
    if not r.ok:
        return metric.failure
    if metric is FIGURE_OF_MERIT and r.metric("integral_square_error") == 0:
        return math.inf  # the polygon through the dominant points passes through every sample
    return r.metric(metric.key)


@dataclasses.dataclass
class Variant:
    """One method as the summary shows it: an algorithm at one parameter setting."""

    label: str
    algorithm: str
    rows: list[SweepRow]
    default: bool  # at the algorithm's default setting (so is a method run with one setting only)

    def values(self, metric: Metric, defined_anywhere: set[tuple[str, str]]) -> dict[str, float]:
        """input -> value; empty when the metric is undefined for this method."""
        if (self.algorithm, metric.key) not in defined_anywhere:
            return {}
        values = {}
        for r in self.rows:
            v = run_value(r, metric)
            if v is not None:
                values[r.input_key] = v
        return values


def defined_metrics(rows: list[SweepRow], metrics: list[Metric]) -> set[tuple[str, str]]:
    """(algorithm, metric) pairs with a value on at least one finished run: a method whose every
    finished run leaves a metric null (edge F1 of a method with vertices of its own) is not scored
    on it, while its failed runs still count against it where it is defined."""
    return {(r.algorithm, m.key) for r in rows for m in metrics if r.ok and r.metric(m.key) is not None}


def condition_variants(rows: list[SweepRow], all_settings: dict[str, list[dict]], choice: Metric,
                       defined_anywhere: set[tuple[str, str]]) -> list[Variant]:
    """Every algorithm of `rows` once, and a method with a grid twice: at its default and at its
    best setting here by median of `choice` (the default only, labelled so, when it is the best)."""
    variants = []
    for algorithm in sorted_algorithms({r.algorithm for r in rows}):
        of_algorithm = [r for r in rows if r.algorithm == algorithm]
        settings = all_settings[algorithm]
        if len(settings) == 1:
            variants.append(Variant(algorithm, algorithm, of_algorithm, True))
            continue
        default = default_setting(algorithm, settings)
        by_setting = collections.defaultdict(list)
        for r in of_algorithm:
            by_setting[setting_key(r.parameters)].append(r)
        sign = -1 if choice.higher_is_better else 1

        # Settings are compared on the inputs they all ran (if any): a grid may run on a subset of
        # the inputs its default runs on, and an easier subset would flatter it.
        shared = shared_inputs(by_setting.values())

        def median_of(key: str) -> float:
            on_shared = [r for r in by_setting[key] if r.input_key in shared] if shared else by_setting[key]
            candidate = Variant("", algorithm, on_shared, False).values(choice, defined_anywhere)
            return sign * quartiles(list(candidate.values()))[0] if candidate else math.inf

        default_key = setting_key(default)
        # A tie keeps the default, then the setting written first.
        order = sorted((setting_key(s) for s in settings if setting_key(s) in by_setting),
                       key=lambda key: key != default_key)
        best = min(order, key=median_of)
        count = len(order)
        if count == 1:  # the grid ran on other inputs only
            changed = changed_values_text(json.loads(best), default)
            label = f"{algorithm} ({changed + '; ' if changed else 'default; '}no grid here)"
            variants.append(Variant(label, algorithm, by_setting[best], best == default_key))
            continue
        if best == default_key:
            variants.append(Variant(f"{algorithm} (default, best of {count} settings)", algorithm,
                                    by_setting[default_key], True))
            continue
        if default_key in by_setting:
            variants.append(Variant(f"{algorithm} (default)", algorithm, by_setting[default_key], True))
        changed = changed_values_text(json.loads(best), default)
        variants.append(Variant(f"{algorithm} ({changed}; best of {count})", algorithm, by_setting[best], False))
    return variants


@dataclasses.dataclass
class SummaryLine:
    """One measure under one condition."""

    condition: str
    measure: str
    higher_is_better: bool
    runs_text: str
    best: str | None
    runner_up: str | None
    separated: bool
    verdict: str
    cells: dict[str, str]  # what the page shows for each method: value and spread
    comparison: Comparison | None = None
    default_on_same_inputs: dict[str, float] = dataclasses.field(default_factory=dict)  # per best-of-grid label
    figures: tuple[str, ...] = ()
    rule: str = ""


@dataclasses.dataclass
class ConditionSummary:
    name: str
    rule: str
    figures: tuple[str, ...]
    runs: int
    inputs: int
    lines: list[SummaryLine]
    agreement: str
    variants: list[Variant]


def _statistics_cell(comparison: Comparison, label: str) -> str:
    s = comparison.statistics[label]
    m = comparison.metric
    failed = f", {s.failed} failed" if s.failed else ""
    subset = f" (on {s.runs} of the {comparison.inputs} inputs)" if s.runs < comparison.inputs else ""
    return (f"{m.format(s.median)} [{m.format(s.lower_quartile)}, {m.format(s.upper_quartile)}]; "
            f"{100 * s.within_tolerance:.0f}% of {s.runs} runs{failed} within {m.tolerance_text()} of the best{subset}")


def beats(comparison: Comparison, a: str, b: str) -> bool:
    """a is better than b on at least SEPARATING_MARGIN more of their shared inputs than worse."""
    h = comparison.pairs[(a, b)]
    return h.wins - h.losses >= SEPARATING_MARGIN


def ranked(comparison: Comparison) -> list[str]:
    """The methods scored on RANKED_COVERAGE of the inputs or more, by rank (all if none is):
    medians over different inputs do not compare, so a method scored on few of them (a grid run on
    a subset, a metric undefined on the hard inputs) is shown but not ranked."""
    covering = [a for a in comparison.ranking if comparison.statistics[a].runs >= RANKED_COVERAGE * comparison.inputs]
    return covering or comparison.ranking


def verdict(comparison: Comparison, algorithm_of: dict[str, str]) -> tuple[str | None, str | None, bool, str]:
    """(best, runner-up, separated, why): among the methods scored on RANKED_COVERAGE of the inputs
    or more (all if none is), the best by median (then by share near the best) of those no other
    beats head to head (by SEPARATING_MARGIN; all if each is beaten), the runner-up the next method
    of another algorithm by median. The best is separated when it beats every ranked method of
    another algorithm; otherwise the methods it does not beat tie with it, and the first method
    outside that group is named."""
    if not comparison.ranking:
        return None, None, False, "no method reports it here"
    ranking = ranked(comparison)
    # A method another one beats head to head cannot be best, whatever its median.
    unbeaten = [a for a in ranking
                if not any(beats(comparison, b, a) for b in ranking if algorithm_of[b] != algorithm_of[a])]
    best = (unbeaten or ranking)[0]
    others = [label for label in ranking if algorithm_of[label] != algorithm_of[best]]

    def record(other: str) -> str:
        h: HeadToHead = comparison.pairs[(best, other)]
        return f"better on {h.wins}, worse on {h.losses} of {h.shared} shared inputs"

    top = comparison.ranking[0]
    if top == best:
        passed_over = ""
    elif top not in ranking:
        passed_over = (f"; {top} has a better median on only {comparison.statistics[top].runs} of the "
                       f"{comparison.inputs} inputs, too few to rank (at least {100 * RANKED_COVERAGE:g}%)")
    else:
        passed_over = f"; {top} has the better median but is not best: {best} is {record(top)}"
    if not others:
        alone = all(algorithm_of[label] == algorithm_of[best] for label in comparison.ranking)
        return best, None, False, (f"not separated: only {algorithm_of[best]} "
                                   f"{'reports it' if alone else 'is ranked'} here{passed_over}")
    runner_up = others[0]
    tied = [label for label in others if not beats(comparison, best, label)]
    if not tied:
        return best, runner_up, True, (f"{best} is better by more than {comparison.metric.tolerance_text()} than each "
                                       f"other method on at least {SEPARATING_MARGIN} more shared inputs than it is "
                                       f"worse; against {runner_up}: {record(runner_up)}{passed_over}")
    beaten = [label for label in others if label not in tied]
    listed = ", ".join(tied[:4]) + (f" and {len(tied) - 4} more" if len(tied) > 4 else "")
    why = (f"not separated: {best} is not better than {listed} on {SEPARATING_MARGIN} more shared inputs than "
           f"worse (against {tied[0]}: {record(tied[0])})")
    if beaten:
        why += f"; this group is ahead of {beaten[0]} ({best} {record(beaten[0])})"
    return best, runner_up, False, why + passed_over


def _runs_text(comparison: Comparison) -> str:
    runs = sum(s.runs for s in comparison.statistics.values())
    failed = sum(s.failed for s in comparison.statistics.values())
    return (f"{runs} runs of {len(comparison.statistics)} methods on {comparison.inputs} inputs"
            + (f" ({failed} failed)" if failed else ""))


def _accuracy_line(condition: str, metric: Metric, variants: list[Variant], defined_anywhere) -> SummaryLine | None:
    values = {v.label: v.values(metric, defined_anywhere) for v in variants}
    values = {label: by_input for label, by_input in values.items() if by_input}
    if not values:
        return None
    comparison = compare(values, metric)
    algorithm_of = {v.label: v.algorithm for v in variants}
    best, runner_up, separated, why = verdict(comparison, algorithm_of)
    cells = {label: _statistics_cell(comparison, label) for label in values}
    # A grid's best setting may run on fewer inputs than its default: its default's median on the
    # same inputs says what the setting gains there.
    default_here = {}
    for v in variants:
        default = next((d for d in variants if d.algorithm == v.algorithm and d.default and d is not v), None)
        if not v.default and v.label in values and default is not None and default.label in values:
            same = [values[default.label][key] for key in values[v.label] if key in values[default.label]]
            if same:
                default_here[v.label] = quartiles(same)[0]
                cells[v.label] += (f"; the default on the same {len(same)} inputs: median "
                                   f"{metric.format(default_here[v.label])}")
    return SummaryLine(condition, metric.name, metric.higher_is_better, _runs_text(comparison), best, runner_up,
                       separated, why, cells, comparison, default_on_same_inputs=default_here)


def leading_algorithms(line: SummaryLine, algorithm_of: dict[str, str]) -> list[str]:
    """The best method's algorithm and those of the ranked methods it does not beat head to head."""
    others = [label for label in ranked(line.comparison) if algorithm_of[label] != algorithm_of[line.best]]
    tied = [algorithm_of[label] for label in others if not beats(line.comparison, line.best, label)]
    return list(dict.fromkeys([algorithm_of[line.best]] + tied))


def agreement_text(lines: list[SummaryLine], algorithm_of: dict[str, str]) -> str:
    """Whether the metrics lead to the same method: they agree when some algorithm leads on every
    metric (is best, or not beaten by the best), and disagree otherwise."""
    scored = [line for line in lines if line.best is not None]
    if not scored:
        return "No metric has a value here."
    leaders = {line.measure: leading_algorithms(line, algorithm_of) for line in scored}
    common = [a for a in leaders[scored[0].measure] if all(a in group for group in leaders.values())]
    separated = [line.measure for line in scored if line.separated]
    how = (f"separated on {', '.join(separated)}" if separated else "no metric separates a single method")
    if common:
        names = ", ".join(common[:4]) + (f" and {len(common) - 4} more" if len(common) > 4 else "")
        verb = "leads" if len(common) == 1 else "lead"
        return f"The metrics agree: {names} {verb} on every metric ({how})."

    def group_text(group: list[str]) -> str:
        return group[0] if len(group) == 1 else ", ".join(group[:3]) + (" ..." if len(group) > 3 else "") + " (tie)"

    listed = "; ".join(f"{measure}: {group_text(group)}" for measure, group in leaders.items())
    return f"The metrics disagree: {listed}."


def setting_choice_metric(rows: list[SweepRow]) -> Metric | None:
    """The first of SETTING_CHOICE_METRICS some finished run of `rows` defines."""
    return next((m for key in SETTING_CHOICE_METRICS for m in ACCURACY_METRICS
                 if m.key == key and any(r.ok and r.metric(key) is not None for r in rows)), None)


def condition_summaries(rows: list[SweepRow]) -> list[ConditionSummary]:
    all_settings = settings_by_algorithm(rows)
    defined_anywhere = defined_metrics(rows, ACCURACY_METRICS)
    summaries = []
    by_condition = condition_rows(rows)
    for condition in CONDITIONS:
        chosen = by_condition.get(condition.name)
        if not chosen:
            continue
        choice = setting_choice_metric(chosen)
        if choice is None:
            continue
        variants = condition_variants(chosen, all_settings, choice, defined_anywhere)
        lines = []
        for metric in ACCURACY_METRICS:
            line = _accuracy_line(condition.name, metric, variants, defined_anywhere)
            if line is not None:
                line.figures = (HEATMAP_FIGURE,) + condition.figures
                line.rule = condition.rule
                lines.append(line)
        algorithm_of = {v.label: v.algorithm for v in variants}
        summaries.append(ConditionSummary(condition.name, condition.rule, (HEATMAP_FIGURE,) + condition.figures,
                                          len(chosen), len({r.input_key for r in chosen}), lines,
                                          agreement_text(lines, algorithm_of), variants))
    return summaries


def medial_axis_line(rows: list[SweepRow]) -> SummaryLine | None:
    defined_anywhere = defined_metrics(rows, [MEDIAL_AXIS_METRIC])
    chosen = [r for r in rows if any(r.algorithm == a for a, _ in defined_anywhere)]
    if not chosen:
        return None
    variants = condition_variants(chosen, settings_by_algorithm(rows), MEDIAL_AXIS_METRIC, defined_anywhere)
    line = _accuracy_line("Medial axis (every run of a method that draws one)", MEDIAL_AXIS_METRIC, variants,
                          defined_anywhere)
    if line is not None:
        line.rule = "every run of the methods that produce an interior medial axis, on closed true curves"
        line.figures = (DISTRIBUTIONS_FIGURE, "gallery")
    return line


@dataclasses.dataclass
class DominantPointStatistics:
    compression_ratio: tuple[float, float, float]  # median, lower and upper quartile
    integral_square_error: tuple[float, float, float]
    runs: int

    @property
    def figure_of_merit(self) -> float:
        """FOM from the medians: median CR / median ISE (infinite for a median ISE of 0)."""
        median_ise = self.integral_square_error[0]
        return math.inf if median_ise == 0 else self.compression_ratio[0] / median_ise


def dominant_point_statistics(rows: list[SweepRow]) -> dict[str, DominantPointStatistics]:
    """Per algorithm, over its finished runs that define both: CR and ISE quartiles."""
    pairs = collections.defaultdict(list)
    for r in rows:
        cr, ise = r.metric("compression_ratio"), r.metric("integral_square_error")
        if r.ok and cr is not None and ise is not None:
            pairs[r.algorithm].append((cr, ise))
    return {algorithm: DominantPointStatistics(quartiles([cr for cr, _ in found]), quartiles([i for _, i in found]),
                                               len(found))
            for algorithm, found in pairs.items()}


def dominant_points_line(rows: list[SweepRow]) -> SummaryLine | None:
    """FOM from the medians of CR and ISE, not the mean of per-run FOMs: ISE is near 0 on some
    runs, so one run's CR / ISE can outweigh all the others in a mean."""
    statistics = dominant_point_statistics(rows)
    if not statistics:
        return None
    ranking = sorted(statistics, key=lambda a: (-statistics[a].figure_of_merit, a))
    by_algorithm = collections.defaultdict(dict)
    for r in rows:
        if r.algorithm in statistics:
            v = run_value(r, FIGURE_OF_MERIT)
            if v is not None:
                by_algorithm[r.algorithm][r.input_key] = v
    comparison = compare(dict(by_algorithm), FIGURE_OF_MERIT)
    comparison.ranking = ranking
    best, runner_up, separated, why = verdict(comparison, {a: a for a in ranking})
    cells = {}
    for algorithm, s in statistics.items():
        cr, ise = s.compression_ratio, s.integral_square_error
        of_algorithm = sum(1 for r in rows if r.algorithm == algorithm)
        cells[algorithm] = (f"FOM {s.figure_of_merit:.3g} = CR {cr[0]:.3g} [{cr[1]:.3g}, {cr[2]:.3g}] / "
                            f"ISE {ise[0]:.3g} [{ise[1]:.3g}, {ise[2]:.3g}], medians [IQR] over the {s.runs} of "
                            f"its {of_algorithm} runs that define both")
    line = SummaryLine("Dominant points (every run of a method that finds them)",
                       "FOM from the medians: median CR / median ISE", True, _runs_text(comparison), best, runner_up,
                       separated, why + " (head to head on each run's FOM)", cells, comparison)
    line.figures = (DISTRIBUTIONS_FIGURE, "gallery")
    line.rule = ("every run of the methods that produce dominant points; FOM is taken from the medians of CR and ISE "
                 "because ISE is near 0 on some runs, where one run's CR / ISE would decide a mean of ratios")
    return line


def speed_lines(suite: ScalingSuite) -> list[SummaryLine]:
    lines = []
    for input_name in suite.inputs():
        runs = [r for r in suite.runs if r.input == input_name and r.skip_reason is None and r.algorithm != DELAUNAY]
        if not runs:
            continue
        largest = max(r.n for r in runs)
        at_largest = [r for r in runs if r.n == largest]
        for condition, measure, value, unit, fmt in [
                (f"Speed, {input_name} curve, n = {largest:,}", "time / bare Delaunay time (benchmark)",
                 lambda r: r.times_delaunay, "x", "{:.2f}x"),
                (f"Memory, {input_name} curve, n = {largest:,}", "peak MiB of the reconstruction (benchmark)",
                 lambda r: r.reconstruction_mib, "MiB", "{:.1f}")]:
            by_algorithm = collections.defaultdict(list)
            for r in at_largest:
                if value(r) is not None:
                    by_algorithm[r.algorithm].append(value(r))
            if not by_algorithm:
                continue
            medians = {a: float(np.median(v)) for a, v in by_algorithm.items()}
            ranking = sorted(medians, key=lambda a: (medians[a], a))
            best = ranking[0]
            runner_up = ranking[1] if len(ranking) > 1 else None
            repetitions = max(len(v) for v in by_algorithm.values())
            figure = "scaling_runtime" if unit == "x" else "scaling_memory"
            # Separated when every repetition of the best is below every repetition of the runner-up.
            if runner_up is None:
                separated, why = False, "not separated: only one algorithm was timed"
            elif repetitions < 2:
                separated, why = False, (f"not separated: one measured run each ({best} {fmt.format(medians[best])}, "
                                         f"{runner_up} {fmt.format(medians[runner_up])}); --benchmark_repetitions "
                                         "gives a spread")
            else:
                separated = max(by_algorithm[best]) < min(by_algorithm[runner_up])
                why = (f"{best} {fmt.format(medians[best])} against {runner_up} {fmt.format(medians[runner_up])}; "
                       f"{'every' if separated else 'not every'} repetition of {best} below every one of "
                       f"{runner_up}")
                why = why if separated else "not separated: " + why
            runs_text = f"{len(medians)} algorithms, " + (
                f"median of {repetitions} repetitions each" if repetitions > 1 else "one measured run each")
            lines.append(SummaryLine(condition, measure, False, runs_text, best, runner_up, separated, why,
                                     {a: fmt.format(v) for a, v in medians.items()}, figures=(figure,),
                                     rule=f"the scaling benchmark's {input_name} input at its largest n"))
    return lines
