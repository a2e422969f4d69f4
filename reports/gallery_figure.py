"""Gallery of reconstructions (as in the paper's Figures 9, 18 and 19): shapes as rows,
algorithms as columns; each cell draws the samples, the reconstructed curve, and the interior
medial axis and dominant points where the algorithm produces them."""
from __future__ import annotations

import collections
import html
import pathlib
import shutil
import textwrap

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.lines import Line2D

from reports.reconstructions import ReconstructionView
from reports.style import SavedFigure, algorithm_color, plt, save_figure, sorted_algorithms

MEDIAL_AXIS_COLOR = "#2b8c3e"
DOMINANT_POINT_COLOR = "#ffd60a"
POINT_COLOR = "#555555"
CELL_INCHES = 2.3


def _draw_cell(ax, view: ReconstructionView, lower: np.ndarray, upper: np.ndarray):
    ax.set_xticks([])
    ax.set_yticks([])
    ax.set_aspect("equal")
    margin = 0.06 * max(upper - lower)
    ax.set_xlim(lower[0] - margin, upper[0] + margin)
    ax.set_ylim(lower[1] - margin, upper[1] + margin)
    if view.status != "ok":
        ax.text(0.5, 0.5, "\n".join(textwrap.wrap(f"{view.status}: {view.message}", 28)[:6]), ha="center",
                va="center", fontsize=7, color="#b00020", transform=ax.transAxes)
        return
    point_size = float(np.clip(600 / max(len(view.points), 1), 0.5, 6))
    ax.scatter(view.points[:, 0], view.points[:, 1], s=point_size, color=POINT_COLOR, linewidths=0, zorder=2)
    notes = [f"n={len(view.points)}"]
    if view.medial_axis_edges is not None:
        segments = view.medial_axis_vertices[view.medial_axis_edges]
        ax.add_collection(LineCollection(segments, colors=MEDIAL_AXIS_COLOR, linewidths=0.6, alpha=0.8, zorder=1))
    if view.curve_edges is not None:
        segments = view.curve_vertices[view.curve_edges]
        ax.add_collection(LineCollection(segments, colors=algorithm_color(view.algorithm), linewidths=1.3, zorder=3))
        notes.append(f"{len(view.curve_edges)} edges")
    if view.dominant_points is not None:
        chosen = view.points[view.dominant_points]
        ax.scatter(chosen[:, 0], chosen[:, 1], s=22, marker="o", facecolor=DOMINANT_POINT_COLOR, edgecolor="black",
                   linewidths=0.6, zorder=4)
        notes.append(f"{len(view.dominant_points)} dominant")
    ax.text(0.02, 0.02, ", ".join(notes), fontsize=6.5, color="#333333", transform=ax.transAxes,
            bbox={"facecolor": "white", "alpha": 0.75, "edgecolor": "none", "pad": 1})


def gallery_figure(views: list[ReconstructionView], out_dir: pathlib.Path) -> SavedFigure:
    by_cell = {(view.shape, view.algorithm): view for view in views}
    shapes = sorted({view.shape for view in views})
    algorithms = sorted_algorithms({view.algorithm for view in views})
    fig, axes = plt.subplots(len(shapes), len(algorithms), squeeze=False,
                             figsize=(CELL_INCHES * len(algorithms), CELL_INCHES * len(shapes) + 0.6))
    for row, shape in enumerate(shapes):
        shape_points = [v.points for v in views if v.shape == shape and len(v.points)]
        all_points = np.concatenate(shape_points) if shape_points else np.zeros((1, 2))
        lower, upper = all_points.min(axis=0), all_points.max(axis=0)
        for column, algorithm in enumerate(algorithms):
            ax = axes[row][column]
            if (shape, algorithm) in by_cell:
                _draw_cell(ax, by_cell[(shape, algorithm)], lower, upper)
            else:
                ax.set_axis_off()
                ax.text(0.5, 0.5, "not run", ha="center", va="center", color="#999999", transform=ax.transAxes)
            if row == 0:
                ax.set_title(algorithm, color=algorithm_color(algorithm), fontweight="bold")
        axes[row][0].set_ylabel(shape, fontsize=10)
    legend = [Line2D([], [], color=POINT_COLOR, marker="o", linestyle="", markersize=3, label="samples"),
              Line2D([], [], color="#444444", linewidth=1.3, label="curve (algorithm's colour)"),
              Line2D([], [], color=MEDIAL_AXIS_COLOR, linewidth=0.8, label="interior medial axis"),
              Line2D([], [], marker="o", linestyle="", markerfacecolor=DOMINANT_POINT_COLOR, markeredgecolor="black",
                     label="dominant points")]
    fig.legend(handles=legend, loc="upper center", ncol=4, frameon=False, bbox_to_anchor=(0.5, 1.0))
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.45 / fig.get_figheight()))
    counts = collections.Counter(view.status for view in views)
    status_text = ", ".join(f"{count} {status}" for status, count in sorted(counts.items()))
    caption = (f"{len(views)} reconstructions ({status_text}) of {len(shapes)} point sets ({', '.join(shapes)}) "
               f"by {', '.join(algorithms)}, drawn from the reconstruction JSON "
               "files: grey dots are the samples, the coloured edges the reconstructed curve; the green medial axis "
               "and yellow dominant points appear only for algorithms that produce them.")
    figure = save_figure(fig, out_dir, "gallery", "Gallery of reconstructions", caption)
    figure.extra_html = full_size_links(views, shapes, algorithms, out_dir)
    return figure


GALLERY_DIRECTORY = "gallery"


def full_size_links(views: list[ReconstructionView], shapes: list[str], algorithms: list[str],
                    out_dir: pathlib.Path) -> str:
    """A table of links, shapes by algorithms, to each reconstruction's own SVG (written by
    `curvebench reconstruct --svg` beside its JSON, copied into out_dir/gallery/ so that the
    report directory stands alone); a cell without one says why."""
    by_cell = {(view.shape, view.algorithm): view for view in views}
    (out_dir / GALLERY_DIRECTORY).mkdir(exist_ok=True)
    head = "".join(f"<th>{html.escape(a)}</th>" for a in algorithms)
    body = []
    for shape in shapes:
        cells = []
        for algorithm in algorithms:
            view = by_cell.get((shape, algorithm))
            if view is None:
                cells.append('<td class="missing">not run</td>')
            elif view.status != "ok":
                cells.append(f'<td class="missing">{html.escape(view.status)}</td>')
            elif view.svg is None:
                cells.append('<td class="missing">no SVG</td>')
            else:
                target = f"{GALLERY_DIRECTORY}/{view.svg.name}"
                shutil.copyfile(view.svg, out_dir / target)
                cells.append(f'<td><a href="{html.escape(target)}">SVG</a></td>')
        body.append(f"<tr><th scope=\"row\">{html.escape(shape)}</th>{''.join(cells)}</tr>")
    return (f'<p>Each reconstruction at full size, as SVG (points, curve, interior medial axis and dominant points '
            f'where the algorithm gives them):</p><table class="gallery-links"><thead><tr><th>shape</th>{head}</tr>'
            f'</thead><tbody>{"".join(body)}</tbody></table>')
