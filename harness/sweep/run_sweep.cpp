#include "sweep/run_sweep.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "external/external_algorithm.h"
#include "io/ground_truth_json.h"
#include "io/metrics_json.h"
#include "io/parameters_json.h"
#include "io/points_file.h"
#include "metrics/evaluate_reconstruction.h"
#include "metrics/oracle_l2_error.h"
#include "sweep/run_in_child_processes.h"

namespace curvebench {
namespace {

using Json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The keys of the rows already in `path`; a partial last line (an interrupted write) is cut.
std::set<std::string> keys_of_existing_rows(const std::string& path) {
  std::set<std::string> keys;
  if (!std::filesystem::exists(path)) return keys;
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  in.close();
  const size_t complete = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
  if (complete < text.size()) std::filesystem::resize_file(path, complete);
  std::istringstream lines(text.substr(0, complete));
  std::string line;
  while (std::getline(lines, line)) {
    if (line.empty()) continue;
    const Json row = Json::parse(line, nullptr, false);
    if (row.is_discarded() || !row.contains("algorithm") || !row.contains("parameters") || !row.contains("input")) {
      throw std::runtime_error(path + ": a line is not a sweep row; not resuming into it");
    }
    keys.insert(run_key(row["algorithm"].get<std::string>(), row["parameters"], row["input"]));
  }
  return keys;
}

std::string settings_hash(const Json& settings) {
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a
  for (const unsigned char c : settings.dump()) hash = (hash ^ c) * 1099511628211ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}

struct PreparedInput {
  std::string points_path;
  std::string truth_path;
  bool ready = false;
  std::string failure;     // why it could not be generated
  int points = 0;
  double oracle_l2_error = 0;  // NaN when the truth has an open curve
};

// Progress and an estimate of the time left, on stderr: rewritten in place on a terminal,
// otherwise a line every few seconds.
class ProgressReport {
 public:
  ProgressReport(std::string what, int total, bool enabled)
      : what_(std::move(what)), total_(total), enabled_(enabled && total > 0), terminal_(::isatty(2)) {}

  void advance(const std::string& tally) {
    ++done_;
    if (!enabled_) return;
    const double elapsed = milliseconds_since(start_) / 1000.0;
    if (!terminal_ && done_ < total_ && elapsed < last_print_ + 5.0) return;
    last_print_ = elapsed;
    const double left = elapsed / done_ * (total_ - done_);
    std::cerr << (terminal_ ? "\r" : "") << what_ << " " << done_ << "/" << total_ << " (" << 100 * done_ / total_ << "%), "
              << duration(elapsed) << " elapsed, about " << duration(left) << " left" << (tally.empty() ? "" : "; " + tally)
              << (terminal_ ? "\033[K" : "\n");
    if (terminal_ && done_ == total_) std::cerr << "\n";
    std::cerr.flush();
  }

 private:
  static std::string duration(double seconds) {
    const long s = static_cast<long>(seconds + 0.5);
    return s >= 60 ? std::to_string(s / 60) + " min " + std::to_string(s % 60) + " s" : std::to_string(s) + " s";
  }
  std::string what_;
  int total_;
  bool enabled_;
  bool terminal_;
  int done_ = 0;
  double last_print_ = 0;
  Clock::time_point start_ = Clock::now();
};

std::vector<PreparedInput> prepare_inputs(const SweepPlan& plan, const std::set<int>& needed, const SweepOptions& options,
                                          const SweepEnvironment& environment, double timeout) {
  std::filesystem::create_directories(options.inputs_directory);
  std::vector<PreparedInput> prepared(plan.inputs.size());
  const std::vector<int> order(needed.begin(), needed.end());
  for (int input : order) {
    const std::string stem = (std::filesystem::path(options.inputs_directory) / settings_hash(plan.inputs[input])).string();
    prepared[input].points_path = stem + ".xy";
    prepared[input].truth_path = stem + ".truth.json";
  }
  ProgressReport progress("inputs", static_cast<int>(order.size()), options.show_progress);
  run_in_child_processes(
      static_cast<int>(order.size()), options.parallel_jobs, timeout, options.memory_limit_mb * 1024,
      [&](int task) {
        const PreparedInput& input = prepared[order[task]];
        try {
          environment.generate_input(plan.inputs[order[task]], input.points_path, input.truth_path);
          const std::vector<Point2> points = read_points_file(input.points_path);
          const GroundTruth truth = read_ground_truth_file(input.truth_path);
          return Json{{"points", points.size()}, {"oracle_l2_error", oracle_l2_error(truth, points)}}.dump();
        } catch (const std::exception& e) {
          return Json{{"failure", e.what()}}.dump();
        }
      },
      [&](int task, const ChildOutcome& outcome) {
        PreparedInput& input = prepared[order[task]];
        const Json summary = outcome.ending == ChildOutcome::Ending::kFinished ? Json::parse(outcome.output) : Json::object();
        if (summary.contains("failure")) {
          input.failure = "input generation failed: " + summary["failure"].get<std::string>();
        } else if (outcome.ending == ChildOutcome::Ending::kFinished) {
          input.ready = true;
          input.points = summary["points"].get<int>();
          // null: the truth has an open curve (oracle_l2_error.h); the row writes it as null again
          input.oracle_l2_error = summary["oracle_l2_error"].is_null() ? std::numeric_limits<double>::quiet_NaN()
                                                                        : summary["oracle_l2_error"].get<double>();
        } else if (outcome.ending == ChildOutcome::Ending::kTimedOut) {
          input.failure = "input generation took longer than the timeout";
        } else {
          input.failure = "input generation crashed: " + outcome.failure;
        }
        progress.advance("");
      });
  return prepared;
}

// The fields of a row that only depend on the plan and the input.
Json row_header(const SweepPlan& plan, const SweepRun& run, const PreparedInput& input) {
  Json row;
  row["algorithm"] = run.algorithm;
  row["parameters"] = run.parameters;
  row["input"] = plan.inputs[run.input];
  if (input.ready) {
    row["input_points"] = input.points;
    row["oracle_l2_error"] = std::isnan(input.oracle_l2_error) ? Json(nullptr) : Json(input.oracle_l2_error);
  }
  return row;
}

// In the child: reconstruct, evaluate, and return the row so far, which starts as `header`.
std::string perform_run(Json row, const Json& run_parameters, const std::string& points_path, const std::string& truth_path,
                        const Algorithm& algorithm) {
  const std::vector<Point2> points = read_points_file(points_path);
  const GroundTruth truth = read_ground_truth_file(truth_path);
  Reconstruction result;
  try {
    result = algorithm.reconstruct(points, parameters_from_json(run_parameters, algorithm.name() + ".parameters"));
  } catch (const ExternalProgramFailed& e) {  // the program it runs crashed, as a built-in run can
    row["status"] = "crash";
    row["message"] = e.what();
    return row.dump();
  } catch (const std::exception& e) {
    row["status"] = "error";
    row["message"] = e.what();
    return row.dump();
  }
  ReconstructionMetrics metrics;
  const Clock::time_point evaluation = Clock::now();
  try {
    metrics = evaluate_reconstruction(truth, points, result);
  } catch (const std::exception& e) {
    row["status"] = "error";
    row["message"] = std::string("evaluation failed: ") + e.what();
    return row.dump();
  }
  const double evaluate_ms = milliseconds_since(evaluation);
  row["status"] = "ok";
  row["metrics"] = metrics_to_json(metrics);
  row["timing_ms"] = Json::object();
  for (const auto& [phase, ms] : result.timing_ms) row["timing_ms"][phase] = ms;
  row["evaluate_ms"] = evaluate_ms;
  return row.dump();
}

const Algorithm& find_in(const std::vector<const Algorithm*>& algorithms, const std::string& name) {
  for (const Algorithm* algorithm : algorithms) {
    if (algorithm->name() == name) return *algorithm;
  }
  throw std::runtime_error("sweep: unknown algorithm '" + name + "'");
}

}  // namespace

std::string run_key(const std::string& algorithm, const nlohmann::ordered_json& parameters, const nlohmann::ordered_json& input) {
  return Json{{"algorithm", algorithm}, {"parameters", parameters}, {"input", input}}.dump();
}

std::string perform_sweep_run(const std::string& spec, const std::vector<const Algorithm*>& algorithms) {
  const Json run = Json::parse(spec);
  const Json& row = run.at("row");
  return perform_run(row, run.at("parameters"), run.at("points").get<std::string>(), run.at("truth").get<std::string>(),
                     find_in(algorithms, row.at("algorithm").get<std::string>()));
}

SweepSummary run_sweep(const SweepPlan& plan, const SweepOptions& options, const SweepEnvironment& environment) {
  const Clock::time_point start = Clock::now();
  if (options.shard_count < 1 || options.shard_index < 0 || options.shard_index >= options.shard_count) {
    throw std::runtime_error("sweep: shard " + std::to_string(options.shard_index) + "/" + std::to_string(options.shard_count) +
                             " is not i/n with 0 <= i < n");
  }
  if (!options.resume && std::filesystem::exists(options.results_path) && std::filesystem::file_size(options.results_path) > 0) {
    throw std::runtime_error(options.results_path + " already holds results; pass --resume to add the missing runs, or remove it");
  }
  const std::set<std::string> done = options.resume ? keys_of_existing_rows(options.results_path) : std::set<std::string>{};
  const double timeout = options.timeout_seconds > 0 ? options.timeout_seconds : plan.timeout_seconds;

  SweepSummary summary;
  std::vector<int> selected;  // plan run indices, in plan order
  for (int r = options.shard_index; r < static_cast<int>(plan.runs.size()); r += options.shard_count) {
    ++summary.planned_runs;
    const SweepRun& run = plan.runs[r];
    if (done.contains(run_key(run.algorithm, run.parameters, plan.inputs[run.input]))) {
      ++summary.skipped_runs;
    } else {
      selected.push_back(r);
    }
  }
  std::set<int> needed_inputs;
  for (int r : selected) needed_inputs.insert(plan.runs[r].input);
  const std::vector<PreparedInput> inputs = prepare_inputs(plan, needed_inputs, options, environment, timeout);

  std::ofstream out(options.results_path, std::ios::binary | std::ios::app);
  if (!out) throw std::runtime_error(options.results_path + ": cannot open for appending");
  // Rows are written in plan order: finished rows wait here until those before them are in.
  std::map<size_t, std::string> waiting_rows;
  size_t next_to_write = 0;
  auto finish_row = [&](size_t position, Json row) {
    const std::string status = row["status"].get<std::string>();
    (status == "ok" ? summary.ok : status == "error" ? summary.errors : status == "timeout" ? summary.timeouts : summary.crashes) += 1;
    waiting_rows[position] = row.dump();
    for (auto it = waiting_rows.begin(); it != waiting_rows.end() && it->first == next_to_write; it = waiting_rows.erase(it)) {
      out << it->second << '\n';
      ++next_to_write;
      ++summary.written_rows;
    }
    out.flush();
    if (!out) throw std::runtime_error(options.results_path + ": write error");
  };

  std::vector<size_t> child_positions;  // positions in `selected` that need a child process
  for (size_t position = 0; position < selected.size(); ++position) {
    const SweepRun& run = plan.runs[selected[position]];
    const PreparedInput& input = inputs[run.input];
    if (input.ready) {
      child_positions.push_back(position);
    } else {
      Json row = row_header(plan, run, input);
      row["status"] = "error";
      row["message"] = input.failure;
      finish_row(position, std::move(row));
    }
  }

  // The runs' temporary files (an external algorithm's, and its program's) go to a directory of
  // the sweep's that is removed when the runs are done: a run killed for its time or memory
  // cannot clean up after itself.
  const std::string temporary_directory = options.results_path + ".tmp";
  std::filesystem::create_directories(temporary_directory);
  ProgressReport progress("runs", static_cast<int>(child_positions.size()), options.show_progress);
  run_in_child_processes(
      static_cast<int>(child_positions.size()), options.parallel_jobs, timeout, options.memory_limit_mb * 1024,
      [&](int task) {
        const SweepRun& run = plan.runs[selected[child_positions[task]]];
        const PreparedInput& input = inputs[run.input];
        ::setenv("TMPDIR", temporary_directory.c_str(), 1);  // in the child only
        if (environment.start_fresh_process) {
          environment.start_fresh_process(Json{{"row", row_header(plan, run, input)},
                                               {"parameters", run.parameters},
                                               {"points", input.points_path},
                                               {"truth", input.truth_path}}
                                              .dump());
          throw std::runtime_error("sweep: cannot start a fresh process for the run");
        }
        return perform_run(row_header(plan, run, input), run.parameters, input.points_path, input.truth_path,
                           find_in(environment.algorithms, run.algorithm));
      },
      [&](int task, const ChildOutcome& outcome) {
        const size_t position = child_positions[task];
        const SweepRun& run = plan.runs[selected[position]];
        Json row;
        if (outcome.ending == ChildOutcome::Ending::kFinished) {
          row = Json::parse(outcome.output);
        } else {
          row = row_header(plan, run, inputs[run.input]);
          const bool timed_out = outcome.ending == ChildOutcome::Ending::kTimedOut;
          row["status"] = timed_out ? "timeout" : "crash";
          std::ostringstream timeout_text;
          timeout_text << timeout;
          row["message"] = timed_out ? "no result within " + timeout_text.str() + " s" : outcome.failure;
        }
        row["wall_ms"] = outcome.wall_seconds * 1000.0;
        row["peak_memory_kb"] = outcome.peak_memory_kilobytes;
        finish_row(position, std::move(row));
        progress.advance(std::to_string(summary.errors) + " errors, " + std::to_string(summary.timeouts) + " timeouts, " +
                         std::to_string(summary.crashes) + " crashes");
      });
  std::filesystem::remove_all(temporary_directory);
  summary.seconds = milliseconds_since(start) / 1000.0;
  return summary;
}

}  // namespace curvebench
