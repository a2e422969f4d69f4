// Running a sweep: every run of a plan (or a shard of them) in its own child process,
// appending one JSON line per run to the results file.
//
// In:  the plan (sweep_plan.h), where to write, how many runs at once, resume and shard
//      choices, and the environment: the algorithms and how to make an input's files.
// Out: the results file gains one row per run, in plan order:
//   {"algorithm": "labeling", "parameters": {...}, "input": {...generator settings, "seed"},
//    "input_points": 230, "oracle_l2_error": 0.0003,
//    "status": "ok" | "error" | "timeout" | "crash", "message": "..." (unless ok),
//    "metrics": {...metrics_json.h, only if ok},
//    "timing_ms": {...the algorithm's phases, only if ok}, "evaluate_ms": 12.5,
//    "wall_ms": 31.0, "peak_memory_kb": 10240}
//   Everything before "timing_ms" is a function of the plan and the code alone, so two
//   sweeps give identical rows apart from the timings and memory at the end.
//   Each input is generated once, before its runs, into `inputs_directory` (files named by
//   a hash of its settings). An input that cannot be generated makes an "error" row for each
//   of its runs. A run that throws is an "error" row, one killed by a signal or exiting
//   without a result a "crash" row, and one past the timeout is killed and a "timeout" row;
//   each run's peak memory is its child's (getrusage). Runs have TMPDIR set to
//   `<results>.tmp/`, removed when they are done. Progress with an estimate of the time
//   left goes to stderr.
//   With `resume`, runs whose (algorithm, parameters, input) already have a row are skipped
//   (a partial last line left by an interrupted sweep is cut off first); without it an
//   existing non-empty results file is an error. A shard i of n (0 <= i < n) takes the runs
//   whose plan index is i modulo n, so n shards together hold every run exactly once
//   (merge_shards.h puts them back together). A run of an external algorithm whose program
//   crashes or exits with an error status is a "crash" row (external/external_algorithm.h).
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/algorithm.h"
#include "sweep/sweep_plan.h"

namespace curvebench {

struct SweepEnvironment {
  std::vector<const Algorithm*> algorithms;
  // Writes the points file and the ground-truth JSON of the input with these settings (the
  // `curvebench sweep` command: generators/generate.h); throws with a one-line message if
  // it cannot. Called in a child process.
  std::function<void(const nlohmann::ordered_json& settings, const std::string& points_path, const std::string& truth_path)>
      generate_input;
  // If set, every run takes place in a fresh process rather than in the forked copy of the
  // sweep: called in the child with the run's spec, it must replace the process image (exec)
  // with a program that reports perform_sweep_run(spec) through report_child_result
  // (run_in_child_processes.h); it returns only if it cannot. An algorithm may depend on the
  // state of the heap it starts with (CGAL's optimal-transport reconstruction did: 23 of 648
  // rows differed between two identical sweeps of forked copies; see optimal_transport.cpp),
  // and a fresh process starts every run from the same state.
  std::function<void(const std::string& spec)> start_fresh_process;
};

// One run as a fresh process performs it: `spec` is the JSON text start_fresh_process is
// given (the row so far, the run's parameters and the paths of its input); returns the row
// as JSON text, ready for the timings and memory the sweep adds.
std::string perform_sweep_run(const std::string& spec, const std::vector<const Algorithm*>& algorithms);

struct SweepOptions {
  std::string results_path;
  std::string inputs_directory;
  int parallel_jobs = 1;
  bool resume = false;
  int shard_index = 0;
  int shard_count = 1;
  double timeout_seconds = 0;  // 0: the plan's
  long memory_limit_mb = 8192;  // resident memory per run before it is killed (a crash row); 0: none
  bool show_progress = true;
};

struct SweepSummary {
  int planned_runs = 0;   // in this shard
  int skipped_runs = 0;   // already in the results (resume)
  int written_rows = 0;
  int ok = 0, errors = 0, timeouts = 0, crashes = 0;
  double seconds = 0;
};

// What identifies a run, in a row as in the plan: its algorithm, parameters and input.
std::string run_key(const std::string& algorithm, const nlohmann::ordered_json& parameters, const nlohmann::ordered_json& input);

SweepSummary run_sweep(const SweepPlan& plan, const SweepOptions& options, const SweepEnvironment& environment);

}  // namespace curvebench
