"""The conditions of the summary ("which method is best under which condition"), each derived from
a sweep row's generator settings alone, so that the same rule holds for every sweep:

  sparse, dense   clean runs (no noise, no outliers) of one smooth closed curve; per shape, its
                  sampling levels (epsilon or point count) ordered from sparse to dense: the
                  sparsest third (at least one level) is sparse, the densest third dense
  noise           noise > 0, no outliers, any shape
  outliers        outliers > 0, any shape
  sharp corners   clean runs of the polygonal families (star, square, l-shape, horned)
  several curves  clean runs of two or more disjoint true curves (not nested, not outlines)
  nested curves   clean runs of the family `nested`
  open curves     clean runs of the open families (arc, ellipse-arc, spiral, open-random)
  real outlines   clean runs of imported outlines (family `outline`)

The clean conditions leave noise and outliers out, so that each isolates one difficulty; a row
falls under at most one condition (a clean smooth curve at a middle density under none).
"""
from __future__ import annotations

import collections
import dataclasses
from typing import Callable

from reports.sweep_results import SweepRow

POLYGON_FAMILIES = {"star", "square", "l-shape", "horned"}
OPEN_FAMILIES = {"arc", "ellipse-arc", "spiral", "open-random"}
NESTED_FAMILIES = {"nested"}
OUTLINE_FAMILY = "outline"


@dataclasses.dataclass(frozen=True)
class Condition:
    name: str
    rule: str  # the rule, as the page states it
    figures: tuple[str, ...]  # stems of the figures that show it beside metrics_by_condition


def _clean(r: SweepRow) -> bool:
    return r.noise == 0 and r.outliers == 0


def _one_smooth_closed_curve(r: SweepRow) -> bool:
    return (_clean(r) and r.smooth and r.family not in OPEN_FAMILIES | NESTED_FAMILIES
            and r.true_curves == 1)


def _density_split(rows: list[SweepRow]) -> tuple[set[int], set[int]]:
    """ids of the rows in the sparsest and in the densest third of their shape's sampling levels."""
    levels = collections.defaultdict(set)
    for r in rows:
        if _one_smooth_closed_curve(r):
            levels[r.shape].add(r.sampling_level)
    sparse, dense = set(), set()
    for r in rows:
        shape_levels = sorted(levels.get(r.shape, ())) if _one_smooth_closed_curve(r) else []
        if len(shape_levels) < 2:
            continue
        third = max(1, len(shape_levels) // 3)
        if r.sampling_level in shape_levels[:third]:
            sparse.add(id(r))
        if r.sampling_level in shape_levels[-third:]:
            dense.add(id(r))
    return sparse, dense


CONDITIONS = [
    Condition("Sparse sampling", "clean runs of one smooth closed curve, the sparsest third of each shape's sampling "
              "levels", ("l2_vs_density",)),
    Condition("Dense sampling", "clean runs of one smooth closed curve, the densest third of each shape's sampling "
              "levels", ("l2_vs_density",)),
    Condition("Noise", "noise > 0 and no outliers, every shape and noise level", ("robustness",)),
    Condition("Outliers", "outliers > 0, every shape and share", ("robustness",)),
    Condition("Sharp corners", "clean runs of the polygonal families (" + ", ".join(sorted(POLYGON_FAMILIES)) + ")",
              ()),
    Condition("Several curves", "clean runs of two or more disjoint true curves", ("success_vs_epsilon",)),
    Condition("Nested curves", "clean runs of the family nested (a curve inside another)", ()),
    Condition("Open curves", "clean runs of the open families (" + ", ".join(sorted(OPEN_FAMILIES)) + ")", ()),
    Condition("Real outlines", "clean runs of imported outlines (family outline)", ("l2_vs_density",)),
]


def condition_rows(rows: list[SweepRow]) -> dict[str, list[SweepRow]]:
    """The rows of every condition that holds at least one, in the order of CONDITIONS."""
    sparse, dense = _density_split(rows)
    rules: dict[str, Callable[[SweepRow], bool]] = {
        "Sparse sampling": lambda r: id(r) in sparse,
        "Dense sampling": lambda r: id(r) in dense,
        "Noise": lambda r: r.noise > 0 and r.outliers == 0,
        "Outliers": lambda r: r.outliers > 0,
        "Sharp corners": lambda r: _clean(r) and r.family in POLYGON_FAMILIES,
        "Several curves": lambda r: (_clean(r) and (r.true_curves or 0) > 1 and r.family not in NESTED_FAMILIES
                                     and r.family != OUTLINE_FAMILY),
        "Nested curves": lambda r: _clean(r) and r.family in NESTED_FAMILIES,
        "Open curves": lambda r: _clean(r) and r.family in OPEN_FAMILIES,
        "Real outlines": lambda r: _clean(r) and r.family == OUTLINE_FAMILY,
    }
    chosen = {}
    for condition in CONDITIONS:
        matching = [r for r in rows if rules[condition.name](r)]
        if matching:
            chosen[condition.name] = matching
    return chosen
