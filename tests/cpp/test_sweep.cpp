// The sweep runner: grid expansion, isolation of crashing, throwing and hanging runs, resume,
// shards and reproducible rows. Inputs come from a hand-made generator (the unit square
// sampled at corners and side midpoints) and the algorithms are test-only ones, so nothing
// here depends on the real generators or on how long anything takes.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "io/ground_truth_json.h"
#include "io/points_file.h"
#include "sweep/run_in_child_processes.h"
#include "sweep/run_sweep.h"
#include "sweep/sweep_plan.h"

namespace curvebench {
namespace {

using Json = nlohmann::ordered_json;

const std::vector<Point2> kSquareSamples{{0, 0}, {0.5, 0}, {1, 0}, {1, 0.5}, {1, 1}, {0.5, 1}, {0, 1}, {0, 0.5}};

std::vector<Edge> square_cycle() {
  std::vector<Edge> edges;
  for (int i = 0; i < 8; ++i) edges.push_back(make_edge(i, (i + 1) % 8));
  return edges;
}

// A test algorithm named `name` whose run() is `body`.
template <class Body>
class TestAlgorithm : public Algorithm {
 public:
  TestAlgorithm(std::string name, std::vector<ParameterSpec> parameters, Body body)
      : info_{std::move(name), "test", kCurve, std::move(parameters), SiteInput::kDistinctPoints}, body_(body) {}
  const AlgorithmInfo& info() const override { return info_; }
  SiteResult run(const Sites& sites, const ParameterValues& params, PhaseTimer&) const override { return body_(sites, params); }

 private:
  AlgorithmInfo info_;
  Body body_;
};

// Returns the true square, or only its first `keep` edges.
SiteResult square(const Sites&, const ParameterValues& params) {
  SiteResult r;
  r.curve_edges = square_cycle();
  r.curve_edges->resize(static_cast<size_t>(params.integer("keep")));
  return r;
}
SiteResult throws(const Sites&, const ParameterValues&) { throw InputError("too few points"); }
SiteResult aborts(const Sites&, const ParameterValues&) { std::abort(); }
SiteResult hangs(const Sites&, const ParameterValues&) {
  for (;;) ::pause();
}
// Allocates and touches memory until it is stopped.
SiteResult allocates(const Sites&, const ParameterValues&) {
  std::vector<std::vector<char>> blocks;
  for (;;) blocks.emplace_back(std::size_t{16} << 20, 'x');
}

using RunFunction = SiteResult (*)(const Sites&, const ParameterValues&);
using SquareAlgorithm = TestAlgorithm<RunFunction>;
const SquareAlgorithm kSquare{"square", {integer_parameter("keep", 8, 0, 8, "edges of the cycle to return")}, square};
const SquareAlgorithm kGreedy{"allocates", {}, allocates};
const SquareAlgorithm kThrows{"throws", {}, throws};
const SquareAlgorithm kAborts{"aborts", {}, aborts};
const SquareAlgorithm kHangs{"hangs", {}, hangs};

void write_square_input(const Json& settings, const std::string& points_path, const std::string& truth_path) {
  if (settings.at("family") != "square") throw std::runtime_error("unknown family");
  GroundTruth truth;
  truth.curves.push_back({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {0.5, 0.5, 0.5, 0.5}});
  for (int i = 0; i < 8; ++i) truth.samples.push_back({0, i / 8.0, 0.5});
  truth.edges = square_cycle();
  write_points_file(points_path, kSquareSamples);
  write_file_atomically(truth_path, ground_truth_to_json(truth).dump());
}

SweepEnvironment test_environment() { return {{&kSquare, &kThrows, &kAborts, &kHangs, &kGreedy}, write_square_input, {}}; }

class SweepTest : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = std::filesystem::temp_directory_path() / ("curvebench_sweep_test_" + std::to_string(::getpid()));
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  SweepOptions options(const std::string& results_name) const {
    SweepOptions o;
    o.results_path = (directory_ / results_name).string();
    o.inputs_directory = (directory_ / "inputs").string();
    o.parallel_jobs = 2;
    o.show_progress = false;
    return o;
  }

  static std::vector<Json> rows(const std::string& path) {
    std::vector<Json> out;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) out.push_back(Json::parse(line));
    return out;
  }

  // A row without the fields that measure time and memory.
  static Json without_measurements(Json row) {
    for (const char* key : {"timing_ms", "evaluate_ms", "wall_ms", "peak_memory_kb"}) row.erase(key);
    return row;
  }

  std::filesystem::path directory_;
};

SweepPlan plan_of(const std::string& config_text) {
  const auto environment = test_environment();
  return plan_sweep(Json::parse(config_text), environment.algorithms);
}

TEST(SweepPlan, ExpandsListsIntoAGridInTheOrderWritten) {
  const SweepPlan plan = plan_of(R"({"seeds": [1, 2], "algorithms": ["square", {"name": "square", "parameters": {"keep": [7, 6]}}],
      "inputs": [{"family": "square", "epsilon": [0.1, 0.2], "shape": {"k": [3, 5]}}]})");
  ASSERT_EQ(plan.inputs.size(), 2u * 2u * 2u);  // epsilon x k x seeds
  EXPECT_EQ(plan.inputs[0], Json::parse(R"({"family": "square", "epsilon": 0.1, "shape": {"k": 3}, "seed": 1})"));
  EXPECT_EQ(plan.inputs[1], Json::parse(R"({"family": "square", "epsilon": 0.1, "shape": {"k": 3}, "seed": 2})"));
  EXPECT_EQ(plan.inputs[2], Json::parse(R"({"family": "square", "epsilon": 0.1, "shape": {"k": 5}, "seed": 1})"));
  ASSERT_EQ(plan.runs.size(), plan.inputs.size() * 3);
  // Defaults are filled in, so every run states the parameters it used.
  EXPECT_EQ(plan.runs[0].parameters, Json::parse(R"({"keep": 8.0})"));
  EXPECT_EQ(plan.runs[2].parameters, Json::parse(R"({"keep": 6.0})"));
  EXPECT_EQ(plan.runs[3].input, 1);
}

TEST(SweepPlan, AllMeansEveryAlgorithm) {
  const SweepPlan plan = plan_of(R"({"algorithms": "all", "inputs": [{"family": "square"}]})");
  ASSERT_EQ(plan.runs.size(), 5u);
  EXPECT_EQ(plan.runs[4].algorithm, "allocates");
  EXPECT_EQ(plan.timeout_seconds, 60);
}

TEST(SweepPlan, AnInputGridMayCarryItsOwnAlgorithmsAndRepeatsArePlannedOnce) {
  // The second grid repeats one input of the first (keys in another order) with a parameter
  // grid whose default value repeats the first grid's run: the input and that run stay one.
  const SweepPlan plan = plan_of(R"({"algorithms": ["square", "throws"],
      "inputs": [{"family": "square", "epsilon": [0.1, 0.2]},
                 {"algorithms": [{"name": "square", "parameters": {"keep": [8, 5]}}], "epsilon": 0.2, "family": "square"}]})");
  ASSERT_EQ(plan.inputs.size(), 2u);
  ASSERT_EQ(plan.runs.size(), 5u);
  EXPECT_EQ(plan.runs[2].input, 1);
  EXPECT_EQ(plan.runs[2].algorithm, "square");
  EXPECT_EQ(plan.runs[2].parameters, Json::parse(R"({"keep": 8.0})"));
  EXPECT_EQ(plan.runs[4].input, 1);
  EXPECT_EQ(plan.runs[4].parameters, Json::parse(R"({"keep": 5.0})"));
  EXPECT_FALSE(plan.inputs[1].contains("algorithms"));  // not a generator setting
}

TEST(SweepPlan, MistakesAreNamed) {
  auto error_of = [](const std::string& config) {
    try {
      plan_of(config);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error_of(R"({"algorithms": ["nope"], "inputs": [{}]})").find("unknown algorithm 'nope'"), std::string::npos);
  EXPECT_NE(error_of(R"({"algorithms": [{"name": "square", "parameters": {"width": 1}}], "inputs": [{}]})").find("width"), std::string::npos);
  EXPECT_NE(error_of(R"({"inputs": []})").find("inputs"), std::string::npos);
  EXPECT_NE(error_of(R"({"inputs": [{"seed": 3}]})").find("seeds"), std::string::npos);
  EXPECT_NE(error_of(R"({"inputs": [{"epsilon": []}]})").find("empty list"), std::string::npos);
  EXPECT_NE(error_of(R"({"inputs": [{"algorithms": ["nope"]}]})").find("unknown algorithm 'nope'"), std::string::npos);
  EXPECT_NE(error_of(R"({"inputs": [{"algorithms": []}]})").find("inputs[0].algorithms"), std::string::npos);
}

TEST_F(SweepTest, EveryFailureBecomesARowWithItsStatusAndTheSweepGoesOn) {
  SweepPlan plan = plan_of(R"({"algorithms": ["square", "throws", "aborts", "hangs", {"name": "square", "parameters": {"keep": 7}}],
                               "inputs": [{"family": "square"}, {"family": "bad"}]})");
  SweepOptions o = options("results.jsonl");
  // Only the hanging run reaches the timeout (it never returns); it is long enough that no
  // other run could, however loaded the machine.
  o.timeout_seconds = 2;
  const SweepSummary summary = run_sweep(plan, o, test_environment());
  const auto written = rows(o.results_path);
  ASSERT_EQ(written.size(), 10u);
  EXPECT_EQ(summary.written_rows, 10);
  // In plan order: the square input's five runs, then the bad input's five.
  EXPECT_EQ(written[0]["status"], "ok");
  EXPECT_EQ(written[0]["metrics"]["l2_error"], 0.0);
  EXPECT_EQ(written[0]["metrics"]["exact"], true);
  EXPECT_EQ(written[0]["input_points"], 8);
  EXPECT_EQ(written[0]["oracle_l2_error"], 0.0);
  EXPECT_GT(written[0]["peak_memory_kb"].get<long>(), 0);
  EXPECT_EQ(written[1]["status"], "error");
  EXPECT_EQ(written[1]["message"], "too few points");
  EXPECT_EQ(written[2]["status"], "crash");
  EXPECT_NE(written[2]["message"].get<std::string>().find("signal 6"), std::string::npos);
  EXPECT_EQ(written[3]["status"], "timeout");
  EXPECT_EQ(written[4]["status"], "ok");
  EXPECT_EQ(written[4]["metrics"]["l2_error"], 1.0);  // an open curve encloses nothing
  EXPECT_EQ(written[4]["metrics"]["edge_recall"], 7.0 / 8.0);
  for (size_t r = 5; r < 10; ++r) {
    EXPECT_EQ(written[r]["status"], "error");
    EXPECT_EQ(written[r]["message"], "input generation failed: unknown family");
  }
  EXPECT_EQ(summary.ok, 2);
  EXPECT_EQ(summary.errors, 6);
  EXPECT_EQ(summary.crashes, 1);
  EXPECT_EQ(summary.timeouts, 1);
}

TEST_F(SweepTest, AnAlgorithmThatAllocatesWithoutBoundIsKilledAndTheSweepGoesOn) {
  SweepPlan plan = plan_of(R"({"algorithms": ["allocates", "square"], "inputs": [{"family": "square"}]})");
  SweepOptions o = options("results.jsonl");
  o.memory_limit_mb = 256;
  o.timeout_seconds = 600;  // a safety net only: the memory limit ends the run long before
  const SweepSummary summary = run_sweep(plan, o, test_environment());
  const auto written = rows(o.results_path);
  ASSERT_EQ(written.size(), 2u);
  EXPECT_EQ(written[0]["status"], "crash");
  EXPECT_NE(written[0]["message"].get<std::string>().find("memory over the limit of 256 MiB"), std::string::npos)
      << written[0]["message"];
  EXPECT_EQ(written[1]["status"], "ok");
  EXPECT_EQ(summary.crashes, 1);
}

TEST_F(SweepTest, RowsAreTheSameEveryTimeApartFromMeasurements) {
  const SweepPlan plan = plan_of(R"({"seeds": [1, 2, 3], "algorithms": ["square", "throws", {"name": "square", "parameters": {"keep": [5, 6, 7]}}],
                                     "inputs": [{"family": "square"}]})");
  run_sweep(plan, options("first.jsonl"), test_environment());
  SweepOptions serial = options("second.jsonl");
  serial.parallel_jobs = 1;
  run_sweep(plan, serial, test_environment());
  const auto first = rows(options("first.jsonl").results_path);
  const auto second = rows(serial.results_path);
  ASSERT_EQ(first.size(), 15u);
  ASSERT_EQ(second.size(), first.size());
  for (size_t r = 0; r < first.size(); ++r) EXPECT_EQ(without_measurements(first[r]), without_measurements(second[r]));
}

TEST_F(SweepTest, ResumeSkipsRowsAlreadyThereAndCutsAPartialLine) {
  const SweepPlan plan = plan_of(R"({"seeds": [1, 2], "algorithms": ["square", "throws"], "inputs": [{"family": "square"}]})");
  SweepOptions o = options("results.jsonl");
  run_sweep(plan, o, test_environment());
  const auto complete = rows(o.results_path);
  ASSERT_EQ(complete.size(), 4u);
  // Without --resume an existing results file is not appended to.
  EXPECT_THROW(run_sweep(plan, o, test_environment()), std::runtime_error);
  // Keep two rows and half of the third, as an interrupted sweep would leave it.
  {
    std::ofstream out(o.results_path, std::ios::trunc);
    out << complete[0].dump() << "\n" << complete[1].dump() << "\n" << complete[2].dump().substr(0, 40);
  }
  o.resume = true;
  const SweepSummary summary = run_sweep(plan, o, test_environment());
  EXPECT_EQ(summary.skipped_runs, 2);
  EXPECT_EQ(summary.written_rows, 2);
  const auto resumed = rows(o.results_path);
  ASSERT_EQ(resumed.size(), 4u);
  for (size_t r = 0; r < 4; ++r) EXPECT_EQ(without_measurements(resumed[r]), without_measurements(complete[r]));
  EXPECT_EQ(run_sweep(plan, o, test_environment()).written_rows, 0);
}

TEST_F(SweepTest, ShardsPartitionTheRuns) {
  const SweepPlan plan = plan_of(R"({"seeds": [1, 2, 3, 4], "algorithms": ["square", "throws"], "inputs": [{"family": "square"}]})");
  std::multiset<std::string> union_of_shards;
  for (int shard = 0; shard < 3; ++shard) {
    SweepOptions o = options("shard" + std::to_string(shard) + ".jsonl");
    o.shard_index = shard;
    o.shard_count = 3;
    run_sweep(plan, o, test_environment());
    for (const Json& row : rows(o.results_path)) union_of_shards.insert(without_measurements(row).dump());
  }
  run_sweep(plan, options("all.jsonl"), test_environment());
  std::multiset<std::string> everything;
  for (const Json& row : rows(options("all.jsonl").results_path)) everything.insert(without_measurements(row).dump());
  EXPECT_EQ(union_of_shards, everything);
  EXPECT_EQ(everything.size(), 8u);
  SweepOptions bad = options("bad.jsonl");
  bad.shard_index = 3;
  bad.shard_count = 3;
  EXPECT_THROW(run_sweep(plan, bad, test_environment()), std::runtime_error);
}

TEST(RunInChildProcesses, ReportsEachEndingOnce) {
  std::vector<ChildOutcome::Ending> endings(4);
  std::vector<std::string> outputs(4);
  std::vector<int> calls(4, 0);
  run_in_child_processes(
      4, 3, 2.0, 0,  // only task 3 reaches the timeout: it never returns
      [](int task) -> std::string {
        if (task == 1) throw std::runtime_error("thrown");
        if (task == 2) std::abort();
        if (task == 3) for (;;) ::pause();
        return std::string(100000, 'x');  // more than a pipe holds at once
      },
      [&](int task, const ChildOutcome& outcome) {
        ++calls[task];
        endings[task] = outcome.ending;
        outputs[task] = outcome.output.size() > 10 ? std::to_string(outcome.output.size()) : outcome.failure;
      });
  EXPECT_EQ(calls, std::vector<int>(4, 1));
  EXPECT_EQ(endings[0], ChildOutcome::Ending::kFinished);
  EXPECT_EQ(outputs[0], "100000");
  EXPECT_EQ(endings[1], ChildOutcome::Ending::kCrashed);
  EXPECT_EQ(outputs[1], "uncaught exception: thrown");
  EXPECT_EQ(endings[2], ChildOutcome::Ending::kCrashed);
  EXPECT_EQ(endings[3], ChildOutcome::Ending::kTimedOut);
}

}  // namespace
}  // namespace curvebench
