"""Which parameter setting each sweep row ran, and how the report names it.

A row's "parameters" are resolved in full (defaults included), so a run is at its algorithm's
default when its parameters equal the catalogue's defaults (`curvebench list --json`). A method
run with a parameter grid is shown twice in the summary: at its default, and at the setting of
the grid that is best under the condition, labelled with the values that won, e.g.
"alpha-shape (alpha=0.02; best of 4)" (reports/summary_table.py).
"""
from __future__ import annotations

import collections
import json

from reports.sweep_results import SweepRow

_catalogue_defaults: dict[str, dict] = {}


def use_catalogue_defaults(catalogue: list[dict]) -> None:
    """Remembers every algorithm's default parameters from the catalogue."""
    _catalogue_defaults.clear()
    for entry in catalogue:
        _catalogue_defaults[entry["name"]] = {p["name"]: p["default"] for p in entry.get("parameters", [])}


def setting_key(parameters: dict) -> str:
    """The same text for the same values, whether a number is written 2 or 2.0."""
    return json.dumps({name: float(value) if isinstance(value, int) and not isinstance(value, bool) else value
                       for name, value in parameters.items()}, sort_keys=True)


def settings_by_algorithm(rows: list[SweepRow]) -> dict[str, list[dict]]:
    """Every algorithm's distinct parameter settings, in the order the rows first show them."""
    settings = collections.defaultdict(dict)
    for r in rows:
        settings[r.algorithm].setdefault(setting_key(r.parameters), r.parameters)
    return {algorithm: list(found.values()) for algorithm, found in settings.items()}


def default_setting(algorithm: str, settings: list[dict]) -> dict:
    """The default setting of `algorithm`, every parameter resolved: the only setting run, or the
    catalogue's defaults (which a grid need not contain). Raises ValueError when several settings
    were run and no catalogue says which is the default."""
    if len(settings) == 1:
        return settings[0]
    defaults = _catalogue_defaults.get(algorithm)
    if defaults is None:
        raise ValueError(f"the results hold {len(settings)} parameter settings of {algorithm}: give --catalogue "
                         "(curvebench list --json) so that the report knows its default")
    return {**settings[0], **defaults}


def default_rows(rows: list[SweepRow]) -> list[SweepRow]:
    """The rows of every algorithm at its default setting (what the figures of one line per
    algorithm draw); an algorithm whose grid leaves out its default has none."""
    defaults = {algorithm: setting_key(default_setting(algorithm, settings))
                for algorithm, settings in settings_by_algorithm(rows).items()}
    return [r for r in rows if setting_key(r.parameters) == defaults[r.algorithm]]


def shared_inputs(groups) -> set[str]:
    """The inputs every group of rows (one per setting of an algorithm) ran."""
    keys = [{r.input_key for r in group} for group in groups]
    return set.intersection(*keys) if keys else set()


def changed_values_text(setting: dict, default: dict) -> str:
    """"alpha=0.02": the values in which a setting differs from the default."""
    return ", ".join(f"{name}={_value_text(value)}" for name, value in setting.items() if default.get(name) != value)


def _value_text(value) -> str:
    if isinstance(value, bool):
        return str(value).lower()
    return f"{value:g}" if isinstance(value, float) else str(value)
