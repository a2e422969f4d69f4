"""Statistics one run cannot dominate, for comparing methods on the same inputs.

In:  for each method (label), its value of one metric on each input it ran (input key -> value;
     a failed run, error, timeout or crash, is the worst value: +inf where lower is better,
     -inf where higher is better), and the metric's direction and tolerance.
Out: per method the median and interquartile range over its runs, the share of its runs within
     the tolerance of the best method on the same input, and for every pair of methods the
     number of shared inputs on which one is better than the other by more than the tolerance
     (wins), worse (losses) or neither (ties). Methods ranked by median, then by that share.
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np


@dataclasses.dataclass(frozen=True)
class Metric:
    key: str  # the metric's name in a sweep row
    name: str  # as the page says it
    higher_is_better: bool
    tolerance: float  # two values closer than this are a tie
    relative: bool = False  # tolerance as a fraction of the larger value instead of absolute
    value_format: str = "{:.3g}"

    @property
    def failure(self) -> float:
        return -math.inf if self.higher_is_better else math.inf

    def tolerance_text(self) -> str:
        return f"{100 * self.tolerance:g}%" if self.relative else f"{self.tolerance:g}"

    def better(self, a: float, b: float) -> bool:
        """a is better than b by more than the tolerance (a failure is worse than any value)."""
        if a == b:
            return False
        if math.isinf(a) or math.isinf(b):
            return a > b if self.higher_is_better else a < b
        margin = self.tolerance * max(abs(a), abs(b)) if self.relative else self.tolerance
        return a > b + margin if self.higher_is_better else a < b - margin

    def format(self, value: float) -> str:
        if math.isinf(value):
            return "failed"
        return self.value_format.format(value)


@dataclasses.dataclass
class MethodStatistics:
    runs: int
    failed: int
    median: float
    lower_quartile: float
    upper_quartile: float
    within_tolerance: float  # share of the runs within the tolerance of the best on the same input


@dataclasses.dataclass
class HeadToHead:
    wins: int
    losses: int
    ties: int

    @property
    def shared(self) -> int:
        return self.wins + self.losses + self.ties


@dataclasses.dataclass
class Comparison:
    metric: Metric
    statistics: dict[str, MethodStatistics]
    ranking: list[str]
    pairs: dict[tuple[str, str], HeadToHead]
    inputs: int  # distinct inputs any method ran


def quartiles(values: list[float]) -> tuple[float, float, float]:
    """25th, 50th and 75th percentiles (linear interpolation); infinite values (failures) take part
    as the worst values, so a median is 'failed' only when half the runs failed."""
    ordered = np.sort(np.asarray(values, dtype=float))
    result = []
    for q in (25, 50, 75):
        position = q / 100 * (len(ordered) - 1)
        low, high = ordered[math.floor(position)], ordered[math.ceil(position)]
        result.append(float(low) if low == high else float(low + (high - low) * (position - math.floor(position))))
    return result[1], result[0], result[2]


def compare(values: dict[str, dict[str, float]], metric: Metric) -> Comparison:
    inputs = set().union(*values.values()) if values else set()
    best = {}
    for key in inputs:
        finite = [v[key] for v in values.values() if key in v and math.isfinite(v[key])]
        if finite:
            best[key] = max(finite) if metric.higher_is_better else min(finite)
    statistics = {}
    for label, by_input in values.items():
        runs = list(by_input.values())
        median, low, high = quartiles(runs)
        within = sum(1 for key, v in by_input.items() if key in best and not metric.better(best[key], v))
        statistics[label] = MethodStatistics(len(runs), sum(1 for v in runs if math.isinf(v)), median, low, high,
                                             within / len(runs))
    sign = -1 if metric.higher_is_better else 1
    ranking = sorted(values, key=lambda label: (sign * statistics[label].median, -statistics[label].within_tolerance,
                                                label))
    pairs = {}
    for a in values:
        for b in values:
            if a == b:
                continue
            shared = values[a].keys() & values[b].keys()
            wins = sum(1 for key in shared if metric.better(values[a][key], values[b][key]))
            losses = sum(1 for key in shared if metric.better(values[b][key], values[a][key]))
            pairs[(a, b)] = HeadToHead(wins, losses, len(shared) - wins - losses)
    return Comparison(metric, statistics, ranking, pairs, len(inputs))
