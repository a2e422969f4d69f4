// The "labeling-holes" algorithm: the paper's incremental Voronoi-vertex labeling
// (Peethambaran et al. 2019) extended to holes and nested curves (label_voronoi_vertices_with_holes.h).
#include "core/registry.h"
#include "labeling-holes/label_voronoi_vertices_with_holes.h"
#include "labeling/extract_shapes.h"

namespace curvebench {
namespace {

class LabelingHoles final : public Algorithm {
 public:
  const AlgorithmInfo& info() const override {
    static const AlgorithmInfo about{
        "labeling-holes",
        "Incremental Voronoi-vertex labeling (Peethambaran, Parakkat, Tagliasacchi, Wang, Muthuganapathy; CGF 2019), "
        "with walks inside the regions it cannot reach: holes and nested curves",
        kCurve | kMedialAxis | kDominantPoints, {}, SiteInput::kDelaunay};
    return about;
  }

  SiteResult run(const Sites& sites, const ParameterValues&, PhaseTimer& timer) const override {
    const DelaunayVoronoi& dv = *sites.delaunay;
    const VoronoiLabels labels = label_voronoi_vertices_with_holes(dv);
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

CURVEBENCH_REGISTER_ALGORITHM(LabelingHoles);

}  // namespace
}  // namespace curvebench
