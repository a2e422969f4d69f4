"""Reads the rows of `curvebench sweep` (JSON lines; layout in harness/sweep/run_sweep.h) into
flat records the figures group by:

  {"algorithm": ..., "parameters": {...}, "input": {generator settings, "seed"},
   "input_points": 230, "oracle_l2_error": 0.0003, "status": "ok" | "error" | "timeout" | "crash",
   "message": ..., "metrics": {...}, "timing_ms": {..., "total": ...}, "peak_memory_kb": ...}

Generator settings a config leaves out take `curvebench generate`'s defaults (GENERATE_DEFAULTS).
Only this module knows the row layout; the figures see SweepRow.
"""
from __future__ import annotations

import dataclasses
import json
import math
import pathlib

# Families of `curvebench generate` whose curves have sharp corners (the guarantees of the
# epsilon-sampling theory are for smooth curves; imported outlines have corners too).
SHARP_CORNER_FAMILIES = {"star", "square", "l-shape", "horned", "outline"}

# `curvebench generate` defaults of the settings the report groups by.
GENERATE_DEFAULTS = {"family": "random", "sampler": "epsilon", "epsilon": 0.2, "count": 200, "noise": 0.0,
                     "noise_scale": "lfs", "noise_model": "gaussian", "outliers": 0.0, "seed": 1}


@dataclasses.dataclass
class SweepRow:
    algorithm: str
    parameters: dict
    settings: dict  # the input's generator settings as the row states them
    family: str
    shape: str  # family and shape parameters or outline file: "rose", "rose k=3", "outline glyph_0041"
    sampler: str  # "epsilon", "uniform" or "random"
    epsilon: float | None  # only for the epsilon-sampler
    count: int | None  # only for the uniform and random samplers
    noise: float
    noise_scale: str  # "lfs" or "diagonal"
    noise_model: str  # "gaussian" (noise = standard deviation) or "uniform" (noise = half-width of the band)
    outliers: float  # outliers as a fraction of the curve samples
    seed: int
    status: str  # ok, error, timeout or crash
    message: str
    metrics: dict
    oracle_l2_error: float | None  # the samples joined in their true order (per input)
    input_points: int | None
    seconds: float | None
    peak_mib: float | None
    true_curves: int | None = None  # from any finished run of the same input

    @property
    def ok(self) -> bool:
        return self.status == "ok"

    @property
    def input_key(self) -> str:
        """The same text for every run of the same input (generator settings and seed)."""
        return json.dumps(self.settings, sort_keys=True)

    @property
    def smooth(self) -> bool:
        return self.family not in SHARP_CORNER_FAMILIES

    @property
    def sampling_level(self) -> float:
        """Orders the samplings of one shape from sparse to dense: the point count of the uniform
        and random samplers, minus epsilon for the epsilon-sampler."""
        return float(self.count) if self.epsilon is None else -self.epsilon

    def metric(self, name: str) -> float | None:
        """A metric as a number (booleans as 0/1); None where absent, null or not a number."""
        value = self.metrics.get(name)
        if isinstance(value, bool):
            return float(value)
        if isinstance(value, (int, float)) and math.isfinite(value):
            return float(value)
        return None


def shape_label(settings: dict) -> str:
    family = str(settings.get("family", GENERATE_DEFAULTS["family"]))
    shape = settings.get("shape") or {}
    outline = [pathlib.Path(str(settings["input"])).stem] if "input" in settings else []
    return " ".join([family] + outline + [f"{name}={value}" for name, value in shape.items()])


def row_from_json(row: dict) -> SweepRow:
    settings = row["input"]
    setting = {**GENERATE_DEFAULTS, **settings}
    total_ms = (row.get("timing_ms") or {}).get("total")
    return SweepRow(
        algorithm=row["algorithm"],
        parameters=row.get("parameters", {}),
        settings=settings,
        family=str(setting["family"]),
        shape=shape_label(settings),
        sampler=str(setting["sampler"]),
        epsilon=float(setting["epsilon"]) if setting["sampler"] == "epsilon" else None,
        count=int(setting["count"]) if setting["sampler"] != "epsilon" else None,
        noise=float(setting["noise"]),
        noise_scale=str(setting["noise_scale"]),
        noise_model=str(setting["noise_model"]),
        outliers=float(setting["outliers"]),
        seed=int(setting["seed"]),
        status=row["status"],
        message=row.get("message", ""),
        metrics=row.get("metrics") or {},
        oracle_l2_error=row.get("oracle_l2_error"),
        input_points=row.get("input_points"),
        seconds=None if total_ms is None else total_ms / 1000,
        peak_mib=None if row.get("peak_memory_kb") is None else row["peak_memory_kb"] / 1024,
    )


def read_sweep_rows(path: pathlib.Path) -> list[SweepRow]:
    rows = []
    with open(path) as f:
        for number, line in enumerate(f, start=1):
            if not line.strip():
                continue
            try:
                rows.append(row_from_json(json.loads(line)))
            except (ValueError, KeyError, TypeError) as e:
                raise ValueError(f"{path}:{number}: not a sweep row: {e!r}") from None
    true_curves = {}
    for r in rows:
        if r.metric("true_curves") is not None:
            true_curves[r.input_key] = int(r.metric("true_curves"))
    for r in rows:
        r.true_curves = true_curves.get(r.input_key)
    return rows
