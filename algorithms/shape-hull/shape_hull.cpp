// The "shape-hull" algorithm: the boundary of the shape-hull graph, sculpted from the shared
// Delaunay layer (shape_hull_triangles.h, shape_hull_edges.h).
#include "core/registry.h"
#include "shape-hull/shape_hull_edges.h"

namespace curvebench {
namespace {

class ShapeHull final : public Algorithm {
 public:
  const AlgorithmInfo& info() const override {
    static const AlgorithmInfo about{
        "shape-hull",
        "Shape-hull: Delaunay triangles sculpted from the hull inwards by circumradius, the boundary as one closed "
        "curve (Peethambaran, Muthuganapathy; Computer-Aided Design 2015)",
        kCurve, {}, SiteInput::kDelaunay};
    return about;
  }

  SiteResult run(const Sites& sites, const ParameterValues&, PhaseTimer& timer) const override {
    SiteResult result;
    result.curve_edges = shape_hull_edges(*sites.delaunay);
    timer.lap("shape-hull");
    return result;
  }
};

CURVEBENCH_REGISTER_ALGORITHM(ShapeHull);

}  // namespace
}  // namespace curvebench
