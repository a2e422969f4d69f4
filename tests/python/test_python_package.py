"""The Python package `curvebench` (harness/python/README.md): the same results, metrics and
files as the command line, for every algorithm; array-likes accepted, points read in place;
one-line ValueErrors; two threads at once give what one gives.

Runs with the venv's python, where the set-up installed the package."""
import json
import sys
import threading

import numpy as np
import pytest

import curvebench

ALGORITHMS = [entry["name"] for entry in curvebench.algorithms()]
# Sparse and a little noisy, so that interpolating and denoising methods both have work.
INPUT = ["--family", "rose", "--epsilon", "0.25", "--noise", "0.02", "--seed", "3"]
INPUT_SETTINGS = {"family": "rose", "epsilon": 0.25, "noise": 0.02, "seed": 3}


def edge_list(edges):
    """Edges as a list of pairs, the form the JSON holds."""
    return [list(e) for e in np.asarray(edges).reshape(-1, 2).tolist()]


def comparable(reconstruction_json):
    """The JSON without the figures that differ from run to run (the phase names stay)."""
    data = dict(reconstruction_json)
    data["timing_ms"] = sorted(data["timing_ms"])
    return data


def cli_error(result):
    """The message `curvebench` printed, without its `curvebench: error: ` prefix."""
    assert result.returncode != 0
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    prefix = "curvebench: error: "
    assert lines[0].startswith(prefix)
    return lines[0][len(prefix):]


@pytest.fixture(scope="module")
def cli_input(tmp_path_factory, curvebench_bin):
    import subprocess

    directory = tmp_path_factory.mktemp("input")
    points, truth = directory / "pts.xy", directory / "truth.json"
    subprocess.run([curvebench_bin, "generate", *INPUT, "--points", points, "--truth", truth], check=True, capture_output=True)
    return points, truth


def test_catalogue_is_list_json(run):
    result = run("list", "--json")
    assert result.returncode == 0, result.stderr
    assert curvebench.algorithms() == json.loads(result.stdout)
    assert "labeling" in ALGORITHMS and len(ALGORITHMS) >= 10


def test_generate_gives_the_files_of_the_command_line(cli_input, tmp_path):
    cli_points, cli_truth = cli_input
    points, truth = curvebench.generate(**INPUT_SETTINGS)
    assert points.dtype == np.float64 and points.shape[1] == 2
    np.testing.assert_array_equal(points, curvebench.read_points(cli_points))
    assert json.loads(truth.to_json()) == json.loads(cli_truth.read_text())
    curvebench.write_generated(points, truth, tmp_path / "p.xy", tmp_path / "t.json")
    assert (tmp_path / "p.xy").read_bytes() == cli_points.read_bytes()
    assert (tmp_path / "t.json").read_bytes() == cli_truth.read_bytes()
    assert len(truth.curves) == 1 and truth.closed == [True]
    assert truth.edges.shape == (len(points), 2)


@pytest.mark.parametrize("algorithm", ALGORITHMS)
def test_every_algorithm_gives_what_the_command_line_gives(run, cli_input, tmp_path, algorithm):
    points_path, truth_path = cli_input
    cli_json = tmp_path / "cli.json"
    result = run("reconstruct", "--algorithm", algorithm, "--input", points_path, "--output", cli_json)
    assert result.returncode == 0, result.stderr
    expected = json.loads(cli_json.read_text())

    points = curvebench.read_points(points_path)
    r = curvebench.reconstruct(points, algorithm=algorithm)
    assert comparable(json.loads(r.to_json(str(points_path)))) == comparable(expected)

    # The arrays themselves, against the command line's JSON.
    curve = expected.get("curve")
    if curve is None:
        assert r.edges is None
    else:
        assert edge_list(r.edges) == edge_list(curve["edges"])
        assert r.edges.dtype == np.int32 and r.edges.shape == (len(curve["edges"]), 2)
    for key in ("positions", "vertices"):
        value = getattr(r, key)
        if curve is None or key not in curve:
            assert value is None
        else:
            np.testing.assert_array_equal(value, np.array(curve[key]).reshape(-1, 2))
    if "medial_axis" in expected:
        axis = expected["medial_axis"]
        np.testing.assert_array_equal(r.medial_axis.vertices, np.array(axis["vertices"]).reshape(-1, 2))
        np.testing.assert_array_equal(r.medial_axis.radii, axis["radii"])
        np.testing.assert_array_equal(r.medial_axis.edges, np.array(axis["edges"]).reshape(-1, 2))
    else:
        assert r.medial_axis is None
    if "dominant_points" in expected:
        np.testing.assert_array_equal(r.dominant_points, expected["dominant_points"])
    else:
        assert r.dominant_points is None
    assert list(r.timing_ms) == list(expected["timing_ms"])
    assert r.parameters == expected["parameters"]

    # The metrics: the same values as `curvebench evaluate` on the command line's files.
    evaluated = run("evaluate", "--truth", truth_path, "--result", cli_json)
    assert evaluated.returncode == 0, evaluated.stderr
    cli_scores = json.loads(evaluated.stdout)
    truth = curvebench.read_ground_truth(truth_path)
    assert curvebench.evaluate(truth, r) == {key: cli_scores[key] for key in ("algorithm", "oracle_l2_error", "metrics")}


def test_written_files_are_what_the_command_line_reads(run, cli_input, tmp_path):
    points_path, truth_path = cli_input
    points, truth = curvebench.read_points(points_path), curvebench.read_ground_truth(truth_path)
    r = curvebench.reconstruct(points, algorithm="fitconnect")
    curvebench.write_reconstruction(tmp_path / "r.json", r, points_path)
    evaluated = run("evaluate", "--truth", truth_path, "--result", tmp_path / "r.json")
    assert evaluated.returncode == 0, evaluated.stderr
    assert json.loads(evaluated.stdout)["metrics"] == curvebench.evaluate(truth, r)["metrics"]

    back = curvebench.read_reconstruction(tmp_path / "r.json")  # reads the points file it names
    assert back.algorithm == "fitconnect" and back.input_path == str(points_path)
    np.testing.assert_array_equal(back.points, points)
    np.testing.assert_array_equal(back.edges, r.edges)
    np.testing.assert_array_equal(back.positions, r.positions)
    assert back.parameters == r.parameters
    assert curvebench.evaluate(truth, back) == curvebench.evaluate(truth, r)

    curvebench.write_points(tmp_path / "copy.xy", points, header="copied")
    assert (tmp_path / "copy.xy").read_text().startswith("# copied\n")
    np.testing.assert_array_equal(curvebench.read_points(tmp_path / "copy.xy"), points)


def test_c_contiguous_float64_is_read_in_place(cli_input):
    points = curvebench.read_points(cli_input[0])
    assert points.flags.c_contiguous and points.dtype == np.float64
    r = curvebench.reconstruct(points)
    assert np.shares_memory(r.points, points)
    assert not r.edges.flags.writeable  # a view of the result's own edges


def test_views_float32_and_lists_are_accepted(cli_input):
    points = curvebench.read_points(cli_input[0])
    reference = curvebench.reconstruct(points).edges  # labeling: its order does not depend on memory

    wide = np.zeros((len(points), 4))
    wide[:, ::2] = points
    strided = wide[:, ::2]
    assert not strided.flags.c_contiguous
    fortran = np.asfortranarray(points)
    assert not fortran.flags.c_contiguous
    for given in (strided, fortran, points.tolist(), [tuple(p) for p in points]):
        r = curvebench.reconstruct(given)
        np.testing.assert_array_equal(r.edges, reference)
        np.testing.assert_array_equal(r.points, points)

    # float32 points are other points: the result is that of their float64 values.
    single = points.astype(np.float32)
    r = curvebench.reconstruct(single)
    assert not np.shares_memory(r.points, single)
    np.testing.assert_array_equal(r.edges, curvebench.reconstruct(single.astype(np.float64)).edges)


@pytest.mark.parametrize(
    "points",
    [np.zeros((10, 3)), np.zeros(10), np.zeros((2, 5, 2)), [[0, 1], [2]], [["a", "b"], ["c", "d"]]],
    ids=["three columns", "one dimension", "three dimensions", "ragged", "strings"],
)
def test_points_that_are_not_n_by_2_numbers_are_a_value_error(points):
    with pytest.raises(ValueError, match=r"points must be an \(n, 2\) array of numbers"):
        curvebench.reconstruct(points)


def test_nan_is_a_value_error():
    points = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [np.nan, 2.0]])
    with pytest.raises(ValueError) as error:
        curvebench.reconstruct(points)
    assert str(error.value) == "labeling: point 3 has a coordinate that is not a finite number"


def test_errors_are_the_command_lines_messages(run, cli_input, tmp_path):
    points_path = cli_input[0]
    points = curvebench.read_points(points_path)
    cases = [
        ("labeling", ["--param", "no_such=1"], {"no_such": 1}),
        ("hnn-crust", ["--param", "k_max=1"], {"k_max": 1}),
        ("alpha-shape", ["--param", "components=maybe"], {"components": "maybe"}),
        ("no-such-algorithm", [], {}),
    ]
    for algorithm, cli_args, parameters in cases:
        expected = cli_error(run("reconstruct", "--algorithm", algorithm, "--input", points_path, *cli_args))
        with pytest.raises(ValueError) as error:
            curvebench.reconstruct(points, algorithm=algorithm, **parameters)
        assert str(error.value) == expected

    # Input errors: the command line puts the file name first.
    two = tmp_path / "two.xy"
    two.write_text("0 0\n1 1\n")
    expected = cli_error(run("reconstruct", "--input", two))
    with pytest.raises(ValueError) as error:
        curvebench.reconstruct([[0, 0], [1, 1]])
    assert expected == f"{two}: {error.value}"

    bad = tmp_path / "bad.xy"
    bad.write_text("0 0\n1 x\n")
    expected = cli_error(run("reconstruct", "--input", bad))
    with pytest.raises(ValueError) as error:
        curvebench.read_points(bad)
    assert str(error.value) == expected

    with pytest.raises(ValueError, match="no-such-family"):
        curvebench.generate(family="no-such-family")


def test_two_threads_at_once_give_what_one_gives():
    points, _ = curvebench.generate(family="rose", sampler="random", count=20000, noise=0.001, seed=5)
    algorithms = ["labeling", "crust", "fitconnect"]
    alone = {name: curvebench.reconstruct(points, algorithm=name) for name in algorithms}
    results = {}
    start = threading.Barrier(2)

    def work(thread):
        start.wait()
        results[thread] = {name: curvebench.reconstruct(points, algorithm=name) for name in algorithms}

    threads = [threading.Thread(target=work, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for thread in range(2):
        for name in algorithms:
            assert edge_list(results[thread][name].edges) == edge_list(alone[name].edges)
            np.testing.assert_array_equal(results[thread][name].points, points)
    np.testing.assert_array_equal(results[0]["fitconnect"].positions, alone["fitconnect"].positions)
    np.testing.assert_array_equal(results[1]["labeling"].medial_axis.vertices, alone["labeling"].medial_axis.vertices)


def test_the_gil_is_released_while_the_algorithm_runs():
    """With a switch interval far beyond the test's length, a thread that holds the GIL keeps
    it until it gives it up; the main thread, waiting for the worker to start, can therefore
    only run before the worker is done if reconstruct gives the GIL up."""
    points, _ = curvebench.generate(family="rose", sampler="random", count=50000, seed=6)
    started = threading.Event()
    state = {"done": False}

    def work():
        started.set()
        curvebench.reconstruct(points)
        state["done"] = True

    interval = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    try:
        worker = threading.Thread(target=work)
        worker.start()
        started.wait()
        done_when_main_ran = state["done"]
        worker.join()
    finally:
        sys.setswitchinterval(interval)
    assert state["done"] and not done_when_main_ran


def test_type_stubs_ship():
    import pathlib

    package = pathlib.Path(curvebench.__file__).parent
    assert (package / "py.typed").exists()
    stub = (package / "_curvebench.pyi").read_text()
    assert "class Reconstruction" in stub and "def reconstruct(" in stub
