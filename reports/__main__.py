"""python -m reports: the report from files only.

  python -m reports --out DIR [--results results.jsonl] [--benchmark scaling.json]
                    [--reconstructions DIR] [--catalogue catalogue.json]

Writes DIR/index.html and, beside it, every figure as PNG and SVG; prints the page's path.
A section whose input is not given or holds no run of its kind is named on the page as missing.
"""
from __future__ import annotations

import argparse
import json
import pathlib
import sys

from reports.accuracy_figures import l2_density_figure, robustness_figure, success_epsilon_figure
from reports.gallery_figure import gallery_figure
from reports.html_page import write_page
from reports.metric_figures import error_runtime_figure, medial_axis_and_dominant_points_figure, \
    metrics_by_condition_figure
from reports.parameter_settings import default_rows, use_catalogue_defaults
from reports.reconstructions import read_reconstructions
from reports.scaling_figures import memory_figure, runtime_figure
from reports.scaling_results import read_scaling_suite
from reports.style import use_catalogue
from reports.summary_html import summary_html
from reports.summary_table import condition_summaries, dominant_points_line, medial_axis_line, speed_lines
from reports.sweep_results import read_sweep_rows


def build_report(out_dir: pathlib.Path, results: pathlib.Path | None, benchmark: pathlib.Path | None,
                 reconstructions: pathlib.Path | None) -> pathlib.Path:
    out_dir.mkdir(parents=True, exist_ok=True)
    figures, missing, sources = [], [], []
    summaries, other_lines = [], []
    if results is not None:
        rows = read_sweep_rows(results)
        sources.append(f"sweep results {results} ({len(rows)} rows)")
        summaries = condition_summaries(rows)
        other_lines = [line for line in (medial_axis_line(rows), dominant_points_line(rows)) if line is not None]
        at_default = default_rows(rows)
        without_default = sorted({r.algorithm for r in rows} - {r.algorithm for r in at_default})
        if without_default:
            missing.append(f"Not drawn at their defaults (the parameter grid leaves the default out): "
                           f"{', '.join(without_default)}; they are in the summary and the error-runtime figure.")
        for make, source, what in [
                (metrics_by_condition_figure, summaries, "the metrics by condition: no run under a summary condition"),
                (error_runtime_figure, rows, "error against runtime: no run under a summary condition"),
                (medial_axis_and_dominant_points_figure, rows,
                 "medial axis and dominant points: no run produced either"),
                (success_epsilon_figure, at_default, "success rate against epsilon: no clean epsilon-sampled runs"),
                (l2_density_figure, at_default, "L2 error against density: no clean runs with a fixed point count"),
                (robustness_figure, at_default, "robustness: no runs with noise or outliers")]:
            figure = make(source, out_dir)
            if figure is None:
                missing.append(f"Not drawn: {what} in {results}.")
            else:
                figures.append(figure)
    else:
        missing.append("Not drawn: the accuracy figures (no sweep results given).")
    if benchmark is not None:
        suite = read_scaling_suite(benchmark)
        sources.append(f"scaling benchmark {benchmark} ({len(suite.runs)} runs)")
        figures += [runtime_figure(suite, out_dir), memory_figure(suite, out_dir)]
        other_lines += speed_lines(suite)
    else:
        missing.append("Not drawn: runtime and memory against n (no benchmark JSON given).")
    if reconstructions is not None:
        views = read_reconstructions(reconstructions)
        sources.append(f"reconstructions in {reconstructions} ({len(views)} files)")
        if views:
            figures.append(gallery_figure(views, out_dir))
        else:
            missing.append(f"Not drawn: the gallery (no reconstruction JSON in {reconstructions}).")
    else:
        missing.append("Not drawn: the gallery (no reconstruction directory given).")
    drawn = {figure.stem for figure in figures}
    return write_page(out_dir, figures, summary_html(summaries, other_lines, drawn), sources, missing)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m reports", description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", type=pathlib.Path, required=True, help="directory for index.html and the figures")
    parser.add_argument("--results", type=pathlib.Path, help="results of `curvebench sweep` (JSON lines)")
    parser.add_argument("--benchmark", type=pathlib.Path, help="curvebench_benchmark --benchmark_format=json output")
    parser.add_argument("--reconstructions", type=pathlib.Path,
                        help="directory of `curvebench reconstruct --output` JSON files (searched recursively)")
    parser.add_argument("--catalogue", type=pathlib.Path,
                        help="`curvebench list --json` output: the algorithms' order in tables and legends and "
                             "their default parameters (needed when the results hold parameter grids)")
    args = parser.parse_args(argv)
    for given in (args.results, args.benchmark, args.reconstructions, args.catalogue):
        if given is not None and not given.exists():
            parser.error(f"{given}: no such file or directory")
    if args.catalogue is not None:
        catalogue = json.loads(args.catalogue.read_text())
        use_catalogue(catalogue)
        use_catalogue_defaults(catalogue)
    try:
        print(build_report(args.out, args.results, args.benchmark, args.reconstructions))
    except ValueError as e:
        print(f"reports: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
