"""External algorithms (harness/external/external_algorithm.h): a program declared with its typed
parameters runs under the sweep's isolation like a built-in algorithm. A nearest-neighbour chain
in Python (external/nn_chain.py, on scipy's k-d tree) goes through `reconstruct`, a sweep and the
report; programs that crash, hang, write an index out of range, write a malformed line, write
nothing or hold too much memory (external/misbehaving.py) each become the row they should, and
the sweep goes on past them."""
import json
import pathlib
import shutil
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCRIPTS = pathlib.Path(__file__).resolve().parent / "external"

# The README's example declaration, run with this interpreter (which has scipy).
NN_CHAIN = {**json.loads((SCRIPTS / "nn_chain.json").read_text())}
NN_CHAIN["command"] = [sys.executable] + NN_CHAIN["command"][1:]
MISBEHAVING = ["crash", "hang", "out-of-range", "malformed", "nothing", "memory", "json-cut", "json-out-of-range",
               "json-error"]


def misbehaving(mode):
    return {"name": f"bad-{mode}", "citation": f"an external algorithm that fails: {mode}",
            "command": [sys.executable, "{dir}/misbehaving.py", mode, "{points}", "{output}"],
            "outputs": ["curve"], "output_format": "reconstruction-json" if mode.startswith("json") else "edges"}


def midpoint_polygon(output_format):
    vertices = ["--vertices", "{vertices}"] if output_format == "edges" else []
    return {"name": f"midpoints-{output_format}", "citation": "midpoint polygon in angular order (a test)",
            "command": [sys.executable, "{dir}/midpoint_polygon.py", "{points}", "{output}", "--format", output_format,
                        *vertices],
            "outputs": ["new_curve"], "output_format": output_format}


@pytest.fixture
def declarations(tmp_path):
    """A declaration file with the scripts beside it ({dir})."""
    directory = tmp_path / "algorithms"
    directory.mkdir()
    for script in SCRIPTS.glob("*.py"):  # {dir} is the declaring file's directory
        shutil.copy(script, directory)
    path = directory / "declarations.json"
    path.write_text(json.dumps([NN_CHAIN] + [misbehaving(mode) for mode in MISBEHAVING]
                               + [midpoint_polygon(output_format) for output_format in ("edges", "reconstruction-json")]))
    return path


def test_reconstruct_runs_the_program_and_checks_its_parameters(run, tmp_path, declarations):
    points = tmp_path / "ellipse.xy"
    assert run("generate", "--family", "ellipse", "--epsilon", "0.2", "--seed", "1", "--points", points).returncode == 0
    count = len(points.read_text().splitlines()) - 1  # the generator's comment line
    out = tmp_path / "r.json"
    result = run("reconstruct", "--external", declarations, "--algorithm", "nn-chain", "--input", points,
                 "--param", "neighbours=2", "--output", out)
    assert result.returncode == 0, result.stderr
    reconstruction = json.loads(out.read_text())
    assert reconstruction["parameters"] == {"neighbours": 2}
    assert len(reconstruction["curve"]["edges"]) == count
    assert list(reconstruction["timing_ms"]) == ["distinct_points", "write_input", "program", "read_output", "total"]

    bad = run("reconstruct", "--external", declarations, "--algorithm", "nn-chain", "--input", points,
              "--param", "neighbours=0")
    assert bad.returncode != 0
    assert bad.stderr.strip().splitlines() == [
        "curvebench: error: algorithm 'nn-chain': parameter 'neighbours' must be a whole number >= 1 and <= 64 (got 0)"]

    listed = run("list", "--json", "--external", declarations)
    entry = next(e for e in json.loads(listed.stdout) if e["name"] == "nn-chain")
    assert entry["outputs"] == ["curve"] and entry["parameters"][0]["default"] == 4


def test_a_program_declared_for_collinear_input_is_given_a_line(run, tmp_path, declarations):
    points = tmp_path / "line.xy"
    points.write_text("".join(f"{0.5 * i} {1 + 0.25 * i}\n" for i in range(10)))
    path = declarations.parent / "chains.json"  # beside the scripts ({dir})
    on_lines = {**NN_CHAIN, "name": "nn-chain-on-lines", "collinear_input": "reconstructed"}
    path.write_text(json.dumps([NN_CHAIN, on_lines]))
    refused = run("reconstruct", "--external", path, "--algorithm", "nn-chain", "--input", points)
    assert refused.returncode != 0
    assert "nn-chain: all 10 distinct points are collinear" in refused.stderr
    out = tmp_path / "r.json"
    given = run("reconstruct", "--external", path, "--algorithm", "nn-chain-on-lines", "--input", points, "--output", out)
    assert given.returncode == 0, given.stderr
    edges = json.loads(out.read_text())["curve"]["edges"]
    assert sorted(map(sorted, edges)) == sorted([[i, i + 1] for i in range(9)] + [[0, 9]])  # the chain, closed
    catalogue = {e["name"]: e["collinear_input"] for e in json.loads(run("list", "--json", "--external", path).stdout)}
    assert catalogue["nn-chain"] == "refused" and catalogue["nn-chain-on-lines"] == "reconstructed"
    assert catalogue["crawl"] == "reconstructed" and catalogue["labeling"] == "refused"


@pytest.mark.parametrize("output_format", ["edges", "reconstruction-json"])
def test_a_program_with_vertices_of_its_own_writes_them_in_either_format(run, tmp_path, declarations, output_format):
    points, truth, out, metrics = (tmp_path / name for name in ("rose.xy", "rose.truth.json", "r.json", "m.json"))
    assert run("generate", "--family", "rose", "--epsilon", "0.2", "--points", points, "--truth", truth).returncode == 0
    result = run("reconstruct", "--external", declarations, "--algorithm", f"midpoints-{output_format}",
                 "--input", points, "--output", out)
    assert result.returncode == 0, result.stderr
    curve = json.loads(out.read_text())["curve"]
    count = len(points.read_text().splitlines()) - 1
    assert len(curve["vertices"]) == count and len(curve["edges"]) == count
    assert run("evaluate", "--truth", truth, "--result", out, "--output", metrics).returncode == 0
    scores = json.loads(metrics.read_text())["metrics"]
    assert scores["closed_components"] == 1 and scores["hausdorff"] < 0.02
    # Its edges join vertices of its own, not samples: the edge metrics are null.
    assert all(scores[key] is None for key in ("exact", "edge_precision", "edge_recall", "edge_f1"))


@pytest.mark.parametrize("declaration, message", [
    ({**NN_CHAIN, "command": ["x", "{points}"]}, "has no {output}"),
    ({key: value for key, value in NN_CHAIN.items() if key != "command"}, "command must be a non-empty list of strings"),
    ({**NN_CHAIN, "command": ["x", "{points}", "{output}", "{k}"]}, "names {k}, which is none of"),
    ({**NN_CHAIN, "output_format": "csv"}, "output_format must be"),
    ({**NN_CHAIN, "outputs": ["curve", "medial_axis"]}, "the edges format holds only a curve"),
    ({**NN_CHAIN, "outputs": ["new_curve"]}, "{vertices} is for, and needed by, a \"new_curve\" in the edges format"),
    ({**NN_CHAIN, "name": "labeling"}, "two algorithms are named 'labeling'"),
    ({**NN_CHAIN, "collinear_input": "yes"}, "collinear_input must be \"refused\" or \"reconstructed\""),
    ({**NN_CHAIN, "parameters": [{"name": "neighbours", "type": "integer", "default": 0, "minimum": 1,
                                  "description": "d"}]}, "the default 0 is not a whole number >= 1"),
])
def test_a_bad_declaration_is_one_line_naming_the_file(run, tmp_path, declaration, message):
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(declaration))
    result = run("list", "--external", path)
    assert result.returncode != 0
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and str(path) in lines[0] and message in lines[0], lines


def sweep_config(tmp_path, declarations):
    config = {
        "timeout_seconds": 5,
        "seeds": [1],
        "external_algorithms": [str(declarations)],
        "algorithms": [{"name": "nn-chain", "parameters": {"neighbours": [1, 8]}}]
                      + [f"bad-{mode}" for mode in MISBEHAVING] + ["labeling"],
        "inputs": [{"family": "ellipse", "epsilon": [0.15, 0.3]}],
    }
    path = tmp_path / "config.json"
    path.write_text(json.dumps(config))
    return path


def test_a_sweep_gives_each_failure_its_row_and_goes_on(run, tmp_path, declarations):
    config = sweep_config(tmp_path, declarations)
    out = tmp_path / "results.jsonl"
    result = run("sweep", config, "--out", out, "--jobs", "2", "--memory-limit-mb", "200", "--quiet", timeout=120)
    assert result.returncode == 0, result.stderr
    rows = [json.loads(line) for line in out.read_text().splitlines()]
    assert len(rows) == 2 * (2 + len(MISBEHAVING) + 1)
    assert not (tmp_path / "results.jsonl.tmp").exists()  # killed runs' files removed with it
    by_algorithm = {}
    for row in rows:
        by_algorithm.setdefault(row["algorithm"], []).append(row)
    for row in by_algorithm["nn-chain"] + by_algorithm["labeling"]:
        assert row["status"] == "ok", row
        assert row["metrics"]["edge_recall"] > 0.9
    assert {row["parameters"]["neighbours"] for row in by_algorithm["nn-chain"]} == {1, 8}
    expected = {
        "crash": ("crash", "bad-crash: the program was killed by signal 6 (Aborted)"),
        "hang": ("timeout", "no result within 5 s"),
        "out-of-range": ("error", "bad-out-of-range: {output}:2: vertex index"),
        "malformed": ("error", "bad-malformed: {output}:2: 'two' is not a vertex index"),
        "nothing": ("error", "bad-nothing: the program exited normally but wrote nothing to {output}"),
        "memory": ("crash", "killed: resident memory over the limit of 200 MiB"),
        "json-cut": ("error", "bad-json-cut: {output}: not JSON: [json.exception.parse_error.101] parse error at line 3"),
        "json-out-of-range": ("error", "bad-json-out-of-range: {output}: curve.edges[1] is [1, "),
        "json-error": ("error", "bad-json-error: too few points for this method"),
    }
    for mode, (status, message) in expected.items():
        for row in by_algorithm[f"bad-{mode}"]:
            assert row["status"] == status and row["message"].startswith(message), row
    out_of_range = by_algorithm["bad-out-of-range"][0]
    assert f"{out_of_range['input_points']} is out of range" in out_of_range["message"]
    # bad-memory's rows show that the limit counts the program, a child of the run's process: the
    # run's own process holds far less than 200 MiB, the program 400 MiB


def test_an_external_algorithm_is_in_the_report(run, tmp_path, declarations):
    config = tmp_path / "config.json"
    config.write_text(json.dumps({
        "seeds": [1, 2], "external_algorithms": [str(declarations)], "algorithms": ["nn-chain", "labeling"],
        "inputs": [{"family": ["ellipse", "rose"], "epsilon": [0.2, 0.3]}]}))
    results = tmp_path / "results.jsonl"
    assert run("sweep", config, "--out", results, "--quiet", timeout=120).returncode == 0
    catalogue = tmp_path / "catalogue.json"
    listed = run("list", "--json", "--external", config)  # as main.sh writes it: the configuration's algorithms
    catalogue.write_text(listed.stdout)
    report = subprocess.run([sys.executable, "-m", "reports", "--out", tmp_path / "report", "--results", results,
                             "--catalogue", catalogue], cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert report.returncode == 0, report.stderr
    assert "nn-chain" in {entry["name"] for entry in json.loads(listed.stdout)}
    page = (tmp_path / "report" / "index.html").read_text()
    assert "nn-chain" in page
    assert "nn-chain" in (tmp_path / "report" / "success_vs_epsilon.svg").read_text()
