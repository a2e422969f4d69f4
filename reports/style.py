"""Shared look of every figure: one colour and marker per algorithm, the theoretical sampling
bounds, and writing a figure as PNG and SVG with its caption."""
from __future__ import annotations

import dataclasses
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)

# The paper's algorithm first, then the others in the catalogue's order (`curvebench list
# --json`, read by use_catalogue), else alphabetically. Colours and markers of the shipped
# algorithms are fixed, so a figure keeps its look as algorithms are added.
ALGORITHM_ORDER = ["labeling"]
_ALGORITHM_COLORS = {
    "labeling": "#d62728",
    "crust": "#1f77b4",
    "nn-crust": "#2ca02c",
    "local-crust": "#9467bd",
    "alpha-shape": "#8c564b",
    "optimal-transport": "#ff7f0e",
    "hnn-crust": "#17becf",
    "crawl": "#bcbd22",
    "peel": "#e377c2",
    "shape-hull": "#7f7f7f",
    "fitconnect": "#393b79",
    "stretchdenoise": "#637939",
}
_ALGORITHM_MARKERS = {"labeling": "o", "crust": "s", "nn-crust": "^", "local-crust": "D", "alpha-shape": "v",
                      "optimal-transport": "P", "hnn-crust": "X", "crawl": "*", "peel": "h", "shape-hull": "<",
                      "fitconnect": ">", "stretchdenoise": "p"}
_OTHER_COLORS = ["#843c39", "#7b4173", "#5254a3", "#8ca252", "#bd9e39", "#ad494a"]
_OTHER_MARKERS = ["d", "H", "8", "1", "2", "3"]

DELAUNAY_COLOR = "#222222"

# Largest epsilon of an epsilon-sample (Amenta-Bern-Eppstein) each method is proved (or, for
# the labeling, claimed) to reconstruct exactly.
THEORETICAL_EPSILON_BOUNDS = {"crust": 0.252, "nn-crust": 1 / 3, "labeling": 0.4}
BOUND_NOTES = {"crust": "proved", "nn-crust": "proved", "labeling": "claimed"}


def use_catalogue(catalogue: list[dict]) -> None:
    """Orders algorithms as the catalogue lists them (after the paper's)."""
    ALGORITHM_ORDER[1:] = [entry["name"] for entry in catalogue if entry["name"] != "labeling"]


def sorted_algorithms(names) -> list[str]:
    """The names in the shipped order, others after them alphabetically."""
    names = set(names)
    known = [name for name in ALGORITHM_ORDER if name in names]
    return known + sorted(names - set(known))


def stacked_line_width(index: int, count: int) -> float:
    """Algorithms often score the same: the index-th of `count` lines is drawn wider than the ones
    drawn after it, so that coinciding lines show as stripes instead of hiding each other."""
    return 1.3 + 2.2 * (count - 1 - index) / max(count - 1, 1)


def algorithm_color(name: str) -> str:
    if name in _ALGORITHM_COLORS:
        return _ALGORITHM_COLORS[name]
    return _OTHER_COLORS[sum(map(ord, name)) % len(_OTHER_COLORS)]


def algorithm_marker(name: str) -> str:
    if name in _ALGORITHM_MARKERS:
        return _ALGORITHM_MARKERS[name]
    return _OTHER_MARKERS[sum(map(ord, name)) % len(_OTHER_MARKERS)]


plt.rcParams.update({
    "figure.dpi": 110,
    "savefig.dpi": 130,
    "font.size": 10,
    "axes.titlesize": 11,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "legend.fontsize": 8.5,
    "legend.framealpha": 0.9,
    "svg.fonttype": "none",  # text stays text in the SVG
    "svg.hashsalt": "curvebench",  # the same figure gives the same SVG bytes
})


@dataclasses.dataclass
class SavedFigure:
    """A figure written as <stem>.png and <stem>.svg, with what the page says about it."""

    stem: str
    title: str
    caption: str
    extra_html: str = ""  # shown below the caption (the gallery's links to full-size pictures)


def save_figure(fig, out_dir: pathlib.Path, stem: str, title: str, caption: str) -> SavedFigure:
    fig.savefig(out_dir / f"{stem}.png", bbox_inches="tight")
    fig.savefig(out_dir / f"{stem}.svg", bbox_inches="tight", metadata={"Date": None})
    plt.close(fig)
    return SavedFigure(stem, title, caption)


def format_values(values, fmt="{:g}") -> str:
    """'0.1, 0.2, 0.3' for a handful of values, '0.1 ... 0.9 (9 values)' for many."""
    values = sorted(set(values))
    if len(values) <= 6:
        return ", ".join(fmt.format(v) for v in values)
    return f"{fmt.format(values[0])} ... {fmt.format(values[-1])} ({len(values)} values)"
