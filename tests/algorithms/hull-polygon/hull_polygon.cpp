// "hull-polygon", an algorithm only the tests compile: the convex hull of the sites as a
// polygon, less its first `skip` edges. It is written exactly as an algorithm folder under
// algorithms/ would be, so that the tests can show that such a folder needs no other edit to
// be listed, validated, swept and checked.
#include "core/registry.h"
#include "voronoi/delaunay_voronoi.h"

namespace curvebench {
namespace {

class HullPolygon final : public Algorithm {
 public:
  const AlgorithmInfo& info() const override {
    static const AlgorithmInfo about{"hull-polygon",
                                     "test only: the convex hull polygon of the sites",
                                     kCurve,
                                     {integer_parameter("skip", 0, 0, 3, "hull edges to leave out, from the first")},
                                     SiteInput::kDelaunay};
    return about;
  }

  SiteResult run(const Sites& sites, const ParameterValues& params, PhaseTimer& timer) const override {
    const std::vector<int>& hull = sites.delaunay->hull;
    const int m = static_cast<int>(hull.size());
    SiteResult result;
    result.curve_edges.emplace();
    for (int k = static_cast<int>(params.integer("skip")); k < m; ++k) {
      result.curve_edges->push_back(make_edge(hull[k], hull[(k + 1) % m]));
    }
    timer.lap("hull");
    return result;
  }
};

CURVEBENCH_REGISTER_ALGORITHM(HullPolygon);

}  // namespace
}  // namespace curvebench
