"""The report end to end from a small fixture of results written by the test itself (sweep rows,
a scaling benchmark JSON, reconstruction JSONs with their points files): every figure and the
page are built, the page references only files that exist, the same files give the same bytes,
and headless Chromium shows the page without a console error."""
import html.parser
import json
import math
import pathlib
import subprocess
import sys
import xml.etree.ElementTree

import matplotlib.image
import pytest
from selenium import webdriver
from selenium.webdriver.chrome.service import Service

ROOT = pathlib.Path(__file__).resolve().parents[2]
FIGURES = ["metrics_by_condition", "error_vs_runtime", "medial_axis_dominant_points", "success_vs_epsilon",
           "l2_vs_density", "robustness", "scaling_runtime", "scaling_memory", "gallery"]
ALGORITHMS = ["labeling", "crust", "nn-crust", "optimal-transport"]
# How much worse than the labeling each algorithm is in the fixture (L2 error multiplier).
ERROR_FACTOR = {"labeling": 1.0, "crust": 1.5, "nn-crust": 1.2, "optimal-transport": 3.0}


def sweep_row(algorithm, settings, seed, metrics, status="ok"):
    """A row as harness/sweep/run_sweep.h describes it."""
    # As many points as a uniform sampler is asked for; an epsilon-sampler gives more for a smaller epsilon.
    points = settings.get("count", round(12 / settings.get("epsilon", 0.2)))
    row = {"algorithm": algorithm, "parameters": {}, "input": {**settings, "seed": seed}, "input_points": points,
           "oracle_l2_error": metrics.pop("oracle_l2_error", 0.001), "status": status}
    if status == "ok":
        row.update({"metrics": metrics, "timing_ms": {"delaunay": 0.5, "total": 1.0 + seed}, "evaluate_ms": 2.0})
    else:
        row["message"] = "no result within 60 s" if status == "timeout" else "killed by signal 11"
    return {**row, "wall_ms": 5.0, "peak_memory_kb": 5000}


def curve_metrics(algorithm, l2, true_curves=1, exact=True):
    metrics = {"oracle_l2_error": l2 / 2, "true_curves": true_curves, "l2_error": 0.0 if exact else l2,
               "hausdorff": l2 / 3, "manifold": exact, "components": true_curves if exact else true_curves + 1,
               "closed_components": true_curves if exact else 0}
    metrics["curve_recall"] = 1.0 if exact else 0.95
    if algorithm != "optimal-transport":  # interpolating methods only
        metrics.update({"exact": exact, "edge_precision": 1.0 if exact else 0.9, "edge_recall": 1.0 if exact else 0.8,
                        "edge_f1": 1.0 if exact else 2 * 0.9 * 0.8 / 1.7})
    else:
        metrics["edge_f1"] = None  # vertices of its own
    if algorithm == "labeling":
        metrics.update({"medial_axis_hausdorff": 0.02, "dominant_points": 12, "compression_ratio": 9.0,
                        "integral_square_error": 0.03, "figure_of_merit": 300.0})
    return metrics


def fixture_rows():
    rows = []
    exact_up_to = {"labeling": 0.4, "crust": 0.25, "nn-crust": 0.3, "optimal-transport": 0.2}
    for algorithm in ALGORITHMS:
        for seed in (1, 2):
            for epsilon in (0.1, 0.2, 0.3, 0.4, 0.5):
                for shape, curves in (("rose", 1), ("disjoint", 3)):
                    exact = epsilon <= exact_up_to[algorithm]
                    rows.append(sweep_row(algorithm, {"family": shape, "epsilon": epsilon},
                                          seed, curve_metrics(algorithm, 0.01 * epsilon, curves, exact)))
            for shape in ("star", "concavities"):
                for count in (50, 100, 200, 400):
                    l2 = ERROR_FACTOR[algorithm] * (3.0 / count) * (1 + 0.1 * seed)
                    rows.append(sweep_row(algorithm, {"family": shape, "sampler": "uniform", "count": count},
                                          seed, curve_metrics(algorithm, l2, exact=False)))
            for noise in (0.0, 0.02, 0.05):
                l2 = ERROR_FACTOR[algorithm] * (0.001 + noise)
                exact = noise == 0 and exact_up_to[algorithm] >= 0.2
                rows.append(sweep_row(algorithm, {"family": "ellipse", "shape": {"a": 2, "b": 1}, "noise": noise}, seed, curve_metrics(algorithm, l2, exact=exact)))
            for outliers in (0.0, 0.1, 0.2):
                l2 = ERROR_FACTOR[algorithm] * (0.001 + outliers)
                exact = outliers == 0 and exact_up_to[algorithm] >= 0.2
                rows.append(sweep_row(algorithm, {"family": "rose", "shape": {"k": 3}, "outliers": outliers}, seed, curve_metrics(algorithm, l2, exact=exact)))
    # alpha-shape with a grid: alpha = 0.5 is best under noise, its default (0) with outliers.
    for seed in (1, 2):
        for alpha in (0.0, 0.5):
            parameters = {"alpha": alpha, "components": 1}
            for noise in (0.02, 0.05):
                l2 = (0.002 if alpha else 0.3) + noise
                rows.append({**sweep_row("alpha-shape", {"family": "ellipse", "shape": {"a": 2, "b": 1}, "noise": noise},
                                         seed, curve_metrics("alpha-shape", l2, exact=False)), "parameters": parameters})
            for outliers in (0.1, 0.2):
                l2 = (0.5 if alpha else 0.01) + outliers
                rows.append({**sweep_row("alpha-shape", {"family": "rose", "shape": {"k": 3}, "outliers": outliers},
                                         seed, curve_metrics("alpha-shape", l2, exact=False)), "parameters": parameters})
    rows.append(sweep_row("crust", {"family": "rose", "epsilon": 0.5}, 3, {}, status="timeout"))
    rows.append(sweep_row("nn-crust", {"family": "rose", "shape": {"k": 3}, "outliers": 0.2}, 3, {}, status="crash"))
    return rows


def benchmark_json():
    rows = []
    for algorithm, factor in [("delaunay", 1.0), ("labeling", 1.3), ("crust", 4.0), ("optimal-transport", 300.0)]:
        for input_name in ("smooth", "noisy"):
            for n in (1000, 10000, 100000):
                name = f"{algorithm}/{input_name}/n:{n}/manual_time"
                if algorithm == "optimal-transport" and n == 100000:
                    rows.append({"name": name, "run_type": "iteration", "error_occurred": True,
                                 "error_message": "skipped: about 35 s predicted from n=10000, over --max_run_seconds=5",
                                 "iterations": 0, "real_time": 0.0, "cpu_time": 0.0, "time_unit": "ms"})
                    continue
                milliseconds = factor * 1e-3 * n * math.log2(n) / 10
                rows.append({"name": name, "run_type": "iteration", "iterations": 3, "real_time": milliseconds,
                             "cpu_time": milliseconds, "time_unit": "ms", "ns_per_point": 1e6 * milliseconds / n,
                             "x_delaunay": factor, "peak_MiB": 4.0 + factor * n * 2e-4, "input_MiB": 4.0})
    return {"context": {"date": "2026-01-01T00:00:00+00:00", "num_cpus": 2, "mhz_per_cpu": 2400},
            "benchmarks": rows}


def write_reconstructions(directory: pathlib.Path):
    directory.mkdir()
    shapes = {"circle": lambda t: (math.cos(t), math.sin(t)),
              "rose": lambda t: ((1 + 0.3 * math.cos(5 * t)) * math.cos(t), (1 + 0.3 * math.cos(5 * t)) * math.sin(t))}
    for shape, curve in shapes.items():
        n = 60
        points = [curve(2 * math.pi * k / n) for k in range(n)]
        # A CRLF file with a comment: the gallery reads the README's points format.
        (directory / f"{shape}.xy").write_bytes(
            ("# fixture\r\n" + "".join(f"{x!r}, {y!r}\r\n" for x, y in points)).encode())
        cycle = [[k, (k + 1) % n] for k in range(n)]
        common = {"parameters": {}, "input": {"path": f"{shape}.xy", "points": n, "distinct_points": n},
                  "timing_ms": {"delaunay": 0.1, "total": 0.2}, "status": "ok"}
        records = {
            "labeling": {"curve": {"edges": cycle},
                         "medial_axis": {"vertices": [[0.0, 0.0], [0.3, 0.0]], "radii": [0.7, 0.5], "edges": [[0, 1]]},
                         "dominant_points": [0, 15, 30, 45]},
            "crust": {"curve": {"edges": cycle}},
            "optimal-transport": {"curve": {"vertices": [list(points[k]) for k in range(0, n, 6)],
                                            "edges": [[k, (k + 1) % 10] for k in range(10)]}},
        }
        for algorithm, record in records.items():
            (directory / f"{shape}.{algorithm}.json").write_text(json.dumps({"algorithm": algorithm, **common, **record}))
            if algorithm != "crust":  # as `curvebench reconstruct --svg` writes it; crust's is missing
                (directory / f"{shape}.{algorithm}.svg").write_text(
                    f'<svg xmlns="http://www.w3.org/2000/svg" width="400" height="400"><title>{algorithm}: {shape}</title>'
                    '<circle cx="200" cy="200" r="150" fill="none" stroke="black"/></svg>')
        error = {"algorithm": "nn-crust", "input": {"path": f"{shape}.xy"}, "status": "error",
                 "message": f"{shape}.xy: a made-up failure for the gallery"}
        (directory / f"{shape}.nn-crust.json").write_text(json.dumps(error))
    (directory / "rose.truth.json").write_text(json.dumps({"format": "curvebench-ground-truth/1"}))  # not a reconstruction


@pytest.fixture(scope="module")
def report_inputs(tmp_path_factory):
    directory = tmp_path_factory.mktemp("report_inputs")
    (directory / "results.jsonl").write_text("".join(json.dumps(row) + "\n" for row in fixture_rows()))
    (directory / "scaling.json").write_text(json.dumps(benchmark_json()))
    write_reconstructions(directory / "reconstructions")
    (directory / "catalogue.json").write_text(json.dumps(
        [{"name": name, "parameters": []} for name in ALGORITHMS] +
        [{"name": "alpha-shape", "parameters": [{"name": "alpha", "default": 0.0}, {"name": "components", "default": 1}]}]))
    return directory


def build(inputs: pathlib.Path, out: pathlib.Path, *sections):
    arguments = {"results": ["--results", inputs / "results.jsonl"], "benchmark": ["--benchmark", inputs / "scaling.json"],
                 "reconstructions": ["--reconstructions", inputs / "reconstructions"],
                 "catalogue": ["--catalogue", inputs / "catalogue.json"]}
    command = [sys.executable, "-m", "reports", "--out", out]
    for section in sections:
        command += arguments[section]
    result = subprocess.run(command, cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    page = pathlib.Path(result.stdout.strip())
    assert page == out / "index.html"
    return page


@pytest.fixture(scope="module")
def report(report_inputs, tmp_path_factory):
    return build(report_inputs, tmp_path_factory.mktemp("report"), "results", "benchmark", "reconstructions",
                 "catalogue")


class PageReferences(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.references = []

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if name in ("src", "href") and value and not value.startswith(("#", "data:")):
                self.references.append(value)


def page_references(page: pathlib.Path):
    parser = PageReferences()
    parser.feed(page.read_text())
    return parser.references


def test_every_figure_is_written_as_png_and_svg(report):
    for stem in FIGURES:
        image = matplotlib.image.imread(report.parent / f"{stem}.png")
        height, width = image.shape[:2]
        assert width >= 600 and height >= 300, (stem, image.shape)
        assert image.std() > 0.01, f"{stem}.png is blank"
        root = xml.etree.ElementTree.parse(report.parent / f"{stem}.svg").getroot()
        assert root.tag.endswith("svg")


def test_page_references_only_files_that_exist_and_every_figure(report):
    references = page_references(report)
    for reference in references:
        assert (report.parent / reference).is_file(), reference
    for stem in FIGURES:
        assert f"{stem}.png" in references and f"{stem}.svg" in references


def test_gallery_links_every_reconstruction_to_its_full_size_svg(report, report_inputs):
    references = page_references(report)
    for shape in ("circle", "rose"):
        for algorithm in ("labeling", "optimal-transport"):
            link = f"gallery/{shape}.{algorithm}.svg"
            assert link in references
            assert (report.parent / link).read_bytes() == \
                (report_inputs / "reconstructions" / f"{shape}.{algorithm}.svg").read_bytes()
    assert not any(reference.endswith((".crust.svg", ".nn-crust.svg")) for reference in references)
    text = report.read_text()
    assert '<td class="missing">no SVG</td>' in text and '<td class="missing">error</td>' in text


def test_a_parameter_grid_is_shown_at_its_default_and_its_best_setting(report):
    text = report.read_text()
    assert "alpha-shape (default)" in text and "alpha-shape (alpha=0.5; best of 2)" in text  # noise
    assert "alpha-shape (default, best of 2 settings)" in text  # outliers


def test_results_with_a_grid_and_no_catalogue_are_a_one_line_error(report_inputs, tmp_path):
    result = subprocess.run([sys.executable, "-m", "reports", "--out", tmp_path, "--results",
                             report_inputs / "results.jsonl"], cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert result.returncode == 1
    assert result.stderr.strip() == ("reports: the results hold 2 parameter settings of alpha-shape: give --catalogue "
                                     "(curvebench list --json) so that the report knows its default")


def test_page_has_a_caption_for_every_figure_and_the_summary(report):
    text = report.read_text()
    assert text.count("<figcaption>") == len(FIGURES)
    assert "Which method is best under which condition" in text
    for condition in ["Several curves", "Sparse sampling", "Dense sampling", "Noise", "Outliers", "Sharp corners",
                      "Medial axis", "Dominant points", "Speed, smooth curve", "Memory, noisy curve", "edge F1",
                      "curve recall", "<tr class=\"agreement\">"]:
        assert condition in text, condition
    assert "Not drawn" not in text
    assert "1 timeout" in text and "1 crash" in text  # failed runs are reported, not hidden


def test_same_files_give_the_same_bytes(report_inputs, report, tmp_path):
    again = build(report_inputs, tmp_path, "results", "benchmark", "reconstructions", "catalogue")
    for name in ["index.html"] + [f"{stem}.{ext}" for stem in FIGURES for ext in ("png", "svg")]:
        assert (again.parent / name).read_bytes() == (report.parent / name).read_bytes(), name


def test_page_names_the_sections_it_could_not_draw(report_inputs, tmp_path):
    page = build(report_inputs, tmp_path, "benchmark")
    text = page.read_text()
    assert "Not drawn: the accuracy figures (no sweep results given)" in text
    assert "Not drawn: the gallery" in text
    assert {r for r in page_references(page)} == {"scaling_runtime.png", "scaling_runtime.svg", "scaling_memory.png",
                                                   "scaling_memory.svg"}


def test_page_opens_in_headless_chromium_without_console_errors(report, tmp_path):
    for binary in ("/usr/bin/chromium", "/usr/bin/chromedriver"):
        assert pathlib.Path(binary).exists(), f"{binary} missing: tests/run.sh installs chromium and chromium-driver"
    options = webdriver.ChromeOptions()
    options.binary_location = "/usr/bin/chromium"
    for flag in ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 f"--user-data-dir={tmp_path / 'profile'}", "--window-size=1280,1000"]:
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
    try:
        driver.get(report.as_uri())
        images = driver.execute_script(
            "return Array.from(document.images).map(i => [i.getAttribute('src'), i.complete, i.naturalWidth])")
        assert sorted(src for src, _, _ in images) == sorted(f"{stem}.png" for stem in FIGURES)
        assert all(complete and width > 0 for _, complete, width in images), images
        height = driver.execute_script("return document.body.scrollHeight")
        driver.set_window_size(1280, height + 100)
        screenshot = tmp_path / "report.png"
        assert driver.save_screenshot(str(screenshot))
        errors = [entry for entry in driver.get_log("browser") if entry["level"] in ("SEVERE", "ERROR")]
    finally:
        driver.quit()
    assert errors == []
    shot = matplotlib.image.imread(screenshot)
    assert shot.shape[0] >= 0.9 * height and shot.std() > 0.05
