#include "labeling/labeling.h"

#include <algorithm>

#include "core/phase_timer.h"
#include "labeling/extract_shapes.h"
#include "labeling/label_voronoi_vertices.h"

namespace curvebench {
namespace {

class Labeling final : public Algorithm {
 public:
  std::string name() const override { return "labeling"; }
  std::string description() const override {
    return "Incremental Voronoi-vertex labeling (Peethambaran, Parakkat, Tagliasacchi, Wang, Muthuganapathy; CGF 2019)";
  }
  unsigned outputs() const override { return kCurve | kMedialAxis | kDominantPoints; }

  Reconstruction reconstruct(std::span<const Point2> points, const Parameters& params) const override {
    resolve_parameters(parameters(), params, name());
    PhaseTimer timer;
    const DelaunayVoronoi dv = build_delaunay_voronoi(points);
    timer.lap("delaunay");
    require_triangulation(dv, name());
    const VoronoiLabels labels = label_voronoi_vertices(dv);
    timer.lap("labeling");
    Reconstruction result;
    result.distinct_points = dv.site_count();
    auto [curve, dominant] = extract_curve_and_dominant_points(dv, labels);
    result.curve_edges = to_input_indices(dv, std::move(curve));
    result.medial_axis = extract_interior_medial_axis(dv, labels);
    for (int& site : dominant) site = dv.input_of_site[site];
    std::sort(dominant.begin(), dominant.end());  // in input order, whatever the site numbering
    result.dominant_points = std::move(dominant);
    timer.lap("extract");
    result.timing_ms = timer.finish();
    return result;
  }
};

}  // namespace

std::unique_ptr<Algorithm> make_labeling_algorithm() { return std::make_unique<Labeling>(); }

}  // namespace curvebench
