#include "optimal-transport/optimal_transport.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Optimal_transportation_reconstruction_2.h>

#include <algorithm>
#include <exception>
#include <cmath>
#include <iterator>
#include <limits>
#include <thread>

#include "core/phase_timer.h"
#include "voronoi/delaunay_voronoi.h"

namespace curvebench {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Otr = CGAL::Optimal_transportation_reconstruction_2<Kernel>;

// Mean distance from each site to its nearest Delaunay neighbour: the sampling scale that
// `tolerance` is measured in, so that the default does not depend on the units of the input.
double mean_nearest_spacing(const DelaunayVoronoi& dv) {
  std::vector<double> nearest(dv.site_count(), std::numeric_limits<double>::infinity());
  for (const auto& tri : dv.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      const double d = distance(dv.sites[a], dv.sites[b]);
      nearest[a] = std::min(nearest[a], d);
      nearest[b] = std::min(nearest[b], d);
    }
  }
  double sum = 0.0;
  for (double d : nearest) sum += d;
  return sum / static_cast<double>(nearest.size());
}

class OptimalTransport final : public Algorithm {
 public:
  std::string name() const override { return "optimal-transport"; }
  std::string description() const override {
    return "CGAL's optimal-transport reconstruction (Optimal_transportation_reconstruction_2; de Goes et al., SGP "
           "2011); outputs new vertices";
  }
  unsigned outputs() const override { return kCurve; }
  std::vector<ParameterSpec> parameters() const override {
    return {{"tolerance", kDefaultTolerance,
             "stop collapsing edges once the Wasserstein transport cost per sample would exceed this many mean "
             "nearest-neighbour spacings (used when vertices is 0)"},
            {"vertices", 0.0, "if > 0, collapse until this many vertices remain instead of using tolerance"},
            {"relocation", 0.0, "vertex relocation steps after each edge collapse (CGAL's default 2 is 2.5 to 6 times slower)"},
            {"flip", 0.0,
             "1: flip edges so that every edge can be collapsed (CGAL's default; about 1.5x slower, the same output "
             "on epsilon-samples), 0: no flips"},
            {"max_points", kDefaultMaxPoints,
             "refuse more distinct points than this (0: no limit): the edge-collapse simulation takes about 4 s at "
             "10^4 points and grows faster than linearly"}};
  }

  Reconstruction reconstruct(std::span<const Point2> points, const Parameters& given) const override {
    const Parameters params = resolve_parameters(parameters(), given, name());
    const double tolerance = params.at("tolerance"), vertices = params.at("vertices");
    const double relocation = params.at("relocation"), flip = params.at("flip");
    if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
      throw InputError("optimal-transport: tolerance must be a number > 0");
    }
    auto whole = [](double v) { return v >= 0.0 && v <= 1e9 && v == std::floor(v); };
    if (!whole(vertices)) throw InputError("optimal-transport: vertices must be a whole number >= 0");
    if (!whole(relocation) || relocation > 100) {
      throw InputError("optimal-transport: relocation must be a whole number from 0 to 100");
    }
    if (flip != 0.0 && flip != 1.0) throw InputError("optimal-transport: flip must be 0 or 1");
    const double max_points = params.at("max_points");
    if (!whole(max_points)) throw InputError("optimal-transport: max_points must be a whole number >= 0");
    PhaseTimer timer;
    // The shared layer removes duplicates (each distinct point carries mass 1) and rejects
    // input without a closed curve, with the same messages as every other algorithm.
    const DelaunayVoronoi dv = build_delaunay_voronoi(points);
    timer.lap("delaunay");
    require_triangulation(dv, name());
    if (max_points > 0 && dv.site_count() > max_points) {
      throw InputError("optimal-transport: " + std::to_string(dv.site_count()) + " distinct points exceed max_points=" +
                       std::to_string(static_cast<long>(max_points)) + " (raise it with --param max_points=N, 0 for no limit)");
    }

    std::vector<Kernel::Point_2> sites;
    sites.reserve(dv.sites.size());
    for (const auto& p : dv.sites) sites.emplace_back(p.x, p.y);
    // CGAL's reconstruction depends on the layout of the heap it runs in (the same run gave
    // another curve under GLIBC_TUNABLES=glibc.malloc.tcache_count=0, and valgrind finds no
    // uninitialised read), so a sweep's row and `reconstruct` on the same file differed
    // whenever the process had allocated other things first; a longer path was enough. A new
    // thread gets a malloc arena of its own, empty in a process that has not run this before
    // (every sweep run and every `reconstruct`), whatever else that process allocated.
    std::vector<Kernel::Point_2> isolated;
    std::vector<Kernel::Segment_2> segments;
    std::exception_ptr failure;
    std::thread([&] {
      try {
        Otr otr(sites);
        otr.set_relocation(static_cast<unsigned>(relocation));
        otr.set_use_flip(flip == 1.0);
        if (vertices > 0) {
          otr.run_until(static_cast<std::size_t>(vertices));
        } else {
          otr.run_under_wasserstein_tolerance(tolerance * mean_nearest_spacing(dv));
        }
        // list_output rather than CGAL's indexed_output, which is quadratic in the output size.
        otr.list_output(std::back_inserter(isolated), std::back_inserter(segments));
      } catch (...) {
        failure = std::current_exception();
      }
    }).join();
    if (failure) std::rethrow_exception(failure);
    timer.lap("optimal_transport");

    std::vector<Point2> out;
    for (const auto& p : isolated) out.push_back({p.x(), p.y()});
    for (const auto& s : segments) {
      out.push_back({s.source().x(), s.source().y()});
      out.push_back({s.target().x(), s.target().y()});
    }
    auto before = [](Point2 a, Point2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
    std::sort(out.begin(), out.end(), before);
    out.erase(std::unique(out.begin(), out.end()), out.end());
    auto index_of = [&](const Kernel::Point_2& p) {
      return static_cast<int>(std::lower_bound(out.begin(), out.end(), Point2{p.x(), p.y()}, before) - out.begin());
    };
    std::vector<Edge> edges;
    edges.reserve(segments.size());
    for (const auto& s : segments) {
      const int a = index_of(s.source()), b = index_of(s.target());
      if (a != b) edges.push_back(make_edge(a, b));
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

    Reconstruction result;
    result.distinct_points = dv.site_count();
    result.curve_vertices = std::move(out);
    result.curve_edges = std::move(edges);
    timer.lap("extract");
    result.timing_ms = timer.finish();
    return result;
  }

 private:
  static constexpr double kDefaultTolerance = 2.0;
  static constexpr double kDefaultMaxPoints = 20000;
};

}  // namespace

std::unique_ptr<Algorithm> make_optimal_transport_algorithm() { return std::make_unique<OptimalTransport>(); }

}  // namespace curvebench
