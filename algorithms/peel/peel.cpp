// The "peel" algorithm: Peeling the Longest on the shared Delaunay layer (peel_edges.h), with
// the authors' optional noise-removal step first (noise_representatives.h).
#include <limits>

#include "core/registry.h"
#include "peel/noise_representatives.h"
#include "peel/peel_edges.h"

namespace curvebench {
namespace {

class Peel final : public Algorithm {
 public:
  const AlgorithmInfo& info() const override {
    static const AlgorithmInfo about{
        "peel",
        "Peeling the Longest: Delaunay edges that are never a triangle's longest side, filtered to degree 2 "
        "(Parakkat, Methirumangalath, Muthuganapathy; Computers & Graphics 2018)",
        kCurve,
        {real_parameter("len", 0.0, 0.0, std::numeric_limits<double>::max(),
                        "reconnection factor: a site left with one edge of length d joins its nearest free Delaunay "
                        "neighbour closer than len * d (0: no reconnection)"),
         real_parameter("simplify_radius", 0.0, 0.0, std::numeric_limits<double>::max(),
                        "noise removal first (the authors' tau, input units): evenly surrounded samples each stand "
                        "for the samples closer than this, the rest are dropped (0: off)"),
         boolean_parameter("reference_degree_rule", false,
                           "the authors' asymmetric degree count instead of the symmetric filter (for comparison)")},
        SiteInput::kDelaunay,
        // Spec section 2: all collinear, no finite triangle, so nothing to peel and no edges.
        CollinearInput::kReconstructed};
    return about;
  }

  SiteResult run(const Sites& sites, const ParameterValues& params, PhaseTimer& timer) const override {
    const double len = params.real("len"), radius = params.real("simplify_radius");
    const bool reference_rule = params.boolean("reference_degree_rule");
    SiteResult result;
    if (radius == 0.0) {
      result.curve_edges = peel_edges(*sites.delaunay, len, reference_rule);
      timer.lap("peel");
      return result;
    }
    // The representatives are triangulated afresh and peeled; the other samples stay isolated.
    const std::vector<int> kept = noise_representatives(*sites.delaunay, radius);
    std::vector<Point2> points;
    points.reserve(kept.size());
    for (int site : kept) points.push_back(sites.points[site]);
    timer.lap("noise_removal");
    const DelaunayVoronoi reduced = build_delaunay_voronoi(points);
    std::vector<Edge> edges = peel_edges(reduced, len, reference_rule);
    for (Edge& e : edges) e = make_edge(kept[reduced.input_of_site[e[0]]], kept[reduced.input_of_site[e[1]]]);
    result.curve_edges = std::move(edges);
    timer.lap("peel");
    return result;
  }
};

CURVEBENCH_REGISTER_ALGORITHM(Peel);

}  // namespace
}  // namespace curvebench
