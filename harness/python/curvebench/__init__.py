"""curvebench on numpy arrays: the same C++ library as the `curvebench` command line.

    import curvebench
    points, truth = curvebench.generate(family="rose", epsilon=0.3, seed=2)
    r = curvebench.reconstruct(points, algorithm="labeling")
    r.edges, r.medial_axis.vertices, r.dominant_points, r.timing_ms
    curvebench.evaluate(truth, r)["metrics"]["l2_error"]

harness/python/README.md documents every function. Errors of the library (bad points, an
unknown algorithm or parameter, a malformed file) raise ValueError with the one-line
message the command line prints after its `curvebench: error:` (without the file name that
the command line puts first).
"""
from __future__ import annotations

import json
import os
from typing import Any, NamedTuple, Optional, Union

import numpy as np
import numpy.typing as npt

from . import _curvebench
from ._curvebench import GroundTruth, MedialAxis, Reconstruction

__all__ = [
    "GeneratedInput",
    "GroundTruth",
    "MedialAxis",
    "Reconstruction",
    "algorithms",
    "evaluate",
    "generate",
    "read_ground_truth",
    "read_points",
    "read_reconstruction",
    "reconstruct",
    "write_generated",
    "write_points",
    "write_reconstruction",
]

PathLike = Union[str, "os.PathLike[str]"]
Value = Union[bool, int, float, str]


class GeneratedInput(NamedTuple):
    """What generate() returns: the (n, 2) float64 points, in order along the curves, and their ground truth."""

    points: npt.NDArray[np.float64]
    truth: GroundTruth


def algorithms() -> list[dict[str, Any]]:
    """The catalogue, as `curvebench list --json` prints it: for each algorithm its name,
    citation, outputs, collinear_input and typed parameters (name, type, default, range or
    choices, allowed, description)."""
    return json.loads(_curvebench.catalogue_json())


def _points_array(points: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """`points` as a C-contiguous float64 (n, 2) array: the same object when it already is
    one (then the library reads it in place), else a converted copy."""
    try:
        array = np.ascontiguousarray(points, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise ValueError(f"points must be an (n, 2) array of numbers: {e}") from None
    if array.ndim != 2 or array.shape[1] != 2:
        raise ValueError(f"points must be an (n, 2) array of numbers, not of shape {array.shape}")
    return array


def _plain(value: Any) -> Any:
    """A numpy scalar as the Python number JSON takes; anything else is refused."""
    if isinstance(value, np.generic):
        return value.item()
    raise ValueError(f"{value!r} is not a number, a boolean or a name")


def _json(values: dict[str, Any]) -> str:
    return json.dumps(values, default=_plain)


def reconstruct(points: npt.ArrayLike, algorithm: str = "labeling", **parameters: Value) -> Reconstruction:
    """Reconstructs the curve (and medial axis, dominant points: what the algorithm makes)
    from (n, 2) points: a numpy array (C-contiguous float64 is read in place, anything else is
    converted), a list of pairs, ... `parameters` are the algorithm's (curvebench.algorithms()),
    each converted to its declared type and checked against its range; missing ones take their
    defaults. The GIL is released while the algorithm runs.

    The result: `edges` (m, 2) int32 (input indices, or indices into `vertices` for a method
    that places vertices of its own), `positions` (denoising methods), `vertices`,
    `medial_axis` (`vertices`, `radii`, `edges`), `dominant_points`, `timing_ms`; an output
    the algorithm does not make is None."""
    return _curvebench.reconstruct(_points_array(points), algorithm, _json(parameters))


def generate(
    family: Optional[str] = None,
    *,
    shape: Optional[dict[str, float]] = None,
    sampler: Optional[str] = None,
    epsilon: Optional[float] = None,
    min_step_fraction: Optional[float] = None,
    count: Optional[int] = None,
    noise: Optional[float] = None,
    noise_scale: Optional[str] = None,
    noise_model: Optional[str] = None,
    outliers: Optional[float] = None,
    seed: Optional[int] = None,
    dense: Optional[int] = None,
    input: Optional[PathLike] = None,
    input_format: Optional[str] = None,
) -> GeneratedInput:
    """A sampled curve and its ground truth, as `curvebench generate` makes them. The keywords
    are a sweep configuration's input keys (generators/generator_settings.h); one left out
    takes the generator's default (family "random", epsilon sampler at 0.2, no noise, seed 1).
    `shape` holds the family's shape parameters (`curvebench generate --help` lists them)."""
    settings = {name: value for name, value in locals().items() if value is not None}
    if "input" in settings:
        settings["input"] = os.fspath(settings["input"])
    points, truth = _curvebench.generate(_json(settings))
    return GeneratedInput(points, truth)


def evaluate(
    truth: GroundTruth, reconstruction: Reconstruction, points: Optional[npt.ArrayLike] = None
) -> dict[str, Any]:
    """Scores `reconstruction` against `truth` with the function `curvebench evaluate` calls:
    {"algorithm", "oracle_l2_error", "metrics"}, the values of its output (without the file
    names). `points` default to the reconstruction's own input points."""
    array = reconstruction.points if points is None else _points_array(points)
    scores = json.loads(_curvebench.evaluate(truth, reconstruction, array))
    return {"algorithm": reconstruction.algorithm, **scores}


def read_points(path: PathLike) -> npt.NDArray[np.float64]:
    """A points file (README "Points file") as an (n, 2) float64 array, in file order."""
    return _curvebench.read_points(os.fspath(path))


def write_points(path: PathLike, points: npt.ArrayLike, header: str = "") -> None:
    """Writes `x y` per line with round-trip precision, `header` as a leading `#` comment."""
    _curvebench.write_points(os.fspath(path), _points_array(points), header)


def read_reconstruction(path: PathLike, points: Optional[npt.ArrayLike] = None) -> Reconstruction:
    """A reconstruction JSON file; its indices refer to `points`, by default the points file
    the JSON names (relative to the working directory, as `curvebench evaluate` reads it)."""
    array = None if points is None else _points_array(points)
    return _curvebench.read_reconstruction(os.fspath(path), array)


def write_reconstruction(path: PathLike, reconstruction: Reconstruction, points_path: PathLike = "") -> None:
    """Writes the reconstruction JSON `curvebench reconstruct --output` writes; `points_path`
    is the points file it names as its input (write_points writes one)."""
    _curvebench.write_reconstruction(os.fspath(path), reconstruction, os.fspath(points_path))


def read_ground_truth(path: PathLike) -> GroundTruth:
    """A ground-truth JSON file from `curvebench generate --truth` or write_generated."""
    return _curvebench.read_ground_truth(os.fspath(path))


def write_generated(points: npt.ArrayLike, truth: GroundTruth, points_path: PathLike, truth_path: PathLike = "") -> None:
    """Writes the files `curvebench generate --points ... --truth ...` writes for the same
    settings: the points file headed by the settings record, and the ground-truth JSON."""
    _curvebench.write_generated(_points_array(points), truth, os.fspath(points_path), os.fspath(truth_path))
