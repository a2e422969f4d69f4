"""The report's readers and computations on hand-made data with known answers, and the two
producers it reads from run for real: a tiny scaling benchmark and a tiny sweep."""
import json
import math
import pathlib
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))  # the reports package lives at the repository root

from reports.reconstructions import read_points_file, read_reconstructions  # noqa: E402
from reports.scaling_figures import log_log_slope  # noqa: E402
from reports.scaling_results import read_scaling_suite  # noqa: E402
from reports.sweep_results import read_sweep_rows  # noqa: E402


def test_slope_of_power_laws_is_their_exponent():
    ns = [1_000, 10_000, 100_000, 1_000_000]
    assert log_log_slope(ns, [3e-9 * n for n in ns]) == pytest.approx(1.0)
    assert log_log_slope(ns, [1e-12 * n * n for n in ns]) == pytest.approx(2.0)
    # n log n: the local slope is 1 + 1 / ln n, about 1.09 over n = 10^4 ... 10^6.
    assert log_log_slope(ns, [1e-9 * n * math.log(n) for n in ns]) == pytest.approx(1.09, abs=0.01)


def test_slope_leaves_out_small_n_when_enough_large_ones_remain():
    # A fixed cost dominates at n = 1000 only: the fit over n >= 10^4 still finds 1.
    ns = [1_000, 10_000, 100_000, 1_000_000]
    assert log_log_slope(ns, [1.0 if n == 1_000 else 1e-6 * n for n in ns]) == pytest.approx(1.0)
    assert log_log_slope([1_000, 10_000], [1e-3, 1e-2]) == pytest.approx(1.0)
    assert log_log_slope([1_000], [1e-3]) is None


def write_json(path, data):
    path.write_text(json.dumps(data))
    return path


def test_scaling_suite_reads_times_counters_and_skipped_runs(tmp_path):
    path = write_json(tmp_path / "scaling.json", {"context": {"num_cpus": 2}, "benchmarks": [
        {"name": "delaunay/smooth/n:1000/manual_time", "run_type": "iteration", "real_time": 2.0, "cpu_time": 9.0,
         "time_unit": "ms", "x_delaunay": 1.0, "peak_MiB": 5.5, "input_MiB": 4.0},
        {"name": "labeling/noisy/n:1000000/manual_time", "run_type": "iteration", "real_time": 1500.0,
         "time_unit": "us", "x_delaunay": 1.4, "peak_MiB": 300.0, "input_MiB": 40.0},
        {"name": "labeling/noisy/n:1000000/manual_time_mean", "run_type": "aggregate", "real_time": 1.0},
        {"name": "optimal-transport/smooth/n:100000/manual_time", "run_type": "iteration", "error_occurred": True,
         "error_message": "skipped: about 35 s predicted", "real_time": 0.0, "time_unit": "ms"}]})
    suite = read_scaling_suite(path)
    assert [(r.algorithm, r.input, r.n) for r in suite.runs] == [
        ("delaunay", "smooth", 1000), ("labeling", "noisy", 1000000), ("optimal-transport", "smooth", 100000)]
    delaunay, labeling, skipped = suite.runs
    assert delaunay.seconds == pytest.approx(0.002)  # the measured (manual) time, not the process CPU time
    assert labeling.seconds == pytest.approx(0.0015)
    assert labeling.reconstruction_mib == pytest.approx(260.0)
    assert skipped.seconds is None and skipped.skip_reason == "skipped: about 35 s predicted"
    assert suite.inputs() == ["smooth", "noisy"] and suite.algorithms() == ["labeling", "optimal-transport"]


def test_scaling_suite_rejects_names_it_cannot_place(tmp_path):
    path = write_json(tmp_path / "scaling.json", {"benchmarks": [{"name": "BM_Other/64", "real_time": 1.0}]})
    with pytest.raises(ValueError, match="not <algorithm>/<input>/n:<n>"):
        read_scaling_suite(path)


@pytest.mark.parametrize("end", ["\n", "\r\n", "\r"])
def test_points_file_reader_follows_the_readme_format(tmp_path, end):
    path = tmp_path / "pts.xy"
    path.write_bytes(end.join(["# header", "0 0", "1,0", "1\t1  extra columns", "", "0 1 # comment", ""]).encode())
    assert read_points_file(path).tolist() == [[0, 0], [1, 0], [1, 1], [0, 1]]


def test_points_file_reader_names_the_bad_line(tmp_path):
    path = tmp_path / "pts.xy"
    path.write_text("0 0\n1 x\n")
    with pytest.raises(ValueError, match=r"pts.xy:2: not two numbers"):
        read_points_file(path)


def test_reconstructions_read_own_vertices_and_error_records(tmp_path):
    (tmp_path / "sq.xy").write_text("0 0\n1 0\n1 1\n0 1\n")
    write_json(tmp_path / "sq.optimal-transport.json", {
        "algorithm": "optimal-transport", "input": {"path": "sq.xy"}, "status": "ok",
        "curve": {"vertices": [[0, 0], [1, 1]], "edges": [[0, 1]]}})
    write_json(tmp_path / "gone.labeling.json", {"algorithm": "labeling", "input": {"path": "gone.xy"},
                                                 "status": "error", "message": "gone.xy: cannot open"})
    write_json(tmp_path / "sq.truth.json", {"format": "curvebench-ground-truth/1"})
    failed, transported = read_reconstructions(tmp_path)
    assert (transported.shape, transported.algorithm) == ("sq", "optimal-transport")
    assert transported.curve_vertices.tolist() == [[0, 0], [1, 1]] and transported.curve_edges.tolist() == [[0, 1]]
    assert len(transported.points) == 4 and transported.medial_axis_edges is None
    assert (failed.status, failed.message, len(failed.points)) == ("error", "gone.xy: cannot open", 0)


def sweep_line(algorithm, settings, status="ok", metrics=None):
    row = {"algorithm": algorithm, "parameters": {}, "input": settings, "input_points": 50, "oracle_l2_error": 0.01,
           "status": status}
    if status == "ok":
        row.update({"metrics": metrics or {}, "timing_ms": {"total": 2.0}})
    return json.dumps({**row, "wall_ms": 3.0, "peak_memory_kb": 2048})


def test_sweep_rows_take_generate_defaults_and_share_the_truth(tmp_path):
    path = tmp_path / "results.jsonl"
    path.write_text("\n".join([
        sweep_line("labeling", {"family": "rose", "shape": {"k": 3}, "seed": 2},
                   metrics={"true_curves": 1, "exact": True, "l2_error": 0.0}),
        sweep_line("crust", {"family": "rose", "shape": {"k": 3}, "seed": 2}, status="timeout"),
        sweep_line("crust", {"family": "star", "sampler": "uniform", "seed": 1}, metrics={"true_curves": 1}),
    ]) + "\n")
    labeling, timed_out, uniform = read_sweep_rows(path)
    assert (labeling.shape, labeling.sampler, labeling.epsilon, labeling.count) == ("rose k=3", "epsilon", 0.2, None)
    assert (labeling.noise, labeling.noise_scale, labeling.outliers, labeling.seed) == (0.0, "lfs", 0.0, 2)
    assert labeling.metric("exact") == 1.0 and labeling.metric("hausdorff") is None
    assert labeling.seconds == pytest.approx(0.002) and labeling.peak_mib == 2.0
    assert not timed_out.ok and timed_out.true_curves == 1  # from the finished run of the same input
    assert (uniform.sampler, uniform.epsilon, uniform.count) == ("uniform", None, 200)


def test_noise_model_is_read_from_the_settings(tmp_path):
    # A Gaussian level is a standard deviation, a uniform one the half-width of a band: the
    # robustness figure draws one panel per model, so each row must know its model.
    path = tmp_path / "results.jsonl"
    lines = []
    for algorithm, l2 in (("labeling", 0.1), ("fitconnect", 0.2)):
        lines.append(sweep_line(algorithm, {"family": "rose", "noise": 0.1}, metrics={"true_curves": 1, "l2_error": l2}))
        lines.append(sweep_line(algorithm, {"family": "rose", "noise": 0.2, "noise_model": "uniform"},
                                metrics={"true_curves": 1, "l2_error": 0.3 - l2}))
    path.write_text("\n".join(lines) + "\n")
    rows = read_sweep_rows(path)
    assert [r.noise_model for r in rows] == ["gaussian", "uniform"] * 2
    assert [r.noise for r in rows] == [0.1, 0.2] * 2


def test_sweep_reader_names_the_bad_line(tmp_path):
    path = tmp_path / "results.jsonl"
    path.write_text(sweep_line("labeling", {"family": "circle"}) + "\n{\"status\": \"ok\"}\n")
    with pytest.raises(ValueError, match=r"results.jsonl:2: not a sweep row"):
        read_sweep_rows(path)


@pytest.fixture(scope="module")
def benchmark_bin(curvebench_bin):
    path = pathlib.Path(curvebench_bin).parent / "bench" / "curvebench_benchmark"
    if not path.exists():
        pytest.fail(f"{path} not built: tests/run.sh builds it (-DCURVEBENCH_BENCHMARKS=ON)")
    return path


def test_benchmark_json_feeds_the_report_with_per_run_memory_and_budget_skips(benchmark_bin, tmp_path):
    out = tmp_path / "scaling.json"
    # A budget of 0 s: every run after the first n is predicted to exceed it, whatever the machine.
    result = subprocess.run([benchmark_bin, "--max_n=10000", "--max_run_seconds=0", "--benchmark_min_time=0.001",
                             "--benchmark_filter=^(delaunay|labeling)/", f"--benchmark_out={out}",
                             "--benchmark_out_format=json"], capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    suite = read_scaling_suite(out)
    assert {(r.algorithm, r.input, r.n) for r in suite.runs} == {
        (a, i, n) for a in ("delaunay", "labeling") for i in ("smooth", "noisy", "shuffled") for n in (1000, 10000)}
    for run in suite.runs:
        if run.n == 1000:
            assert run.skip_reason is None and run.seconds > 0
            assert run.peak_mib >= run.input_mib > 0  # measured in a fresh process
            assert run.times_delaunay > 0
        else:
            assert run.seconds is None and "--max_run_seconds=0" in run.skip_reason


def test_a_real_sweep_gives_every_accuracy_figure(run, tmp_path):
    config = write_json(tmp_path / "config.json", {
        "description": "report test", "seeds": [1], "algorithms": ["labeling", "crust"],
        "inputs": [{"family": ["circle", "disjoint"], "epsilon": [0.2, 0.4]},
                   {"family": "star", "sampler": "uniform", "count": [40, 80]},
                   {"family": "rose", "noise": [0, 0.05]},
                   {"family": "rose", "outliers": [0, 0.2]}]})
    results = tmp_path / "results.jsonl"
    swept = run("sweep", config, "--out", results, "--jobs", "2", "--quiet", timeout=300)
    assert swept.returncode == 0, swept.stderr
    rows = read_sweep_rows(results)
    assert len(rows) == 2 * (4 + 2 + 2 + 2)
    out = tmp_path / "report"
    built = subprocess.run([sys.executable, "-m", "reports", "--out", out, "--results", results], cwd=ROOT,
                           capture_output=True, text=True, timeout=300)
    assert built.returncode == 0, built.stderr
    page = (out / "index.html").read_text()
    for stem in ("success_vs_epsilon", "l2_vs_density", "robustness"):
        assert f'src="{stem}.png"' in page and (out / f"{stem}.svg").exists()
    assert "Not drawn: runtime and memory" in page and "Not drawn: the gallery" in page
    assert "Several curves" in page and "Sparse sampling" in page
