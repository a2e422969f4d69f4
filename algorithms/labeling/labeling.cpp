// The "labeling" algorithm: incremental Voronoi-vertex labeling (Peethambaran et al. 2019),
// producing the curve, the interior medial axis and the dominant points from one labeling.
#include "core/registry.h"
#include "labeling/extract_shapes.h"
#include "labeling/label_voronoi_vertices.h"

namespace curvebench {
namespace {

class Labeling final : public Algorithm {
 public:
  const AlgorithmInfo& info() const override {
    static const AlgorithmInfo about{
        "labeling",
        "Incremental Voronoi-vertex labeling (Peethambaran, Parakkat, Tagliasacchi, Wang, Muthuganapathy; CGF 2019)",
        kCurve | kMedialAxis | kDominantPoints, {}, SiteInput::kDelaunay};
    return about;
  }

  SiteResult run(const Sites& sites, const ParameterValues&, PhaseTimer& timer) const override {
    const DelaunayVoronoi& dv = *sites.delaunay;
    const VoronoiLabels labels = label_voronoi_vertices(dv);
    timer.lap("labeling");
    SiteResult result;
    auto [curve, dominant] = extract_curve_and_dominant_points(dv, labels);
    result.curve_edges = std::move(curve);
    result.dominant_points = std::move(dominant);
    result.medial_axis = extract_interior_medial_axis(dv, labels);
    timer.lap("extract");
    return result;
  }
};

CURVEBENCH_REGISTER_ALGORITHM(Labeling);

}  // namespace
}  // namespace curvebench
