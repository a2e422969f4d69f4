"""`curvebench reconstruct` and `curvebench list` end to end: every awkward input gives a
correct result or a one-line error with a nonzero exit, never a crash, hang or partial file."""
import json
import math

import pytest


def write(tmp_path, text, name="pts.xy", mode="w"):
    path = tmp_path / name
    with open(path, mode, newline="") as f:
        f.write(text)
    return path


def circle_text(n, sep=" ", end="\n", extra=""):
    lines = []
    for k in range(n):
        t = 2 * math.pi * k / n
        lines.append(f"{math.cos(t)!r}{sep}{math.sin(t)!r}{extra}")
    return end.join(lines) + end


def cycle(n):
    return sorted(sorted([k, (k + 1) % n]) for k in range(n))


def test_list_names_every_algorithm_and_its_outputs(run):
    result = run("list")
    assert result.returncode == 0
    assert "labeling" in result.stdout
    assert "produces: curve, medial axis, dominant points" in result.stdout
    entries, name = {}, None  # the indented lines under each algorithm's name
    for line in result.stdout.splitlines():
        if not line.startswith(" "):
            name = line
        entries.setdefault(name, []).append(line.strip())
    assert "takes collinear input" in entries["crawl"] and "takes collinear input" not in entries["labeling"]


def test_reconstruct_writes_json_and_svg(run, tmp_path):
    pts = write(tmp_path, circle_text(40))
    out, svg = tmp_path / "r.json", tmp_path / "r.svg"
    result = run("reconstruct", "--algorithm", "labeling", "--input", pts, "--output", out, "--svg", svg)
    assert result.returncode == 0, result.stderr
    data = json.loads(out.read_text())
    assert data["status"] == "ok"
    assert data["algorithm"] == "labeling"
    assert data["input"] == {"path": str(pts), "points": 40, "distinct_points": 40}
    assert sorted(data["curve"]["edges"]) == cycle(40)
    assert len(data["medial_axis"]["vertices"]) == len(data["medial_axis"]["radii"])
    assert set(data["timing_ms"]) == {"delaunay", "labeling", "extract", "total"}
    text = svg.read_text()
    assert text.startswith("<svg") and text.rstrip().endswith("</svg>")
    assert not list(tmp_path.glob("*.partial"))


@pytest.mark.parametrize(
    "label,text",
    [
        ("LF", circle_text(30)),
        ("CRLF", circle_text(30, end="\r\n")),
        ("CR", circle_text(30, end="\r")),
        ("tabs", circle_text(30, sep="\t")),
        ("commas", circle_text(30, sep=",")),
        ("third column", circle_text(30, extra=" 7.5")),
        ("comments", "# a header\n" + circle_text(30).replace("\n", " # note\n", 3)),
    ],
)
def test_accepted_formats_give_the_same_curve(run, tmp_path, label, text):
    pts = write(tmp_path, text)
    result = run("reconstruct", "--input", pts)
    assert result.returncode == 0, f"{label}: {result.stderr}"
    assert sorted(json.loads(result.stdout)["curve"]["edges"]) == cycle(30)


def test_duplicates_map_to_first_occurrence(run, tmp_path):
    lines = circle_text(12).splitlines()
    lines.insert(5, lines[0])  # index 5 duplicates index 0
    pts = write(tmp_path, "\n".join(lines) + "\n")
    data = json.loads(run("reconstruct", "--input", pts).stdout)
    assert data["input"]["points"] == 13 and data["input"]["distinct_points"] == 12
    used = {i for e in data["curve"]["edges"] for i in e}
    assert 5 not in used and 0 in used and len(data["curve"]["edges"]) == 12


@pytest.mark.parametrize(
    "label,text,message",
    [
        ("empty file", "", "pts.xy: labeling needs at least 3 distinct points, the input has 0"),
        ("one point", "1 2\n", "the input has 1"),
        ("two distinct points", "1 2\n3 4\n1 2\n", "the input has 2"),
        ("collinear", "0 0\n1 1\n2 2\n3 3\n", "all 4 distinct points are collinear"),
        ("non-numeric", "0 0\n1 x\n", "pts.xy:2: 'x' is not a number"),
        ("NaN", "0 0\n1 0\nnan 1\n", "pts.xy:3: coordinate 'nan' is not finite"),
        ("infinite", "0 0\n1 0\n0 -inf\n", "pts.xy:3: coordinate '-inf' is not finite"),
        ("one number", "0 0\n1 0\n\n7\n", "pts.xy:4: expected two coordinates 'x y', found one"),
    ],
)
def test_bad_input_is_one_line_error_and_no_partial_output(run, tmp_path, label, text, message):
    pts = write(tmp_path, text)
    out, svg = tmp_path / "r.json", tmp_path / "r.svg"
    result = run("reconstruct", "--input", pts, "--output", out, "--svg", svg)
    assert result.returncode != 0, label
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, f"{label}: {result.stderr!r}"
    assert message in lines[0], f"{label}: {lines[0]}"
    assert str(pts) in lines[0]
    data = json.loads(out.read_text())  # a complete error record, never a partial file
    assert data["status"] == "error" and message in data["message"]
    assert not svg.exists()
    assert not list(tmp_path.glob("*.partial"))


def test_missing_input_file_and_unknown_algorithm(run, tmp_path):
    result = run("reconstruct", "--input", tmp_path / "nope.xy")
    assert result.returncode != 0 and "cannot open" in result.stderr
    pts = write(tmp_path, circle_text(10))
    result = run("reconstruct", "--algorithm", "nope", "--input", pts)
    assert result.returncode != 0 and "unknown algorithm 'nope'" in result.stderr
    result = run("reconstruct", "--input", pts, "--param", "alpha=1")
    assert result.returncode != 0 and "algorithm 'labeling' has no parameter 'alpha'" in result.stderr
    result = run("reconstruct", "--algorithm", "alpha-shape", "--input", pts, "--param", "alpha=abc")
    assert result.returncode != 0
    assert "algorithm 'alpha-shape': parameter 'alpha' must be a real number >= 0" in result.stderr
    assert "(got abc)" in result.stderr
    result = run("reconstruct", "--algorithm", "alpha-shape", "--input", pts, "--param", "components=1.5")
    assert result.returncode != 0 and "parameter 'components' must be a whole number >= 1" in result.stderr
