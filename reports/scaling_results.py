"""Reads the scaling benchmark's JSON (curvebench_benchmark --benchmark_out_format=json).

Benchmarks are named <algorithm>/<input>/n:<n>[/...]; "delaunay" is the bare CGAL Delaunay
construction, the floor every algorithm is compared with. See harness/bench/scaling_benchmark.cpp
for the counters.
"""
from __future__ import annotations

import dataclasses
import json
import pathlib
import re

_NAME = re.compile(r"^(?P<algorithm>[^/]+)/(?P<input>[^/]+)/n:(?P<n>\d+)(/|$)")
_SECONDS_PER_UNIT = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}

DELAUNAY = "delaunay"


@dataclasses.dataclass
class ScalingRun:
    algorithm: str
    input: str
    n: int
    seconds: float | None = None  # CPU seconds per reconstruction; None if skipped
    times_delaunay: float | None = None
    peak_mib: float | None = None
    input_mib: float | None = None  # the measuring process before the reconstruction
    skip_reason: str | None = None

    @property
    def reconstruction_mib(self) -> float | None:
        """Peak memory above the process's baseline and the points: what the run itself needs."""
        if self.peak_mib is None or self.input_mib is None:
            return None
        return self.peak_mib - self.input_mib


@dataclasses.dataclass
class ScalingSuite:
    runs: list[ScalingRun]
    context: dict
    source: pathlib.Path

    def inputs(self) -> list[str]:
        return sorted({run.input for run in self.runs}, key=lambda name: (name != "smooth", name))

    def algorithms(self) -> list[str]:
        return sorted({run.algorithm for run in self.runs if run.algorithm != DELAUNAY})

    def sizes(self) -> list[int]:
        return sorted({run.n for run in self.runs})


def read_scaling_suite(path: pathlib.Path) -> ScalingSuite:
    with open(path) as f:
        data = json.load(f)
    runs = []
    for row in data.get("benchmarks", []):
        if row.get("run_type", "iteration") != "iteration":
            continue  # aggregates of repetitions repeat what the iterations say
        match = _NAME.match(row["name"])
        if not match:
            raise ValueError(f"{path}: benchmark name {row['name']!r} is not <algorithm>/<input>/n:<n>")
        run = ScalingRun(match["algorithm"], match["input"], int(match["n"]))
        if row.get("error_occurred"):
            run.skip_reason = row.get("error_message", "failed")
        else:
            # With manual timing "real_time" holds the time the benchmark measured: thread CPU time.
            run.seconds = row["real_time"] * _SECONDS_PER_UNIT[row.get("time_unit", "ns")]
            run.times_delaunay = row.get("x_delaunay")
            run.peak_mib = row.get("peak_MiB")
            run.input_mib = row.get("input_MiB")
        runs.append(run)
    if not runs:
        raise ValueError(f"{path}: no benchmark rows")
    return ScalingSuite(runs, data.get("context", {}), pathlib.Path(path))
