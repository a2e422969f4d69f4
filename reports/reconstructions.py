"""Reads reconstruction JSON files (`curvebench reconstruct --output`, format in the README)
together with the points file each names, for the gallery."""
from __future__ import annotations

import dataclasses
import json
import pathlib
import re

import numpy as np

_SEPARATORS = re.compile(r"[ \t,]+")


def read_points_file(path: pathlib.Path) -> np.ndarray:
    """The README's points format: `x y` per line (spaces, tabs or commas; more columns ignored),
    `#` comments, blank lines skipped, LF, CRLF or lone CR line ends. Returns an (n, 2) array."""
    with open(path, newline="") as f:
        text = f.read()
    points = []
    for number, line in enumerate(text.replace("\r\n", "\n").replace("\r", "\n").split("\n"), start=1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        fields = _SEPARATORS.split(line)
        try:
            points.append((float(fields[0]), float(fields[1])))
        except (ValueError, IndexError):
            raise ValueError(f"{path}:{number}: not two numbers: {line!r}") from None
    return np.array(points, dtype=float).reshape(-1, 2)


@dataclasses.dataclass
class ReconstructionView:
    """One reconstruction with everything the gallery draws, in plain arrays."""

    algorithm: str
    shape: str  # the points file's name without extension
    points: np.ndarray
    status: str
    message: str = ""
    # What curve_edges index: the input points, their moved positions (a denoising method), or
    # the method's own vertices.
    curve_vertices: np.ndarray | None = None
    curve_edges: np.ndarray | None = None
    medial_axis_vertices: np.ndarray | None = None
    medial_axis_edges: np.ndarray | None = None
    dominant_points: np.ndarray | None = None  # indices into points
    svg: pathlib.Path | None = None  # `curvebench reconstruct --svg` beside the JSON (same name, .svg)


def _resolve_points_path(json_path: pathlib.Path, named: str) -> pathlib.Path:
    """A relative input path is taken beside the JSON file first, then from the working directory."""
    candidate = pathlib.Path(named)
    if candidate.is_absolute():
        return candidate
    beside = json_path.parent / candidate
    return beside if beside.exists() else candidate


def _edges(values) -> np.ndarray:
    return np.array(values, dtype=int).reshape(-1, 2)


def _view(path: pathlib.Path, data: dict) -> ReconstructionView:
    named_input = data.get("input", {}).get("path")
    if not named_input:
        raise ValueError(f"{path}: no input.path, so the points cannot be drawn")
    status = data.get("status", "ok")
    points_path = _resolve_points_path(path, named_input)
    if status != "ok" and not points_path.exists():
        points = np.zeros((0, 2))  # a failed run may name a file that was never readable
    else:
        points = read_points_file(points_path)
    svg = path.with_suffix(".svg")
    view = ReconstructionView(algorithm=data["algorithm"], shape=pathlib.Path(named_input).stem, points=points,
                              status=status, message=data.get("message", ""), svg=svg if svg.is_file() else None)
    if "curve" in data:
        curve = data["curve"]
        if "vertices" in curve:
            view.curve_vertices = np.array(curve["vertices"], dtype=float).reshape(-1, 2)
        elif "positions" in curve:
            view.curve_vertices = np.array(curve["positions"], dtype=float).reshape(-1, 2)
        else:
            view.curve_vertices = view.points
        view.curve_edges = _edges(curve.get("edges", []))
    if "medial_axis" in data:
        view.medial_axis_vertices = np.array(data["medial_axis"]["vertices"], dtype=float).reshape(-1, 2)
        view.medial_axis_edges = _edges(data["medial_axis"]["edges"])
    if "dominant_points" in data:
        view.dominant_points = np.array(data["dominant_points"], dtype=int)
    return view


def read_reconstructions(directory: pathlib.Path) -> list[ReconstructionView]:
    """Every *.json under `directory` that is a reconstruction (has an "algorithm" field)."""
    views = []
    for path in sorted(directory.rglob("*.json")):
        with open(path) as f:
            data = json.load(f)
        if isinstance(data, dict) and "algorithm" in data:
            views.append(_view(path, data))
    return views
