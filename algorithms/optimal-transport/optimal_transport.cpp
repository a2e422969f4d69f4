// The "optimal-transport" algorithm: CGAL's optimal-transport reconstruction of the sites.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Optimal_transportation_reconstruction_2.h>

#include <algorithm>
#include <exception>
#include <cmath>
#include <iterator>
#include <limits>
#include <thread>

#include "core/registry.h"
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
  const AlgorithmInfo& info() const override {
    static const AlgorithmInfo about{
        "optimal-transport",
        "CGAL's optimal-transport reconstruction (Optimal_transportation_reconstruction_2; de Goes et al., SGP 2011); "
        "outputs new vertices",
        kNewCurve,
        {real_parameter("tolerance", 2.0, 0.0, std::numeric_limits<double>::max(),
                        "stop collapsing edges once the Wasserstein transport cost per sample would exceed this many "
                        "mean nearest-neighbour spacings (used when vertices is 0)",
                        /*minimum_exclusive=*/true),
         integer_parameter("vertices", 0, 0, 1000000000,
                           "if > 0, collapse until this many vertices remain instead of using tolerance"),
         integer_parameter("relocation", 0, 0, 100,
                           "vertex relocation steps after each edge collapse (CGAL's default is 2, several times slower)"),
         boolean_parameter("flip", false,
                           "flip edges so that every edge can be collapsed (CGAL's default; slower, the same output on "
                           "epsilon-samples)"),
         integer_parameter("max_points", 20000, 0, 1000000000,
                           "refuse more distinct points than this (0: no limit): the edge-collapse simulation grows "
                           "faster than linearly")},
        SiteInput::kDelaunay};
    return about;
  }

  SiteResult run(const Sites& input, const ParameterValues& params, PhaseTimer& timer) const override {
    const double tolerance = params.real("tolerance");
    const auto vertices = params.integer("vertices"), relocation = params.integer("relocation");
    const bool flip = params.boolean("flip");
    const auto max_points = params.integer("max_points");
    const DelaunayVoronoi& dv = *input.delaunay;
    if (max_points > 0 && dv.site_count() > max_points) {
      throw InputError("optimal-transport: " + std::to_string(dv.site_count()) + " distinct points exceed max_points=" +
                       std::to_string(max_points) + " (raise it with --param max_points=N, 0 for no limit)");
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
        otr.set_use_flip(flip);
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

    SiteResult result;
    result.new_curve = PolylineGraph{std::move(out), std::move(edges)};
    timer.lap("extract");
    return result;
  }
};

CURVEBENCH_REGISTER_ALGORITHM(OptimalTransport);

}  // namespace
}  // namespace curvebench
