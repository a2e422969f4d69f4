// Scaling suite: every algorithm against the bare CGAL Delaunay construction of the same
// points, side by side in one run. Each algorithm's row carries its time as a ratio to the
// Delaunay time measured for the same n in this run (counter "x_delaunay"), its time per
// point, and the process's peak resident memory so far.
//
// Run: curvebench_benchmark [--benchmark_format=json] [--benchmark_filter=...]
#include <benchmark/benchmark.h>
#include <sys/resource.h>

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
    const auto start = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(bare_delaunay_vertex_count(points));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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
  double total = 0.0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    auto result = algorithm->reconstruct(points, params);
    benchmark::DoNotOptimize(result);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.SetIterationTime(seconds);
    total += seconds;
  }
  report(state, n, total);
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
