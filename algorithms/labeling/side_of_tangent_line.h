// The labeler's Definition-5 predicate: on which side of a sample's estimated tangent line a
// Voronoi vertex lies. The tangent line at p is the line through p orthogonal to the vector
// from p to its source vertex (the pole estimate, Lemma 3.2).
#pragma once

#include <cmath>
#include <limits>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

// The sign of dot(circumcenter(query) - p, circumcenter(source) - p) in exact rational
// arithmetic, p = sites[site]: side_of_tangent_line's fallback.
int exact_side_of_tangent_line(const DelaunayVoronoi& dv, int site, int source_triangle, int query_triangle);

// Exact sign of dot(circumcenter(query) - p, circumcenter(source) - p) with p = sites[site]:
// +1 if the two Voronoi vertices lie on the same side of the line through p orthogonal to
// (circumcenter(source) - p), -1 on opposite sides, 0 if the query lies on that line.
// Evaluated in double precision with an exact rational fallback near zero. Inline: the
// labeling walk calls it once or more per Voronoi vertex, and inlined, its loads start
// while the caller's are still in flight.
inline int side_of_tangent_line(const DelaunayVoronoi& dv, int site, int source_triangle, int query_triangle) {
  const Point2 p = dv.sites[site];
  const double value = dot(dv.circumcenters[query_triangle] - p, dv.circumcenters[source_triangle] - p);
  // p lies on both circumcircles, so the two vectors have the circumradii as lengths.
  const double rounding = 4.0 * std::numeric_limits<double>::epsilon() * (std::abs(p.x) + std::abs(p.y));
  const double eu = dv.circumcenter_errors[query_triangle] + rounding;
  const double ev = dv.circumcenter_errors[source_triangle] + rounding;
  const double bound = eu * dv.circumradii[source_triangle] + ev * dv.circumradii[query_triangle] + eu * ev;
  if (std::abs(value) > bound && std::isfinite(bound)) [[likely]] return value > 0 ? 1 : -1;
  return exact_side_of_tangent_line(dv, site, source_triangle, query_triangle);
}

}  // namespace curvebench
