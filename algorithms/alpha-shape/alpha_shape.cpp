#include "alpha-shape/alpha_shape.h"

#include <CGAL/Alpha_shape_2.h>
#include <CGAL/Alpha_shape_face_base_2.h>
#include <CGAL/Alpha_shape_vertex_base_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

#include "core/phase_timer.h"
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
  std::string name() const override { return "alpha-shape"; }
  std::string description() const override {
    return "Boundary of CGAL's regularized alpha shape (Alpha_shape_2), alpha from CGAL's optimal alpha unless given";
  }
  unsigned outputs() const override { return kCurve; }
  std::vector<ParameterSpec> parameters() const override {
    return {{"alpha", 0.0,
             "squared radius of the alpha disk in squared input units (CGAL convention); 0: the optimal alpha, the "
             "smallest at which every sample is on the shape and it has at most `components` solid components"},
            {"components", 1.0, "solid components allowed when choosing alpha automatically: the number of curves"}};
  }

  Reconstruction reconstruct(std::span<const Point2> points, const Parameters& given) const override {
    const Parameters params = resolve_parameters(parameters(), given, name());
    const double alpha = params.at("alpha");
    const double components = params.at("components");
    if (!(alpha >= 0.0) || !std::isfinite(alpha)) throw InputError("alpha-shape: alpha must be a number >= 0");
    if (!(components >= 1.0) || components != std::floor(components) || components > 1e9) {
      throw InputError("alpha-shape: components must be a whole number >= 1");
    }
    PhaseTimer timer;
    // The shared layer removes duplicates and rejects input without a closed curve, with the
    // same messages as every other algorithm; CGAL then triangulates the distinct sites.
    const DelaunayVoronoi dv = build_delaunay_voronoi(points);
    timer.lap("delaunay");
    require_triangulation(dv, name());

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
    Reconstruction result;
    result.distinct_points = dv.site_count();
    result.curve_edges = to_input_indices(dv, std::move(edges));
    timer.lap("extract");
    result.timing_ms = timer.finish();
    return result;
  }
};

}  // namespace

std::unique_ptr<Algorithm> make_alpha_shape_algorithm() { return std::make_unique<AlphaShapeAlgorithm>(); }

}  // namespace curvebench
