"""`curvebench sweep` end to end: every run takes place in a fresh process, so a row is what
`reconstruct` and `evaluate`, each a fresh process, give for the same input; and the hidden
`sweep-run` subcommand that performs a run refuses a bad spec with an error row, not a crash."""
import json

# CGAL's optimal-transport reconstruction used to depend on the heap it started with: on
# these noisy inputs sweep rows disagreed with `reconstruct`, and two sweeps with each other.
CONFIG = {
    "timeout_seconds": 60,
    "seeds": [1, 2, 3],
    "algorithms": ["optimal-transport", "alpha-shape", "labeling"],
    "inputs": [{"family": ["random", "rose"], "epsilon": [0.13, 0.17], "noise": [0.1], "dense": 1024}],
}
MEASUREMENTS = ("timing_ms", "evaluate_ms", "wall_ms", "peak_memory_kb")


def sweep(run, tmp_path, name, *args):
    config = tmp_path / "config.json"
    config.write_text(json.dumps(CONFIG))
    out = tmp_path / f"{name}.jsonl"
    result = run("sweep", config, "--out", out, "--inputs", tmp_path / "inputs", "--quiet", *args, timeout=300)
    assert result.returncode == 0, result.stderr
    rows = [json.loads(line) for line in out.read_text().splitlines()]
    for row in rows:
        for key in MEASUREMENTS:
            row.pop(key, None)
    return rows


def test_rows_are_what_fresh_processes_give(run, tmp_path):
    rows = sweep(run, tmp_path, "parallel", "--jobs", "2")
    assert len(rows) == 36 and all(row["status"] == "ok" for row in rows)
    for i, row in enumerate(rows):
        settings = dict(row["input"])
        args = []
        for key, value in settings.items():
            args += ["--" + key.replace("_", "-"), str(value)]
        points, truth, result, metrics = (tmp_path / f"r{i}{suffix}" for suffix in (".xy", ".truth.json", ".json", ".metrics.json"))
        assert run("generate", *args, "--points", points, "--truth", truth).returncode == 0
        reconstructed = run("reconstruct", "--algorithm", row["algorithm"], "--input", points, "--output", result)
        assert reconstructed.returncode == 0, reconstructed.stderr
        evaluated = run("evaluate", "--truth", truth, "--result", result, "--output", metrics)
        assert evaluated.returncode == 0, evaluated.stderr
        assert json.loads(metrics.read_text())["metrics"] == row["metrics"], (row["algorithm"], settings)


def test_rows_do_not_depend_on_the_number_of_jobs(run, tmp_path):
    assert sweep(run, tmp_path, "serial", "--jobs", "1") == sweep(run, tmp_path, "parallel", "--jobs", "2")


def test_sweep_run_reports_a_bad_spec_as_an_exception(run):
    result = run("sweep-run", '{"row": {"algorithm": "labeling"}}')
    assert result.returncode == 0
    assert result.stdout.startswith("T") and "not found" in result.stdout
