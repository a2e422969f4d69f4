// The "labeling" algorithm: incremental Voronoi-vertex labeling (Peethambaran et al. 2019),
// producing the curve, the interior medial axis and the dominant points from one labeling.
#include "labeling/labeling_algorithm.h"

#include <utility>

#include "core/registry.h"
#include "labeling/extract_shapes.h"

namespace curvebench {
namespace {

class LabelingAlgorithm final : public Algorithm {
 public:
  LabelingAlgorithm(std::string name, std::string citation, LabelFunction label)
      : info_{std::move(name), std::move(citation), kCurve | kMedialAxis | kDominantPoints, {}, SiteInput::kDelaunay},
        label_(label) {}
  const AlgorithmInfo& info() const override { return info_; }

  SiteResult run(const Sites& sites, const ParameterValues&, PhaseTimer& timer) const override {
    const VoronoiLabels labels = label_(*sites.delaunay);
    timer.lap("labeling");
    SiteResult result = shapes_from_labels(*sites.delaunay, labels);
    timer.lap("extract");
    return result;
  }

 private:
  AlgorithmInfo info_;
  LabelFunction label_;
};

[[maybe_unused]] const bool registered = register_algorithm(make_labeling_algorithm(
    "labeling",
    "Incremental Voronoi-vertex labeling (Peethambaran, Parakkat, Tagliasacchi, Wang, Muthuganapathy; CGF 2019)",
    label_voronoi_vertices));

}  // namespace

std::unique_ptr<Algorithm> make_labeling_algorithm(std::string name, std::string citation, LabelFunction label) {
  return std::make_unique<LabelingAlgorithm>(std::move(name), std::move(citation), label);
}

}  // namespace curvebench
