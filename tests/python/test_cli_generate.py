"""`curvebench generate` end to end: the same command and seed give the same bytes, the
ground truth matches the points file, and bad settings give a one-line error, a nonzero
exit and no file."""
import json
import math

import pytest


def generate(run, tmp_path, *args, name="g"):
    points, truth = tmp_path / f"{name}.xy", tmp_path / f"{name}.json"
    result = run("generate", *args, "--points", points, "--truth", truth)
    return result, points, truth


def read_points(path):
    rows = [line.split() for line in path.read_text().splitlines() if line and not line.startswith("#")]
    return [(float(x), float(y)) for x, y in rows]


@pytest.mark.parametrize(
    "args",
    [
        ["--family", "rose", "--epsilon", "0.2", "--seed", "3"],
        ["--family", "disjoint", "--shape", "count=3", "--sampler", "random", "--count", "300", "--noise", "0.05",
         "--outliers", "0.2", "--seed", "8"],
        ["--family", "star", "--sampler", "uniform", "--count", "120", "--noise", "0.002", "--noise-scale", "diagonal"],
    ],
)
def test_same_command_and_seed_give_the_same_bytes(run, tmp_path, args):
    first, p1, t1 = generate(run, tmp_path, *args, name="a")
    second, p2, t2 = generate(run, tmp_path, *args, name="b")
    assert first.returncode == 0 and second.returncode == 0, first.stderr + second.stderr
    assert p1.read_bytes() == p2.read_bytes()
    assert t1.read_bytes() == t2.read_bytes()


def test_another_seed_gives_other_points(run, tmp_path):
    _, p1, _ = generate(run, tmp_path, "--family", "random", "--seed", "1", name="a")
    _, p2, _ = generate(run, tmp_path, "--family", "random", "--seed", "2", name="b")
    assert p1.read_bytes() != p2.read_bytes()


def test_truth_matches_points(run, tmp_path):
    result, points, truth = generate(run, tmp_path, "--family", "ellipse", "--epsilon", "0.3", "--outliers", "0.25", "--seed", "4")
    assert result.returncode == 0, result.stderr
    data = json.loads(truth.read_text())
    pts = read_points(points)
    assert data["format"] == "curvebench-ground-truth/1"
    assert data["generator"]["seed"] == 4 and data["generator"]["epsilon"] == 0.3
    assert data["points"] == len(pts) == len(data["samples"])
    outliers = [i for i, s in enumerate(data["samples"]) if s["curve"] == "outlier"]
    on_curve = len(pts) - len(outliers)
    assert len(outliers) == round(0.25 * on_curve)
    assert len(data["edges"]) == on_curve  # one cycle
    # Without noise each curve sample lies on the ellipse x^2/4 + y^2 = 1.
    for i, s in enumerate(data["samples"]):
        if s["curve"] != "outlier":
            x, y = pts[i]
            assert abs(x * x / 4 + y * y - 1) < 1e-6
            assert 0 <= s["parameter"] < 1 and s["lfs"] > 0
    # Exact medial axis of the ellipse: the segment |x| <= 1.5, and the two major-axis ends dominant.
    xs = [v[0] for v in data["medial_axis"]["vertices"]]
    assert min(xs) == -1.5 and max(xs) == 1.5
    assert sorted(p[0] for p in data["dominant_points"]) == pytest.approx([-2, 2])


def test_every_family_generates(run, tmp_path):
    for family in ["circle", "ellipse", "superellipse", "rose", "random", "dumbbell", "concavities", "disjoint", "nested", "holes",
                   "star", "square", "l-shape", "horned"]:
        result, points, truth = generate(run, tmp_path, "--family", family, "--epsilon", "0.4", "--dense", "2048", name=family)
        assert result.returncode == 0, family + ": " + result.stderr
        data = json.loads(truth.read_text())
        assert data["points"] == len(read_points(points)) >= 3


@pytest.mark.parametrize(
    "args, message",
    [
        (["--epsilon", "0"], "--epsilon: must be > 0"),
        (["--epsilon", "-0.5"], "--epsilon: must be > 0"),
        (["--noise", "abc"], "--noise: 'abc' is not a number"),
        (["--noise", "nan"], "--noise: 'nan' is not a number"),
        (["--family", "nope"], "--family: unknown family 'nope'"),
        (["--family", "rose", "--shape", "b=2"], "rose: need a > |b|"),
        (["--family", "star", "--shape", "points=2.5"], "--shape points: '2.5' is not an integer"),
        (["--sampler", "uniform", "--count", "2"], "--count: '2' is not an integer"),
    ],
)
def test_bad_settings_give_one_line_and_no_file(run, tmp_path, args, message):
    result, points, truth = generate(run, tmp_path, *args)
    assert result.returncode != 0
    assert message in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert not points.exists() and not truth.exists()


def real_outlines(*args):
    import subprocess
    import sys
    from pathlib import Path

    script = Path(__file__).resolve().parents[2] / "generators" / "real_outlines.py"
    return subprocess.run([sys.executable, str(script), *map(str, args)], capture_output=True, text=True, timeout=120)


def test_glyph_outlines_are_the_default_real_shapes(run, tmp_path):
    result = real_outlines("glyphs", "--out", tmp_path / "glyphs", "--chars", "B8&")
    assert result.returncode == 0, result.stderr
    curves = {}
    for rings in sorted((tmp_path / "glyphs").glob("*.rings")):
        generated, points, truth = generate(run, tmp_path, "--family", "outline", "--input", rings, "--epsilon", "0.3",
                                            name=rings.stem)
        assert generated.returncode == 0, generated.stderr
        curves[rings.stem] = len(json.loads(truth.read_text())["curves"])
    assert curves == {"glyph_0042": 3, "glyph_0038": 3, "glyph_0026": 2}  # B and 8: two holes; &: one


def test_real_outlines_help_prints_for_every_command():
    # argparse formats help texts with %: the default glyphs include a '%'.
    for command in ([], ["glyphs"], ["png"]):
        result = real_outlines(*command, "--help")
        assert result.returncode == 0, result.stderr
        assert "usage:" in result.stdout


def test_png_silhouette_traced_with_holes(run, tmp_path):
    import numpy as np
    import matplotlib.pyplot as plt

    y, x = np.mgrid[0:120, 0:160]
    r = np.hypot(x - 80, y - 60)
    plt.imsave(tmp_path / "ring.png", 1 - ((r < 50) & (r > 20)).astype(float), cmap="gray")
    result = real_outlines("png", tmp_path / "ring.png", "--out", tmp_path / "ring.rings")
    assert result.returncode == 0, result.stderr
    generated, _, truth = generate(run, tmp_path, "--family", "outline", "--input", tmp_path / "ring.rings")
    assert generated.returncode == 0, generated.stderr
    assert len(json.loads(truth.read_text())["curves"]) == 2  # outer contour and hole

    plt.imsave(tmp_path / "blank.png", np.ones((40, 40)), cmap="gray")
    blank = real_outlines("png", tmp_path / "blank.png", "--out", tmp_path / "blank.rings")
    assert blank.returncode == 1 and "no shape in the image" in blank.stderr
    assert not (tmp_path / "blank.rings").exists()


def test_self_intersecting_outline_is_an_error(run, tmp_path):
    (tmp_path / "bow.rings").write_text("0 0\n2 2\n2 0\n0 2\n")
    result, points, truth = generate(run, tmp_path, "--family", "outline", "--input", tmp_path / "bow.rings")
    assert result.returncode != 0 and "not simple" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert not points.exists() and not truth.exists()
