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
  // Bound on the rounding error of each computed circumcenter (see labeling/side_of_tangent_line.h).
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

// The corner (0, 1 or 2) of `site` in `triangle`, which must have it: the triangle after
// `triangle` counter-clockwise around the site is neighbors[triangle][(corner + 1) % 3], the
// one clockwise neighbors[triangle][(corner + 2) % 3].
inline int corner_of_site(const DelaunayVoronoi& dv, int triangle, int site) {
  const auto& t = dv.triangles[triangle];
  return t[0] == site ? 0 : (t[1] == site ? 1 : 2);
}

// visit(t) for each triangle of the fan of `site` (which must have a cell, site_triangle >= 0),
// counter-clockwise from site_triangle, and then visit(kInfinite) for a hull site, whose fan
// is open: the infinite vertex closes its cycle of Voronoi vertices.
template <class Visit>
void for_each_voronoi_vertex_around(const DelaunayVoronoi& dv, int site, Visit&& visit) {
  const int first = dv.site_triangle[site];
  int t = first;
  do {
    visit(t);
    t = dv.neighbors[t][(corner_of_site(dv, t, site) + 1) % 3];
  } while (t != kInfinite && t != first);
  if (t == kInfinite) visit(kInfinite);
}

// Whether pred(q) holds for some Delaunay neighbour q of `site` (which must have a cell,
// site_triangle >= 0): its fan walked counter-clockwise from site_triangle, each triangle's
// other two corners asked in turn, stopping at the first that holds.
template <class Pred>
bool any_delaunay_neighbor(const DelaunayVoronoi& dv, int site, Pred&& pred) {
  const int first = dv.site_triangle[site];
  int t = first;
  do {
    const int corner = corner_of_site(dv, t, site);
    if (pred(dv.triangles[t][(corner + 1) % 3]) || pred(dv.triangles[t][(corner + 2) % 3])) return true;
    t = dv.neighbors[t][(corner + 1) % 3];
  } while (t != kInfinite && t != first);
  return false;
}

// The benchmark's floor: CGAL's documented range insertion of (point, index) pairs, the
// fastest documented way to a triangulation whose vertices know their input index. Returns
// its vertex count. build_delaunay_voronoi builds the same triangulation faster by
// sorting the pairs themselves instead of indices to them (see insert_in_spatial_order).
int bare_delaunay_vertex_count(std::span<const Point2> points);

// True if the Voronoi edge dual to the Delaunay edge opposite `corner` of `triangle` has
// zero length: the four sites of the two triangles are exactly co-circular. False for hull edges.
bool is_degenerate_voronoi_edge(const DelaunayVoronoi& dv, int triangle, int corner);

// True if `q` lies inside or on the boundary of the convex hull of the sites (dimension 2).
// `wedge` (any value at first) keeps the hull position where the last query was decided,
// and the search gallops from there: in a sequence of queries, one near the one before
// costs a few orientation tests instead of log(hull size).
bool in_convex_hull(const DelaunayVoronoi& dv, Point2 q, int& wedge);

}  // namespace curvebench
