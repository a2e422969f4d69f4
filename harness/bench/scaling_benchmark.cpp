// Scaling suite: every algorithm against the bare CGAL Delaunay construction of the same
// points, side by side in one run, on three inputs at n = 10^3 ... 10^6 (10^7 with --max_n):
//   smooth  n random positions along the rose r = 1 + 0.3 cos(5t), a smooth closed curve
//           with five pseudo-concavities;
//   noisy   the same positions, each moved along the curve normal by a Gaussian amount of
//           standard deviation half the mean sample spacing (curve length / n), so that the
//           noise stays the same relative to the sampling at every n;
//   shuffled the smooth points in random order. The other two come in order along the curve,
//           as traced outlines do, and the Voronoi layer keeps that order; here it puts the
//           sites in Z order (see number_sites_and_faces).
// Benchmarks are named <algorithm>/<input>/n:<n> ("delaunay" is the bare construction).
//
// Counters of each row:
//   ns_per_point                 time per point
//   x_delaunay                   time over the bare Delaunay time of the same points, timed
//                                just before every iteration of the algorithm: paired this
//                                way, the ratio holds while the machine's speed drifts (a
//                                shared host slows both alike), which separate rows do not
//   after_delaunay_ns_per_point  time per point of the phases after the algorithm's own
//                                "delaunay" phase: the CPU time times the share of the
//                                wall-clock phase times (Reconstruction::timing_ms) after it
//   peak_MiB, input_MiB          peak resident memory (VmHWM of /proc/self/status) of a fresh
//                                process that makes the same points and reconstructs them
//                                once, and of the same process before the reconstruction
//                                (executable, libraries and the points). The process is this
//                                executable started again with --peak_memory_child, so each
//                                row's peak is its own and not the running maximum of the suite.
// Times are the process's CPU time, so that other work on the machine does not enter the
// ratios; it counts every thread (optimal-transport runs CGAL in a thread of its own), and
// nothing else runs in this process while a run is timed.
//
// A run predicted to take more than --max_run_seconds (its time at the previous n, scaled
// linearly in n) or more memory than is available (its peak at the previous n, scaled the
// same way, against MemAvailable of /proc/meminfo) is skipped and reported as an error row
// saying why, and so are the larger n of the same algorithm and input.
//
// Run: curvebench_benchmark [--max_n=1000000] [--max_run_seconds=60]
//                           [--benchmark_out=scaling.json --benchmark_out_format=json]
//                           [--benchmark_filter=...] [--benchmark_min_time=...]
#include <benchmark/benchmark.h>
#include <sys/wait.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/registry.h"
#include "generators/families.h"
#include "generators/rose_curve.h"
#include "process/child_process.h"
#include "process/proc_status.h"
#include "voronoi/delaunay_voronoi.h"

namespace curvebench {
namespace {

const std::vector<std::string> kInputs = {"smooth", "noisy", "shuffled"};

struct Settings {
  long long max_n = 1'000'000;
  double max_run_seconds = 60.0;
};

Settings& settings() {
  static Settings value;
  return value;
}

// The rose family with its default shape, r = 1 + 0.3 cos(5t).
struct Rose {
  double a, b;
  int k;
};

const Rose& rose() {
  static const Rose shape = [] {
    const ShapeValues values = resolve_shape(find_curve_family("rose"), {});
    return Rose{values.at("a"), values.at("b"), static_cast<int>(values.at("k"))};
  }();
  return shape;
}

Point2 point_on_rose(double t) { return rose_point(rose().a, rose().b, rose().k, t); }

double rose_length() {
  constexpr int kSegments = 100'000;
  double length = 0.0;
  for (int i = 0; i < kSegments; ++i) {
    const Point2 a = point_on_rose(2 * std::numbers::pi * i / kSegments);
    const Point2 b = point_on_rose(2 * std::numbers::pi * (i + 1) / kSegments);
    length += std::hypot(b.x - a.x, b.y - a.y);
  }
  return length;
}

// The points of `input` ("smooth", "noisy" or "shuffled") at n. Fixed seeds: every run times the same points.
std::vector<Point2> make_points(const std::string& input, int n) {
  std::mt19937_64 rng(20190501u + static_cast<unsigned>(n));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> t(n);
  for (auto& value : t) value = 2 * std::numbers::pi * unit(rng);
  std::sort(t.begin(), t.end());
  std::vector<Point2> points;
  points.reserve(n);
  for (double angle : t) points.push_back(point_on_rose(angle));
  if (input == "noisy") {
    std::normal_distribution<double> gaussian(0.0, 0.5 * rose_length() / n);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double shift = gaussian(rng);
      const Point2 normal = rose_unit_normal(rose().a, rose().b, rose().k, t[i]);
      points[i] = {points[i].x + shift * normal.x, points[i].y + shift * normal.y};
    }
  }
  if (input == "shuffled") std::shuffle(points.begin(), points.end(), rng);
  return points;
}

// Points of the one input and n the suite is at; the previous ones are released, so that the
// suite's own memory stays near that of its current run.
const std::vector<Point2>& current_points(const std::string& input, int n) {
  static std::pair<std::string, int> key;
  static std::vector<Point2> points;
  if (key != std::pair(input, n)) {
    points = {};
    points = make_points(input, n);
    key = {input, n};
  }
  return points;
}

double cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

void reconstruct_once(const std::string& algorithm, std::span<const Point2> points) {
  if (algorithm == "delaunay") {
    benchmark::DoNotOptimize(bare_delaunay_vertex_count(points));
    return;
  }
  const Algorithm& chosen = find_algorithm(algorithm);
  auto result = chosen.reconstruct(points, {});
  benchmark::DoNotOptimize(result);
}

// The child side of the memory measurement: "<algorithm>/<input>/<n>" in, "input_MiB peak_MiB" out.
int run_peak_memory_child(const std::string& run) {
  std::istringstream fields(run);
  std::string algorithm, input, n;
  std::getline(fields, algorithm, '/');
  std::getline(fields, input, '/');
  std::getline(fields, n);
  const auto points = make_points(input, std::stoi(n));
  const double input_mib = proc_status_kib(0, "VmHWM") / 1024.0;
  try {
    reconstruct_once(algorithm, points);
  } catch (const InputError& e) {  // an algorithm's own limit (optimal-transport's max_points)
    std::printf("%s\n", e.what());
    return 1;
  }
  std::printf("%.3f %.3f\n", input_mib, proc_status_kib(0, "VmHWM") / 1024.0);
  return 0;
}

struct PeakMemory {
  double input_mib = 0.0, peak_mib = 0.0;
  std::string failure;  // empty on success
};

PeakMemory measure_peak_memory_in_child(const std::string& algorithm, const std::string& input, int n) {
  const std::string run = algorithm + "/" + input + "/" + std::to_string(n);
  const ChildExit end = run_child(start_this_executable({"--peak_memory_child=" + run}, true), {});
  const int status = end.wait_status;
  std::string output = end.output;
  PeakMemory memory;
  while (!output.empty() && output.back() == '\n') output.pop_back();
  if (WIFEXITED(status) && WEXITSTATUS(status) == 1) {
    memory.failure = "skipped: " + output;  // the algorithm refused the input
  } else if (status != 0 || std::sscanf(output.c_str(), "%lf %lf", &memory.input_mib, &memory.peak_mib) != 2) {
    memory.failure = "memory-measuring process failed (status " + std::to_string(status) + "): " + output;
  }
  return memory;
}

struct Run {  // one (algorithm, input, n), as far as it got
  std::string skip_reason;  // empty unless skipped
  PeakMemory memory;
  double seconds = 0.0;  // mean CPU seconds per iteration, once timed
};

// By (algorithm, input), then n. Google Benchmark calls a benchmark function several times
// per n (growing the iteration count), so the memory is measured at the first call only.
std::map<std::pair<std::string, std::string>, std::map<int, Run>>& runs() {
  static std::map<std::pair<std::string, std::string>, std::map<int, Run>> by_algorithm_and_input;
  return by_algorithm_and_input;
}

// Why the run at n should not start, judged from the same algorithm and input at the largest
// smaller n; or empty.
std::string reason_to_skip(const std::map<int, Run>& sizes, int n) {
  const auto below = sizes.lower_bound(n);
  if (below == sizes.begin()) return "";
  const auto& [previous_n, previous] = *std::prev(below);
  if (!previous.skip_reason.empty()) return "skipped: a smaller n was skipped or failed";
  const double growth = static_cast<double>(n) / previous_n;
  const double predicted_seconds = previous.seconds * growth;
  const double predicted_mib = previous.memory.peak_mib * growth;
  const double available_mib = meminfo_kib("MemAvailable") / 1024.0;
  char reason[256] = "";
  if (predicted_seconds > settings().max_run_seconds) {
    std::snprintf(reason, sizeof reason, "skipped: about %.0f s predicted from n=%d, over --max_run_seconds=%g",
                  predicted_seconds, previous_n, settings().max_run_seconds);
  } else if (predicted_mib > 0.8 * available_mib) {
    std::snprintf(reason, sizeof reason, "skipped: about %.0f MiB predicted from n=%d, %.0f MiB available",
                  predicted_mib, previous_n, available_mib);
  }
  return reason;
}

// Runs `algorithm` on `input` at the benchmark's n: skip check and peak memory in a child
// process (first call for this n only), then the timed iterations, each after an untimed
// bare Delaunay construction of the same points that is the iteration's floor. Returns the
// mean CPU seconds per iteration, or nothing if the run was skipped.
template <typename Reconstruct>
std::optional<double> time_run(benchmark::State& state, const std::string& algorithm, const std::string& input,
                               Reconstruct&& reconstruct) {
  const int n = static_cast<int>(state.range(0));
  auto& sizes = runs()[{algorithm, input}];
  if (!sizes.contains(n)) {
    Run first;
    first.skip_reason = reason_to_skip(sizes, n);
    if (first.skip_reason.empty()) {
      first.memory = measure_peak_memory_in_child(algorithm, input, n);
      first.skip_reason = first.memory.failure;
    }
    sizes[n] = first;
  }
  Run& run = sizes[n];
  if (!run.skip_reason.empty()) {
    state.SkipWithError(run.skip_reason.c_str());
    return std::nullopt;
  }
  const auto& points = current_points(input, n);
  const bool paired = algorithm != "delaunay";
  double total = 0.0, delaunay_total = 0.0;
  for (auto _ : state) {
    if (paired) {
      const double start = cpu_seconds();
      benchmark::DoNotOptimize(bare_delaunay_vertex_count(points));
      delaunay_total += cpu_seconds() - start;
    }
    const double start = cpu_seconds();
    reconstruct(points);
    const double seconds = cpu_seconds() - start;
    state.SetIterationTime(seconds);
    total += seconds;
  }
  run.seconds = total / static_cast<double>(state.iterations());
  state.counters["ns_per_point"] = 1e9 * run.seconds / n;
  state.counters["peak_MiB"] = run.memory.peak_mib;
  state.counters["input_MiB"] = run.memory.input_mib;
  state.counters["x_delaunay"] = paired ? total / delaunay_total : 1.0;
  return run.seconds;
}

void BM_Delaunay(benchmark::State& state, std::string input) {
  time_run(state, "delaunay", input, [](const std::vector<Point2>& points) {
    benchmark::DoNotOptimize(bare_delaunay_vertex_count(points));
  });
}

void BM_Algorithm(benchmark::State& state, const Algorithm* algorithm, std::string input) {
  double after_delaunay_share_sum = 0.0;
  int phased_iterations = 0;
  std::optional<double> mean;
  try {
    mean = time_run(state, algorithm->name(), input, [&](const std::vector<Point2>& points) {
      auto result = algorithm->reconstruct(points, {});
      benchmark::DoNotOptimize(result);
      const auto& phases = result.timing_ms;
      if (phases.size() >= 2 && phases.front().first == "delaunay" && phases.back().second > 0) {
        after_delaunay_share_sum += 1.0 - phases.front().second / phases.back().second;
        ++phased_iterations;
      }
    });
  } catch (const InputError& e) {  // an algorithm's own limit (optimal-transport's max_points)
    state.SkipWithError(e.what());
    return;
  }
  if (mean && phased_iterations > 0) {
    const int n = static_cast<int>(state.range(0));
    state.counters["after_delaunay_ns_per_point"] = 1e9 * *mean * after_delaunay_share_sum / phased_iterations / n;
  }
}

void apply_sizes(benchmark::internal::Benchmark* b) {
  for (long long n = 1'000; n <= settings().max_n; n *= 10) b->Arg(n);
  b->ArgName("n")->UseManualTime()->Unit(benchmark::kMillisecond);
}

// Removes "--name=value" from argv and returns the value, if present.
std::optional<std::string> take_flag(int& argc, char** argv, const std::string& name) {
  const std::string prefix = "--" + name + "=";
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]).rfind(prefix, 0) == 0) {
      std::string value = argv[i] + prefix.size();
      std::copy(argv + i + 1, argv + argc, argv + i);
      --argc;
      return value;
    }
  }
  return std::nullopt;
}

}  // namespace
}  // namespace curvebench

int main(int argc, char** argv) {
  using namespace curvebench;
  if (const auto run = take_flag(argc, argv, "peak_memory_child")) return run_peak_memory_child(*run);
  if (const auto value = take_flag(argc, argv, "max_n")) settings().max_n = std::stoll(*value);
  if (const auto value = take_flag(argc, argv, "max_run_seconds")) settings().max_run_seconds = std::stod(*value);
  // The bare construction's own rows first: the floor in ns per point.
  for (const auto& input : kInputs) {
    apply_sizes(benchmark::RegisterBenchmark(("delaunay/" + input).c_str(), BM_Delaunay, input));
  }
  for (const Algorithm* algorithm : all_algorithms()) {
    for (const auto& input : kInputs) {
      apply_sizes(benchmark::RegisterBenchmark((algorithm->name() + "/" + input).c_str(), BM_Algorithm,
                                               algorithm, input));
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
