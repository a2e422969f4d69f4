// Scaling suite: every algorithm against the bare CGAL Delaunay construction of the same
// points, side by side in one run. Each algorithm's row carries its time as a ratio to the
// Delaunay time measured for the same n in this run (counter "x_delaunay"), its time per
// point, the time per point of its phases after its own "delaunay" phase
// ("after_delaunay_ns_per_point", from Reconstruction::timing_ms), and the process's peak
// resident memory so far. Times are the thread's CPU time, so that other work on the machine
// does not enter the ratios; the code timed is single-threaded.
//
// Run: curvebench_benchmark [--benchmark_format=json] [--benchmark_filter=...]
#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <vector>

#include "core/registry.h"
#include "voronoi/delaunay_voronoi.h"

namespace curvebench {
namespace {

// n points at random positions along the rose r = 1 + 0.3 cos(5t), a smooth closed curve
// with five pseudo-concavities. Fixed seed: every run times the same points.
std::vector<Point2> smooth_curve_points(int n) {
  std::mt19937_64 rng(20190501u + static_cast<unsigned>(n));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> t(n);
  for (auto& value : t) value = 2 * std::numbers::pi * unit(rng);
  std::sort(t.begin(), t.end());
  std::vector<Point2> points;
  points.reserve(n);
  for (double angle : t) {
    const double r = 1.0 + 0.3 * std::cos(5 * angle);
    points.push_back({r * std::cos(angle), r * std::sin(angle)});
  }
  return points;
}

const std::vector<Point2>& cached_points(int n) {
  static std::map<int, std::vector<Point2>> cache;
  auto it = cache.find(n);
  if (it == cache.end()) it = cache.emplace(n, smooth_curve_points(n)).first;
  return it->second;
}

std::map<int, double>& delaunay_seconds() {  // mean Delaunay time per n, from this run
  static std::map<int, double> seconds;
  return seconds;
}

double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double peak_memory_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

void report(benchmark::State& state, int n, double total_seconds) {
  const double mean = total_seconds / static_cast<double>(state.iterations());
  state.counters["ns_per_point"] = 1e9 * mean / n;
  state.counters["peak_MiB"] = peak_memory_mib();
  const auto it = delaunay_seconds().find(n);
  if (it != delaunay_seconds().end()) state.counters["x_delaunay"] = mean / it->second;
}

void BM_Delaunay(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto& points = cached_points(n);
  double total = 0.0;
  for (auto _ : state) {
    const double start = thread_cpu_seconds();
    benchmark::DoNotOptimize(bare_delaunay_vertex_count(points));
    const double seconds = thread_cpu_seconds() - start;
    state.SetIterationTime(seconds);
    total += seconds;
  }
  delaunay_seconds()[n] = total / static_cast<double>(state.iterations());
  report(state, n, total);
}

void BM_Algorithm(benchmark::State& state, const Algorithm* algorithm) {
  const int n = static_cast<int>(state.range(0));
  const auto& points = cached_points(n);
  const Parameters params = resolve_parameters(algorithm->parameters(), {}, algorithm->name());
  double total = 0.0, after_delaunay_ms = 0.0;
  for (auto _ : state) {
    const double start = thread_cpu_seconds();
    auto result = algorithm->reconstruct(points, params);
    benchmark::DoNotOptimize(result);
    const double seconds = thread_cpu_seconds() - start;
    state.SetIterationTime(seconds);
    total += seconds;
    const auto& phases = result.timing_ms;
    if (phases.size() >= 2 && phases.front().first == "delaunay") after_delaunay_ms += phases.back().second - phases.front().second;
  }
  report(state, n, total);
  if (after_delaunay_ms > 0) state.counters["after_delaunay_ns_per_point"] = 1e6 * after_delaunay_ms / static_cast<double>(state.iterations()) / n;
}

void apply_sizes(benchmark::internal::Benchmark* b) {
  for (int n : {10'000, 100'000, 1'000'000}) b->Arg(n);
  b->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(0.5);
}

}  // namespace
}  // namespace curvebench

int main(int argc, char** argv) {
  using namespace curvebench;
  // Delaunay first at every n, so each algorithm's ratio uses this run's floor.
  apply_sizes(benchmark::RegisterBenchmark("delaunay", BM_Delaunay));
  for (const auto& algorithm : all_algorithms()) {
    apply_sizes(benchmark::RegisterBenchmark(algorithm->name().c_str(), BM_Algorithm, algorithm.get()));
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
