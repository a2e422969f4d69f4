#include "core/algorithm.h"

#include <CGAL/exceptions.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/distinct_points.h"
#include "voronoi/delaunay_voronoi.h"

namespace curvebench {
namespace {

void require_finite(std::span<const Point2> points, const std::string& algorithm) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y)) {
      throw InputError(algorithm + ": point " + std::to_string(i) + " has a coordinate that is not a finite number");
    }
  }
}

// The degenerate-input rule every algorithm shares: a curve needs three distinct points, and
// a closed one needs them not all on one line. Collinear sites reach only the algorithms that
// declare an output for them.
void require_sites(int distinct, bool collinear, const AlgorithmInfo& about) {
  const std::string& algorithm = about.name;
  if (distinct < 3) {
    throw InputError(algorithm + " needs at least 3 distinct points, the input has " + std::to_string(distinct));
  }
  if (collinear && about.collinear == CollinearInput::kRefused) {
    throw InputError(algorithm + ": all " + std::to_string(distinct) +
                     " distinct points are collinear, so they bound no closed curve");
  }
}

void require_output(bool present, unsigned outputs, Output part, const std::string& algorithm, const char* what) {
  if (present != ((outputs & part) != 0)) {
    throw std::logic_error(algorithm + ": " + (present ? "produced " : "did not produce ") + what +
                           (present ? " it does not declare" : " it declares"));
  }
}

void require_indices(const std::vector<Edge>& edges, std::size_t count, const std::string& algorithm, const char* what) {
  for (const Edge& e : edges) {
    if (e[0] < 0 || e[1] < 0 || static_cast<std::size_t>(e[0]) >= count || static_cast<std::size_t>(e[1]) >= count ||
        e[0] == e[1]) {
      throw std::logic_error(algorithm + ": " + what + " edge (" + std::to_string(e[0]) + ", " + std::to_string(e[1]) +
                             ") is not between two of its " + std::to_string(count) + " vertices");
    }
  }
}

// Checks `result` against what the algorithm declares, then maps sites to input indices.
Reconstruction to_input(SiteResult result, std::span<const int> input_of_site, std::span<const int> site_of_input,
                        const AlgorithmInfo& info) {
  const std::size_t sites = input_of_site.size();
  require_output(result.curve_edges.has_value(), info.outputs, kCurve, info.name, "curve edges");
  require_output(result.moved_points.has_value(), info.outputs, kMovedPoints, info.name, "moved points");
  require_output(result.new_curve.has_value(), info.outputs, kNewCurve, info.name, "a curve on new vertices");
  require_output(result.medial_axis.has_value(), info.outputs, kMedialAxis, info.name, "a medial axis");
  require_output(result.dominant_points.has_value(), info.outputs, kDominantPoints, info.name, "dominant points");

  Reconstruction out;
  out.distinct_points = static_cast<int>(sites);
  if (result.curve_edges) {
    require_indices(*result.curve_edges, sites, info.name, "curve");
    for (Edge& e : *result.curve_edges) e = make_edge(input_of_site[e[0]], input_of_site[e[1]]);
    out.curve_edges = std::move(result.curve_edges);
  }
  if (result.moved_points) {
    if (result.moved_points->size() != sites) {
      throw std::logic_error(info.name + ": moved " + std::to_string(result.moved_points->size()) + " points, not " +
                             std::to_string(sites));
    }
    // A duplicate moves with its first occurrence.
    std::vector<Point2> moved(site_of_input.size());
    for (std::size_t i = 0; i < moved.size(); ++i) moved[i] = (*result.moved_points)[site_of_input[i]];
    out.moved_points = std::move(moved);
  }
  if (result.new_curve) {
    require_indices(result.new_curve->edges, result.new_curve->vertices.size(), info.name, "new curve");
    out.new_curve = std::move(result.new_curve);
  }
  if (result.medial_axis) {
    require_indices(result.medial_axis->edges, result.medial_axis->vertices.size(), info.name, "medial-axis");
    out.medial_axis = std::move(result.medial_axis);
  }
  if (result.dominant_points) {
    for (int& site : *result.dominant_points) {
      if (site < 0 || static_cast<std::size_t>(site) >= sites) {
        throw std::logic_error(info.name + ": dominant point " + std::to_string(site) + " is not a site");
      }
      site = input_of_site[site];
    }
    std::sort(result.dominant_points->begin(), result.dominant_points->end());  // input order, whatever the numbering
    out.dominant_points = std::move(result.dominant_points);
  }
  return out;
}

// CGAL checks its preconditions with exceptions; with coordinates near the limits of double
// precision (beyond about 1e150) a construction inside the triangulation can overflow and
// fail one. That is a limit of the input, reported as such rather than as a crash.
DelaunayVoronoi triangulate(std::span<const Point2> points, const std::string& algorithm) {
  try {
    return build_delaunay_voronoi(points);
  } catch (const CGAL::Failure_exception& e) {
    throw InputError(algorithm + ": CGAL's Delaunay triangulation failed its check '" + e.expression() +
                     "' on this input (coordinates near the limits of double precision?)");
  }
}

}  // namespace

Reconstruction Algorithm::reconstruct(std::span<const Point2> points,
                                      const ParameterAssignments& given) const {
  const AlgorithmInfo& about = info();
  const ParameterValues parameters = resolve_parameters(about.name, about.parameters, given);
  require_finite(points, about.name);
  PhaseTimer timer;
  Reconstruction result;
  if (about.input == SiteInput::kDelaunay) {
    const DelaunayVoronoi dv = triangulate(points, about.name);
    timer.lap("delaunay");
    require_sites(dv.site_count(), dv.dimension < 2, about);
    SiteResult site_result = run(Sites{dv.sites, &dv}, parameters, timer);
    result = to_input(std::move(site_result), dv.input_of_site, dv.site_of_input, about);
  } else {
    DistinctPoints distinct = distinct_points(points);
    timer.lap("distinct_points");
    require_sites(static_cast<int>(distinct.points.size()), all_collinear(distinct.points), about);
    SiteResult site_result = run(Sites{distinct.points, nullptr}, parameters, timer);
    result = to_input(std::move(site_result), distinct.input_of_point, distinct.point_of_input, about);
  }
  result.timing_ms = timer.finish();
  return result;
}

}  // namespace curvebench
