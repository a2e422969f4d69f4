// The shared Delaunay/Voronoi layer: the only place that includes
// CGAL's triangulation headers. It builds CGAL::Delaunay_triangulation_2 with exact
// predicates once and hands out flat arrays, delaunator style.
//
// In:  planar points in any order; duplicates allowed (each maps to its first occurrence).
// Out: the Delaunay triangulation of the distinct points ("sites") and its dual Voronoi
//      diagram. Every finite Delaunay triangle is one finite Voronoi vertex, also when four
//      or more sites are co-circular (a uniformly sampled circle gives n-2 triangles whose
//      Voronoi vertices coincide): the triangulation CGAL picks among co-circular ones is
//      kept, so every Voronoi vertex has degree 3 and the zero-length Voronoi edges between
//      coinciding vertices are reported by is_degenerate_voronoi_edge().
//
// Sites and triangles are numbered so that neighbours lie close in the arrays: sites in input
// order when the points come in order along the curves (most consecutive points are Delaunay
// neighbours), else in Z order of their positions; triangles by smallest site (see
// number_sites_and_faces). The numbering is deterministic for a given input; algorithms use
// it at most to break exact ties and to order their output lists, and report input indices.
//
// Conventions: triangles are counter-clockwise; neighbors[t][i] is the triangle across the
// edge opposite corner i (the edge from corner i+1 to corner i+2), or kInfinite if that edge
// is on the convex hull (its dual Voronoi edge is an infinite ray).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "core/phase_timer.h"
#include "core/point.h"

namespace curvebench {

inline constexpr int kInfinite = -1;

struct DelaunayVoronoi {
  // 2: a proper triangulation; 1: all sites collinear (no triangles); 0: one site; -1: none.
  int dimension = -1;

  std::vector<Point2> sites;          // distinct points, each once (see the numbering above)
  std::vector<int> input_of_site;     // sites[s] == input[input_of_site[s]], its first occurrence
  std::vector<int> site_of_input;     // input index -> site index

  std::vector<std::array<int, 3>> triangles;  // site indices, counter-clockwise
  std::vector<std::array<int, 3>> neighbors;  // triangle across the edge opposite each corner
  std::vector<Point2> circumcenters;          // the Voronoi vertex of each triangle
  std::vector<double> circumradii;
  // Bound on the rounding error of each computed circumcenter (see side_of_tangent_line).
  std::vector<double> circumcenter_errors;

  // One triangle incident to each site. For a hull site it is the first triangle of its fan
  // in counter-clockwise order, so that a walk from it covers the whole unbounded cell.
  std::vector<int> site_triangle;
  std::vector<std::uint8_t> on_hull;  // 1 if the site's Voronoi cell is unbounded
  std::vector<int> hull;              // hull sites in counter-clockwise order (collinear ones included)

  int triangle_count() const { return static_cast<int>(triangles.size()); }
  int site_count() const { return static_cast<int>(sites.size()); }
};

DelaunayVoronoi build_delaunay_voronoi(std::span<const Point2> points);

// The benchmark's floor: CGAL's documented range insertion of (point, index) pairs, the
// fastest documented way to a triangulation whose vertices know their input index. Returns
// its vertex count. build_delaunay_voronoi builds the same triangulation 10-20% faster by
// sorting the pairs themselves instead of indices to them (see insert_in_spatial_order).
int bare_delaunay_vertex_count(std::span<const Point2> points);

// The crust's triangulation (Amenta, Bern, Eppstein 1998): the Delaunay edges between two
// sites in the triangulation of the sites together with all their Voronoi vertices, as site
// pairs, each once, in no particular order. `sites` receives the site fields of
// build_delaunay_voronoi (sites, input_of_site, site_of_input, dimension), sites always in
// order of first occurrence, and nothing else; below dimension 2 there are no edges. No
// triangle arrays are built: the Voronoi vertices are read straight off the sites' CGAL
// triangulation. A Voronoi vertex equal to a site counts as that site; one whose computed
// position is not finite (a hull triangle flat to rounding, its centre beyond the range of
// doubles) is left out: its only effect would be on hull edges. `timer` laps "delaunay"
// once the sites are triangulated.
std::vector<Edge> delaunay_edges_with_voronoi_vertices(std::span<const Point2> points, DelaunayVoronoi& sites,
                                                      PhaseTimer& timer);

// Throws InputError, naming `algorithm`, unless the sites span the plane (three or more
// distinct points, not all collinear): only then is there a closed curve to look for.
void require_triangulation(const DelaunayVoronoi& dv, const std::string& algorithm);

// Edges between sites as edges between input indices (first occurrences), in the same order.
std::vector<Edge> to_input_indices(const DelaunayVoronoi& dv, std::vector<Edge> site_edges);

// True if the Voronoi edge dual to the Delaunay edge opposite `corner` of `triangle` has
// zero length: the four sites of the two triangles are exactly co-circular. False for hull edges.
bool is_degenerate_voronoi_edge(const DelaunayVoronoi& dv, int triangle, int corner);

// The sign of dot(circumcenter(query) - p, circumcenter(source) - p) in exact rational
// arithmetic, p = sites[site]: side_of_tangent_line's fallback.
int exact_side_of_tangent_line(const DelaunayVoronoi& dv, int site, int source_triangle, int query_triangle);

// Exact sign of dot(circumcenter(query) - p, circumcenter(source) - p) with p = sites[site]:
// +1 if the two Voronoi vertices lie on the same side of the line through p orthogonal to
// (circumcenter(source) - p), -1 on opposite sides, 0 if the query lies on that line.
// Evaluated in double precision with an exact rational fallback near zero. Inline: the
// labeling walk calls it once or more per Voronoi vertex, and inlined, its loads start
// while the caller's are still in flight (5-7% of the labeling at 10^6 points).
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

// True if `q` lies inside or on the boundary of the convex hull of the sites (dimension 2).
// `wedge` (any value at first) keeps the hull position where the last query was decided,
// and the search gallops from there: in a sequence of queries, one near the one before
// costs a few orientation tests instead of log(hull size).
bool in_convex_hull(const DelaunayVoronoi& dv, Point2 q, int& wedge);

}  // namespace curvebench
