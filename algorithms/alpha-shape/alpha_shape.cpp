// The "alpha-shape" algorithm: the boundary of CGAL's regularized alpha shape of the sites.
#include <CGAL/Alpha_shape_2.h>
#include <CGAL/Alpha_shape_face_base_2.h>
#include <CGAL/Alpha_shape_vertex_base_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <utility>

#include "core/registry.h"
#include "voronoi/delaunay_voronoi.h"

namespace curvebench {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Alpha_shape_vertex_base_2<Kernel, CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>>;
using FaceBase = CGAL::Alpha_shape_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Triangulation = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
using AlphaShape = CGAL::Alpha_shape_2<Triangulation>;

class AlphaShapeAlgorithm final : public Algorithm {
 public:
  const AlgorithmInfo& info() const override {
    static const AlgorithmInfo about{
        "alpha-shape",
        "Boundary of CGAL's regularized alpha shape (Alpha_shape_2), alpha from CGAL's optimal alpha unless given",
        kCurve,
        {real_parameter("alpha", 0.0, 0.0, std::numeric_limits<double>::max(),
                        "squared radius of the alpha disk in squared input units (CGAL convention); 0: the optimal "
                        "alpha, the smallest at which every sample is on the shape and it has at most `components` "
                        "solid components"),
         integer_parameter("components", 1, 1, 1000000000,
                           "solid components allowed when choosing alpha automatically: the number of curves")},
        SiteInput::kDelaunay};
    return about;
  }

  SiteResult run(const Sites& sites, const ParameterValues& params, PhaseTimer& timer) const override {
    const double alpha = params.real("alpha");
    const auto components = params.integer("components");
    const DelaunayVoronoi& dv = *sites.delaunay;
    // CGAL's alpha shape needs its own triangulation type; it triangulates the distinct sites.
    std::vector<std::pair<Kernel::Point_2, int>> indexed;
    indexed.reserve(dv.sites.size());
    for (int s = 0; s < dv.site_count(); ++s) indexed.emplace_back(Kernel::Point_2(dv.sites[s].x, dv.sites[s].y), s);
    Triangulation triangulation;
    triangulation.insert(indexed.begin(), indexed.end());
    AlphaShape shape(triangulation, 0, AlphaShape::REGULARIZED);
    double chosen = alpha;
    if (alpha == 0.0) {
      // An empty spectrum means every squared circumradius rounded to zero (coordinates of
      // denormal size): there is no alpha to choose, and no largest one to fall back on.
      if (shape.alpha_begin() == shape.alpha_end()) {
        throw InputError("alpha-shape: every triangle's squared circumradius rounds to zero in double precision; scale the points up");
      }
      auto optimal = shape.find_optimal_alpha(static_cast<AlphaShape::size_type>(components));
      chosen = optimal != shape.alpha_end() ? *optimal : *std::prev(shape.alpha_end());
    }
    shape.set_alpha(chosen);
    timer.lap("alpha_shape");

    std::vector<Edge> edges;
    for (auto e = shape.alpha_shape_edges_begin(); e != shape.alpha_shape_edges_end(); ++e) {
      const auto face = e->first;
      const int i = e->second;
      edges.push_back(make_edge(face->vertex(AlphaShape::ccw(i))->info(), face->vertex(AlphaShape::cw(i))->info()));
    }
    std::sort(edges.begin(), edges.end());
    SiteResult result;
    result.curve_edges = std::move(edges);
    timer.lap("extract");
    return result;
  }
};

CURVEBENCH_REGISTER_ALGORITHM(AlphaShapeAlgorithm);

}  // namespace
}  // namespace curvebench
