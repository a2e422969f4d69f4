#include "local-crust/local_crust.h"

#include "core/phase_timer.h"
#include "local-crust/anti_crust_medial_axis.h"
#include "local-crust/one_step_crust.h"

namespace curvebench {
namespace {

class LocalCrust final : public Algorithm {
 public:
  std::string name() const override { return "local-crust"; }
  std::string description() const override {
    return "Local (one-step) crust and anti-crust: one InCircle test per Delaunay/Voronoi edge pair gives curve "
           "and skeleton (Gold, SCG 1999; Gold, Snoeyink, Algorithmica 2001)";
  }
  unsigned outputs() const override { return kCurve | kMedialAxis; }

  Reconstruction reconstruct(std::span<const Point2> points, const Parameters& params) const override {
    resolve_parameters(parameters(), params, name());
    PhaseTimer timer;
    const DelaunayVoronoi dv = build_delaunay_voronoi(points);
    timer.lap("delaunay");
    require_triangulation(dv, name());
    OneStepCrust crust = one_step_crust(dv);
    timer.lap("crust");
    Reconstruction result;
    result.distinct_points = dv.site_count();
    result.medial_axis = anti_crust_medial_axis(dv, crust);
    result.curve_edges = to_input_indices(dv, std::move(crust.curve));
    timer.lap("skeleton");
    result.timing_ms = timer.finish();
    return result;
  }
};

}  // namespace

std::unique_ptr<Algorithm> make_local_crust_algorithm() { return std::make_unique<LocalCrust>(); }

}  // namespace curvebench
