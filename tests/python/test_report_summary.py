"""The summary's statistics on hand-made sweep rows whose winners are known: medians, quartiles,
shares near the best and head-to-head counts; a run with an extreme value that must not change a
verdict; the conditions derived from the settings; default and best-of-grid labelling; FOM from
the medians of CR and ISE."""
import pathlib
import statistics
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))  # the reports package lives at the repository root

from reports.conditions import condition_rows  # noqa: E402
from reports.parameter_settings import default_rows, use_catalogue_defaults  # noqa: E402
from reports.scaling_results import ScalingRun, ScalingSuite  # noqa: E402
from reports.summary_table import condition_summaries, dominant_points_line, speed_lines  # noqa: E402
from reports.sweep_results import row_from_json  # noqa: E402


def row(algorithm, settings, metrics=None, status="ok", parameters=None):
    data = {"algorithm": algorithm, "parameters": parameters or {}, "input": settings, "input_points": 100,
            "status": status}
    if status == "ok":
        data.update({"metrics": {"true_curves": 1, **(metrics or {})}, "timing_ms": {"total": 1.0}})
    result = row_from_json(data)
    result.true_curves = int(result.metric("true_curves")) if result.ok else None  # as read_sweep_rows shares it
    return result


NOISY = [{"family": "ellipse", "epsilon": 0.1, "noise": 0.05, "seed": seed} for seed in range(1, 11)]


def noisy_rows(l2_of, recall_of=None):
    """Every algorithm of l2_of on the ten noisy inputs; l2_of[a](i) is its L2 error on input i."""
    rows = []
    for i, settings in enumerate(NOISY):
        for algorithm, l2 in l2_of.items():
            metrics = {"l2_error": l2(i), "hausdorff": 0.01}
            if recall_of is not None:
                metrics["curve_recall"] = recall_of[algorithm](i)
            rows.append(row(algorithm, settings, metrics))
    return rows


def summary_of(rows, name):
    return next(s for s in condition_summaries(rows) if s.name == name)


def line_of(summary, measure):
    return next(line for line in summary.lines if line.measure == measure)


def test_known_winner_with_medians_quartiles_shares_and_head_to_head():
    rows = noisy_rows({"labeling": lambda i: 0.01 + 0.001 * i, "crust": lambda i: 0.05 + 0.001 * i,
                       "nn-crust": lambda i: 0.30})
    noise = summary_of(rows, "Noise")
    assert (noise.runs, noise.inputs) == (30, 10)
    l2 = line_of(noise, "L2 error")
    assert (l2.best, l2.runner_up, l2.separated) == ("labeling", "crust", True)
    assert l2.comparison.ranking == ["labeling", "crust", "nn-crust"]
    best = l2.comparison.statistics["labeling"]
    assert best.median == pytest.approx(0.0145)  # 0.010 ... 0.019
    assert (best.lower_quartile, best.upper_quartile) == (pytest.approx(0.01225), pytest.approx(0.01675))
    assert best.within_tolerance == 1.0 and l2.comparison.statistics["crust"].within_tolerance == 0.0
    head_to_head = l2.comparison.pairs[("labeling", "crust")]
    assert (head_to_head.wins, head_to_head.losses, head_to_head.ties) == (10, 0, 0)
    assert "30 runs of 3 methods on 10 inputs" == l2.runs_text
    # Hausdorff is the same for all: not separated, and the row says so.
    hausdorff = line_of(noise, "Hausdorff / diagonal")
    assert not hausdorff.separated and hausdorff.verdict.startswith("not separated")
    assert noise.agreement == "The metrics agree: labeling leads on every metric (separated on L2 error)."


def test_metrics_that_name_different_winners_are_reported_as_disagreeing():
    rows = noisy_rows({"labeling": lambda i: 0.01, "crust": lambda i: 0.2},
                      recall_of={"labeling": lambda i: 0.5, "crust": lambda i: 0.99})
    noise = summary_of(rows, "Noise")
    assert line_of(noise, "L2 error").best == "labeling" and line_of(noise, "curve recall").best == "crust"
    assert noise.agreement == ("The metrics disagree: L2 error: labeling; curve recall: crust; "
                               "Hausdorff / diagonal: crust, labeling (tie).")


def test_one_extreme_run_does_not_change_the_verdict():
    l2_of = {"labeling": lambda i: 1e9 if i == 0 else 0.01, "crust": lambda i: 0.05}
    rows = noisy_rows(l2_of)
    # A mean would hand the verdict to crust: the fixture has teeth.
    assert statistics.mean(l2_of["labeling"](i) for i in range(10)) > statistics.mean(
        l2_of["crust"](i) for i in range(10))
    l2 = line_of(summary_of(rows, "Noise"), "L2 error")
    assert (l2.best, l2.separated) == ("labeling", True)
    assert l2.comparison.statistics["labeling"].median == pytest.approx(0.01)
    head_to_head = l2.comparison.pairs[("labeling", "crust")]
    assert (head_to_head.wins, head_to_head.losses) == (9, 1)


def test_a_failed_run_counts_as_the_worst_value():
    rows = noisy_rows({"labeling": lambda i: 0.01, "crust": lambda i: 0.02})
    rows = [row("crust", r.settings, status="crash") if r.algorithm == "crust" and r.seed <= 6 else r for r in rows]
    l2 = line_of(summary_of(rows, "Noise"), "L2 error")
    crust = l2.comparison.statistics["crust"]
    assert (crust.runs, crust.failed) == (10, 6)
    assert crust.median == float("inf") and "failed" in l2.cells["crust"]
    assert l2.comparison.pairs[("labeling", "crust")].wins == 6  # a tie within 0.01 elsewhere


def test_methods_within_tolerance_everywhere_are_not_separated_and_the_row_says_why():
    rows = noisy_rows({"labeling": lambda i: 0.010, "labeling-holes": lambda i: 0.011, "crust": lambda i: 0.5})
    l2 = line_of(summary_of(rows, "Noise"), "L2 error")
    assert not l2.separated
    assert "not separated: labeling is not better than labeling-holes on 3 more" in l2.verdict
    assert "ahead of crust" in l2.verdict


def test_a_metric_a_method_never_defines_leaves_it_out_instead_of_scoring_it_zero():
    rows = noisy_rows({"labeling": lambda i: 0.01, "optimal-transport": lambda i: 0.02})
    for r in rows:
        if r.algorithm == "labeling":
            r.metrics["edge_f1"] = 0.9
        else:
            r.metrics["edge_f1"] = None  # vertices of its own: JSON null
    f1 = line_of(summary_of(rows, "Noise"), "edge F1")
    assert set(f1.comparison.statistics) == {"labeling"}
    assert f1.verdict == "not separated: only labeling reports it here"


def test_conditions_follow_the_stated_rules():
    rows = [row("crust", {"family": "rose", "epsilon": e, "seed": 1}) for e in (0.1, 0.2, 0.3, 0.4, 0.5, 0.6)]
    rows += [row("crust", {"family": "star", "epsilon": 0.2, "seed": 1}),
             row("crust", {"family": "disjoint", "epsilon": 0.2, "seed": 1}, {"true_curves": 3}),
             row("crust", {"family": "nested", "epsilon": 0.2, "seed": 1}, {"true_curves": 2}),
             row("crust", {"family": "spiral", "epsilon": 0.2, "seed": 1}),
             row("crust", {"family": "outline", "input": "g.rings", "sampler": "random", "count": 100, "seed": 1}),
             row("crust", {"family": "star", "epsilon": 0.2, "noise": 0.1, "seed": 1}),
             row("crust", {"family": "star", "epsilon": 0.2, "noise": 0.1, "outliers": 0.2, "seed": 1})]
    found = {name: [(r.family, r.epsilon, r.noise, r.outliers) for r in chosen]
             for name, chosen in condition_rows(rows).items()}
    assert found == {
        "Sparse sampling": [("rose", 0.5, 0, 0), ("rose", 0.6, 0, 0)],  # the sparsest third of six levels
        "Dense sampling": [("rose", 0.1, 0, 0), ("rose", 0.2, 0, 0)],
        "Noise": [("star", 0.2, 0.1, 0)],
        "Outliers": [("star", 0.2, 0.1, 0.2)],
        "Sharp corners": [("star", 0.2, 0, 0)],
        "Several curves": [("disjoint", 0.2, 0, 0)],
        "Nested curves": [("nested", 0.2, 0, 0)],
        "Open curves": [("spiral", 0.2, 0, 0)],
        "Real outlines": [("outline", None, 0, 0)],
    }


ALPHA_CATALOGUE = [{"name": "alpha-shape", "parameters": [{"name": "alpha", "default": 0.0},
                                                          {"name": "components", "default": 1}]}]


def grid_rows():
    """alpha-shape at alpha = 0 (its default), 0.02 and 0.08: 0.02 wins under noise, the default
    on sharp corners."""
    rows = []
    for seed in (1, 2, 3):
        for alpha, noisy_l2, corner_l2 in ((0.0, 0.2, 0.01), (0.02, 0.03, 0.3), (0.08, 0.1, 0.4)):
            parameters = {"alpha": alpha, "components": 1}
            rows.append(row("alpha-shape", {"family": "rose", "noise": 0.1, "seed": seed}, {"l2_error": noisy_l2},
                            parameters=parameters))
            rows.append(row("alpha-shape", {"family": "star", "seed": seed}, {"l2_error": corner_l2},
                            parameters=parameters))
        rows.append(row("crust", {"family": "rose", "noise": 0.1, "seed": seed}, {"l2_error": 0.05}))
        rows.append(row("crust", {"family": "star", "seed": seed}, {"l2_error": 0.05}))
    return rows


@pytest.fixture
def alpha_catalogue():
    use_catalogue_defaults(ALPHA_CATALOGUE)
    yield
    use_catalogue_defaults([])


def test_a_grid_is_shown_at_its_default_and_at_its_best_setting_labelled_with_the_value(alpha_catalogue):
    rows = grid_rows()
    noise = summary_of(rows, "Noise")
    assert [v.label for v in noise.variants] == ["alpha-shape (default)", "alpha-shape (alpha=0.02; best of 3)",
                                                 "crust"]
    l2 = line_of(noise, "L2 error")
    assert l2.best == "alpha-shape (alpha=0.02; best of 3)" and l2.runner_up == "crust"
    assert l2.comparison.statistics["alpha-shape (default)"].median == pytest.approx(0.2)
    corners = summary_of(rows, "Sharp corners")
    assert [v.label for v in corners.variants] == ["alpha-shape (default, best of 3 settings)", "crust"]
    assert {r.parameters["alpha"] for r in default_rows(rows) if r.algorithm == "alpha-shape"} == {0.0}


def test_a_grid_without_a_catalogue_is_a_clear_error():
    with pytest.raises(ValueError, match="3 parameter settings of alpha-shape: give --catalogue"):
        condition_summaries(grid_rows())


def dominant_rows():
    """labeling: one run with ISE near 0 makes its mean FOM huge, but its median ISE is 1;
    labeling-holes: the same CR with ISE 0.5 on every run."""
    rows = []
    for seed in range(1, 6):
        settings = {"family": "star", "seed": seed}
        ise = 1e-6 if seed == 1 else 1.0
        rows.append(row("labeling", settings, {"compression_ratio": 10.0, "integral_square_error": ise,
                                               "figure_of_merit": 10.0 / ise}))
        rows.append(row("labeling-holes", settings, {"compression_ratio": 10.0, "integral_square_error": 0.5,
                                                     "figure_of_merit": 20.0}))
    return rows


def test_fom_comes_from_the_medians_of_cr_and_ise_not_from_a_mean_of_ratios():
    rows = dominant_rows()
    mean_fom = {a: statistics.mean(r.metric("figure_of_merit") for r in rows if r.algorithm == a)
                for a in ("labeling", "labeling-holes")}
    assert mean_fom["labeling"] > mean_fom["labeling-holes"]  # what the mean would say
    line = dominant_points_line(rows)
    assert (line.best, line.runner_up, line.separated) == ("labeling-holes", "labeling", True)
    assert line.cells["labeling"].startswith("FOM 10 = CR 10 [10, 10] / ISE 1 [1, 1]")
    assert line.cells["labeling-holes"].startswith("FOM 20 = CR 10 [10, 10] / ISE 0.5 [0.5, 0.5]")
    head_to_head = line.comparison.pairs[("labeling-holes", "labeling")]
    assert (head_to_head.wins, head_to_head.losses) == (4, 1)


def test_a_lead_one_run_could_reverse_does_not_separate():
    # labeling is better on two inputs and ties on the rest: turning one of them into a loss
    # would leave 1 to 1, so the lead of 2 does not separate.
    rows = noisy_rows({"labeling": lambda i: 0.01, "crust": lambda i: 0.05 if i < 2 else 0.01})
    l2 = line_of(summary_of(rows, "Noise"), "L2 error")
    assert l2.best == "labeling" and not l2.separated
    assert "better on 2, worse on 0 of 10 shared inputs" in l2.verdict


def test_a_grid_whose_settings_tie_is_shown_at_its_default(alpha_catalogue):
    rows = [row("alpha-shape", {"family": "rose", "outliers": 0.1, "seed": seed}, {"l2_error": 0.1},
                parameters={"alpha": alpha, "components": 1}) for seed in (1, 2) for alpha in (0.5, 0.0)]
    assert [v.label for v in summary_of(rows, "Outliers").variants] == ["alpha-shape (default, best of 2 settings)"]


def test_grid_settings_are_compared_on_the_inputs_they_all_ran(alpha_catalogue):
    # The default runs on six inputs, three of them hard; alpha = 0.02 only on the three easy
    # ones, where it is worse than the default. Over its own runs its median would look better.
    rows = []
    for seed in range(1, 7):
        settings = {"family": "rose", "noise": 0.1, "seed": seed}
        rows.append(row("alpha-shape", settings, {"l2_error": 0.5 if seed > 3 else 0.01},
                        parameters={"alpha": 0.0, "components": 1}))
        if seed <= 3:
            rows.append(row("alpha-shape", settings, {"l2_error": 0.05}, parameters={"alpha": 0.02, "components": 1}))
    noise = summary_of(rows, "Noise")
    assert [v.label for v in noise.variants] == ["alpha-shape (default, best of 2 settings)"]
    assert len(noise.variants[0].rows) == 6


def test_a_best_setting_run_on_fewer_inputs_says_on_how_many(alpha_catalogue):
    rows = []
    for seed in range(1, 7):
        settings = {"family": "rose", "noise": 0.1, "seed": seed}
        rows.append(row("alpha-shape", settings, {"l2_error": 0.3}, parameters={"alpha": 0.0, "components": 1}))
        if seed <= 3:
            rows.append(row("alpha-shape", settings, {"l2_error": 0.05}, parameters={"alpha": 0.02, "components": 1}))
    l2 = line_of(summary_of(rows, "Noise"), "L2 error")
    tuned = "alpha-shape (alpha=0.02; best of 2)"
    assert l2.cells[tuned].endswith("(on 3 of the 6 inputs); the default on the same 3 inputs: median 0.3")
    assert l2.default_on_same_inputs == {tuned: pytest.approx(0.3)}
    assert l2.best == "alpha-shape (default)"  # the tuned setting covers too few inputs to be ranked


def suite_of(times_by_algorithm):
    runs = [ScalingRun(algorithm, "smooth", 1000, seconds=0.01, times_delaunay=t, peak_mib=5.0, input_mib=4.0)
            for algorithm, times in times_by_algorithm.items() for t in times]
    return ScalingSuite(runs, {}, pathlib.Path("scaling.json"))


def test_speed_is_separated_only_by_repetitions_that_do_not_overlap():
    speed = speed_lines(suite_of({"labeling": [1.2], "crust": [1.5]}))[0]
    assert (speed.best, speed.runner_up, speed.separated) == ("labeling", "crust", False)
    assert "one measured run each" in speed.verdict
    apart = speed_lines(suite_of({"labeling": [1.2, 1.25, 1.3], "crust": [1.5, 1.6, 1.4]}))[0]
    assert apart.separated and apart.cells["labeling"] == "1.25x"
    overlapping = speed_lines(suite_of({"labeling": [1.2, 1.25, 1.6], "crust": [1.5, 1.6, 1.4]}))[0]
    assert overlapping.best == "labeling" and not overlapping.separated


def test_a_method_scored_on_few_inputs_is_shown_but_not_ranked():
    # labeling leaves its five hard inputs undefined (null) and has the lower median over the
    # five easy ones it scores; crust, scored everywhere, is best.
    rows = noisy_rows({"labeling": lambda i: 0.02, "crust": lambda i: 0.005 if i < 5 else 0.5})
    for r in rows:
        if r.algorithm == "labeling" and r.seed > 5:
            r.metrics["l2_error"] = None
    l2 = line_of(summary_of(rows, "Noise"), "L2 error")
    assert l2.comparison.ranking[0] == "labeling" and "labeling" in l2.cells
    assert (l2.best, l2.runner_up) == ("crust", None)
    assert "labeling has a better median on only 5 of the 10 inputs, too few to rank (at least 90%)" in l2.verdict


def test_a_method_beaten_head_to_head_is_not_best_whatever_its_median():
    # labeling's median (0.025) is below crust's (0.03), but crust is better by more than the
    # tolerance on three inputs and within it on the rest.
    rows = noisy_rows({"labeling": lambda i: 0.025, "crust": lambda i: 0.0 if i < 3 else 0.03})
    l2 = line_of(summary_of(rows, "Noise"), "L2 error")
    assert l2.comparison.ranking[0] == "labeling"
    assert (l2.best, l2.runner_up, l2.separated) == ("crust", "labeling", True)
    assert "labeling has the better median but is not best: crust is better on 3, worse on 0" in l2.verdict


def test_a_grid_method_with_one_setting_under_a_condition_says_so(alpha_catalogue):
    rows = grid_rows() + [row("alpha-shape", {"family": "rose", "outliers": 0.1, "seed": 1}, {"l2_error": 0.1},
                              parameters={"alpha": 0.0, "components": 1})]
    assert [v.label for v in summary_of(rows, "Outliers").variants] == ["alpha-shape (default; no grid here)"]


def test_agreement_counts_only_ranked_methods(alpha_catalogue):
    rows = []
    for seed in range(1, 7):
        settings = {"family": "rose", "noise": 0.1, "seed": seed}
        rows.append(row("crust", settings, {"l2_error": 0.05}))
        rows.append(row("alpha-shape", settings, {"l2_error": 0.3}, parameters={"alpha": 0.0, "components": 1}))
        if seed <= 3:  # better than crust, but on too few inputs to be ranked
            rows.append(row("alpha-shape", settings, {"l2_error": 0.01}, parameters={"alpha": 0.02, "components": 1}))
    noise = summary_of(rows, "Noise")
    assert line_of(noise, "L2 error").best == "crust"
    assert noise.agreement == "The metrics agree: crust leads on every metric (separated on L2 error)."
