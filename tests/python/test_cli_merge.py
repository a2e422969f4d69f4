"""`curvebench merge`: the shards of a sweep (`--shard i/n`) merge into the rows of the whole sweep,
in plan order; a missing, duplicated or unplanned run fails the merge, naming it."""
import json

import pytest

CONFIG = {"seeds": [1, 2], "algorithms": ["labeling", "crust", {"name": "alpha-shape", "parameters": {"alpha": [1, 2]}}],
          "inputs": [{"family": ["ellipse", "rose"], "epsilon": [0.2, 0.3]}]}
MEASUREMENTS = ("timing_ms", "evaluate_ms", "wall_ms", "peak_memory_kb")
RUNS = 2 * 2 * 2 * 4


def without_measurements(path):
    rows = [json.loads(line) for line in path.read_text().splitlines()]
    return [{key: value for key, value in row.items() if key not in MEASUREMENTS} for row in rows]


@pytest.fixture(scope="module")
def swept(tmp_path_factory, curvebench_bin):
    """The whole sweep on one machine, and its three shards."""
    import subprocess
    directory = tmp_path_factory.mktemp("merge")
    config = directory / "config.json"
    config.write_text(json.dumps(CONFIG))

    def sweep(out, *args):
        result = subprocess.run([curvebench_bin, "sweep", config, "--out", out, "--inputs", directory / "inputs", "--quiet",
                                 *args], capture_output=True, text=True, timeout=300)
        assert result.returncode == 0, result.stderr

    sweep(directory / "whole.jsonl")
    shards = [directory / f"shard-{i}.jsonl" for i in range(3)]
    for i, shard in enumerate(shards):
        sweep(shard, "--shard", f"{i}/3")
    return config, directory / "whole.jsonl", shards


def test_merged_shards_are_the_whole_sweep(run, tmp_path, swept):
    config, whole, shards = swept
    merged = tmp_path / "merged.jsonl"
    result = run("merge", config, *reversed(shards), "--out", merged)
    assert result.returncode == 0, result.stderr
    assert len(merged.read_text().splitlines()) == RUNS
    assert without_measurements(merged) == without_measurements(whole)


def test_a_missing_run_fails_the_merge_naming_it(run, tmp_path, swept):
    config, _, shards = swept
    partial = tmp_path / "partial.jsonl"
    lines = shards[1].read_text().splitlines()
    partial.write_text("\n".join(lines[:2] + lines[3:]) + "\n")  # the third run of shard 1 is plan index 7
    merged = tmp_path / "merged.jsonl"
    result = run("merge", config, shards[0], partial, shards[2], "--out", merged)
    assert result.returncode != 0 and not merged.exists()
    message = result.stderr.strip()
    assert "1 run of the plan has no row: #7 (" in message and json.loads(lines[2])["algorithm"] in message
    assert len(message.splitlines()) == 1

    missing_shard = run("merge", config, shards[0], shards[1], "--out", merged)
    assert missing_shard.returncode != 0
    assert f"{RUNS // 3} runs of the plan have no row: #2 (" in missing_shard.stderr and "and 5 more" in missing_shard.stderr


def test_a_duplicated_run_fails_the_merge_naming_both_rows(run, tmp_path, swept):
    config, _, shards = swept
    result = run("merge", config, *shards, shards[2], "--out", tmp_path / "merged.jsonl")
    assert result.returncode != 0
    assert f"{RUNS // 3} runs have more than one row: #2 (" in result.stderr
    assert f"in {shards[2]}:1 and {shards[2]}:1" in result.stderr


def test_a_row_of_another_sweep_or_a_partial_line_fails_the_merge(run, tmp_path, swept):
    config, whole, shards = swept
    other = json.loads(whole.read_text().splitlines()[0])
    other["input"]["epsilon"] = 0.25
    foreign = tmp_path / "foreign.jsonl"
    foreign.write_text(json.dumps(other) + "\n")
    result = run("merge", config, *shards, foreign, "--out", tmp_path / "merged.jsonl")
    assert result.returncode != 0 and f"1 run is not in the plan: {foreign}:1 (" in result.stderr

    cut = tmp_path / "cut.jsonl"
    cut.write_text(shards[0].read_text()[:-40])
    result = run("merge", config, cut, shards[1], shards[2], "--out", tmp_path / "merged.jsonl")
    assert result.returncode != 0
    assert f"{cut}:{RUNS // 3 + 1}: not a sweep row" in result.stderr
