// The "crawl" algorithm: Crawl through Neighbors on the shared Delaunay layer (crawl_edges.h).
#include "core/registry.h"
#include "crawl/crawl_edges.h"

namespace curvebench {
namespace {

class Crawl final : public Algorithm {
 public:
  const AlgorithmInfo& info() const override {
    static const AlgorithmInfo about{
        "crawl",
        "Crawl through Neighbors: greedy growth of curves along nearest unused Delaunay neighbours (Parakkat, "
        "Muthuganapathy; CGF 2016)",
        kCurve, {}, SiteInput::kDelaunay};
    return about;
  }

  SiteResult run(const Sites& sites, const ParameterValues&, PhaseTimer& timer) const override {
    SiteResult result;
    result.curve_edges = crawl_edges(*sites.delaunay);
    timer.lap("crawl");
    return result;
  }
};

CURVEBENCH_REGISTER_ALGORITHM(Crawl);

}  // namespace
}  // namespace curvebench
