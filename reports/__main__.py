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
from reports.reconstructions import read_reconstructions
from reports.scaling_figures import memory_figure, runtime_figure
from reports.scaling_results import read_scaling_suite
from reports.style import use_catalogue
from reports.summary_table import summary_lines, summary_table_html
from reports.sweep_results import read_sweep_rows


def build_report(out_dir: pathlib.Path, results: pathlib.Path | None, benchmark: pathlib.Path | None,
                 reconstructions: pathlib.Path | None) -> pathlib.Path:
    out_dir.mkdir(parents=True, exist_ok=True)
    figures, missing, sources = [], [], []
    rows = []
    if results is not None:
        rows = read_sweep_rows(results)
        sources.append(f"sweep results {results} ({len(rows)} rows)")
        for make, what in [(success_epsilon_figure, "success rate against epsilon: no clean epsilon-sampled runs"),
                           (l2_density_figure, "L2 error against density: no clean runs with a fixed point count"),
                           (robustness_figure, "robustness: no runs with noise or outliers")]:
            figure = make(rows, out_dir)
            if figure is None:
                missing.append(f"Not drawn: {what} in {results}.")
            else:
                figures.append(figure)
    else:
        missing.append("Not drawn: the accuracy figures (no sweep results given).")
    suite = None
    if benchmark is not None:
        suite = read_scaling_suite(benchmark)
        sources.append(f"scaling benchmark {benchmark} ({len(suite.runs)} runs)")
        figures += [runtime_figure(suite, out_dir), memory_figure(suite, out_dir)]
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
    return write_page(out_dir, figures, summary_table_html(summary_lines(rows, suite)), sources, missing)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m reports", description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", type=pathlib.Path, required=True, help="directory for index.html and the figures")
    parser.add_argument("--results", type=pathlib.Path, help="results of `curvebench sweep` (JSON lines)")
    parser.add_argument("--benchmark", type=pathlib.Path, help="curvebench_benchmark --benchmark_format=json output")
    parser.add_argument("--reconstructions", type=pathlib.Path,
                        help="directory of `curvebench reconstruct --output` JSON files (searched recursively)")
    parser.add_argument("--catalogue", type=pathlib.Path,
                        help="`curvebench list --json` output: the algorithms' order in tables and legends")
    args = parser.parse_args(argv)
    for given in (args.results, args.benchmark, args.reconstructions, args.catalogue):
        if given is not None and not given.exists():
            parser.error(f"{given}: no such file or directory")
    if args.catalogue is not None:
        use_catalogue(json.loads(args.catalogue.read_text()))
    print(build_report(args.out, args.results, args.benchmark, args.reconstructions))
    return 0


if __name__ == "__main__":
    sys.exit(main())
