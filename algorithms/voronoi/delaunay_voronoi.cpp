#include "voronoi/delaunay_voronoi.h"

#include <CGAL/Exact_rational.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <utility>

#include "core/distinct_points.h"
#include "voronoi/cgal_kernel.h"

namespace curvebench {

namespace cgal {

// What Delaunay_triangulation_2::insert does with a range of (point, index) pairs, without
// its indirection: CGAL sorts an array of indices into spatial order (randomized rounds, each
// along a Hilbert curve) comparing the points they index; here the pairs themselves are
// sorted, then each is inserted from the face of the one before. The result is the same
// triangulation, built faster at large n because the sort reads contiguous memory (see
// harness/bench/README.md). Inserting a point equal to an earlier one returns the earlier
// vertex, whose index is then replaced unless the new one is negative.
void insert_in_spatial_order(Delaunay& dt, IndexedPoints& indexed) {
  using Traits = CGAL::Spatial_sort_traits_adapter_2<Kernel, CGAL::First_of_pair_property_map<IndexedPoints::value_type>>;
  CGAL::spatial_sort(indexed.begin(), indexed.end(), Traits());
  Delaunay::Face_handle hint;
  for (const auto& [point, index] : indexed) {
    const auto before = dt.number_of_vertices();
    const auto v = dt.insert(point, hint);
    if (index >= 0 || dt.number_of_vertices() > before) v->info() = index;
    hint = v->face();
  }
}

}  // namespace cgal

namespace {

using cgal::IndexedPoints;
using cgal::insert_in_spatial_order;

// Sites are the distinct input points in order of first occurrence. Only called when the
// triangulation reports fewer vertices than input points, so the common case pays nothing.
void deduplicate(std::span<const Point2> points, DelaunayVoronoi& dv) {
  DistinctPoints distinct = distinct_points(points);
  dv.sites = std::move(distinct.points);
  dv.input_of_site = std::move(distinct.input_of_point);
  dv.site_of_input = std::move(distinct.point_of_input);
}

// Circumcentre of a triangle in exact rational arithmetic, rounded once at the end.
Point2 exact_circumcenter(Point2 a, Point2 b, Point2 c) {
  using Q = CGAL::Exact_rational;
  const Q bx = Q(b.x) - Q(a.x), by = Q(b.y) - Q(a.y), cx = Q(c.x) - Q(a.x), cy = Q(c.y) - Q(a.y);
  const Q d = 2 * (bx * cy - by * cx);  // nonzero: Delaunay triangles are never flat
  const Q b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  return {CGAL::to_double(Q(a.x) + (cy * b2 - by * c2) / d), CGAL::to_double(Q(a.y) + (bx * c2 - cx * b2) / d)};
}

// Circumcentre, circumradius and a bound on the centre's absolute rounding error, with a
// wide margin: the formula loses about |ab||ac| / |cross(ab, ac)| in relative precision.
// A nearly flat triangle (three samples along a straight stretch) would lose every digit, or
// divide by a cross product that rounds to zero. Along a densely sampled curve a fifth of
// the triangles are that flat (the conditioning grows like the curvature radius over the
// sample spacing), so they go to the 64-bit mantissa of x87 long double where the platform
// has one (2^11 times more precise, and much cheaper than rationals), and only the flattest
// to exact rational arithmetic.
template <class Real>
bool float_circumcircle(Point2 a, Point2 b, Point2 c, Point2& center, double& radius, double& error) {
  constexpr Real eps = std::numeric_limits<Real>::epsilon();
  constexpr Real max_conditioning = 1e-10 / eps;  // keeps the relative error of the centre below ~1e-8
  const Real abx = Real(b.x) - a.x, aby = Real(b.y) - a.y, acx = Real(c.x) - a.x, acy = Real(c.y) - a.y;
  const Real area2 = abx * acy - aby * acx;
  const Real ab2 = abx * abx + aby * aby, ac2 = acx * acx + acy * acy;
  const Real half_inverse_area2 = Real(0.5) / area2;  // one division: it runs once per triangle
  const Real conditioning = std::sqrt(ab2 * ac2) * std::abs(2 * half_inverse_area2);
  if (!(conditioning < max_conditioning)) return false;
  const Real ux = (acy * ab2 - aby * ac2) * half_inverse_area2, uy = (abx * ac2 - acx * ab2) * half_inverse_area2;
  center = {static_cast<double>(a.x + ux), static_cast<double>(a.y + uy)};
  const Real r = std::sqrt(ux * ux + uy * uy);  // not hypot: this runs once per triangle and hypot is slow
  radius = static_cast<double>(r);
  constexpr double double_eps = std::numeric_limits<double>::epsilon();
  // The computation's own error, plus rounding the results to double.
  error = static_cast<double>(64 * eps * (std::abs(a.x) + std::abs(a.y) + r * (1 + conditioning))) +
          4 * double_eps * (std::abs(center.x) + std::abs(center.y));
  return true;
}

void circumcircle(Point2 a, Point2 b, Point2 c, Point2& center, double& radius, double& error) {
  if (float_circumcircle<double>(a, b, c, center, radius, error)) return;
  if constexpr (std::numeric_limits<long double>::digits > std::numeric_limits<double>::digits) {
    if (float_circumcircle<long double>(a, b, c, center, radius, error)) return;
  }
  center = exact_circumcenter(a, b, c);
  const Point2 u = center - a;
  radius = std::sqrt(dot(u, u));
  error = 4.0 * std::numeric_limits<double>::epsilon() * (std::abs(center.x) + std::abs(center.y));
}

IndexedPoints indexed_points(std::span<const Point2> points) {
  IndexedPoints indexed;
  indexed.reserve(points.size());
  for (int i = 0; i < static_cast<int>(points.size()); ++i) indexed.emplace_back(cgal::Point(points[i].x, points[i].y), i);
  return indexed;
}


// Triangulates the points into `dt` and fills the site fields of `dv` (sites, input_of_site,
// site_of_input, dimension); each vertex's info becomes its site index.
void triangulate_sites(std::span<const Point2> points, cgal::Delaunay& dt, DelaunayVoronoi& dv) {
  const int n = static_cast<int>(points.size());
  IndexedPoints indexed = indexed_points(points);
  insert_in_spatial_order(dt, indexed);
  if (static_cast<int>(dt.number_of_vertices()) == n) {
    dv.sites.assign(points.begin(), points.end());
    dv.input_of_site.resize(n);
    std::iota(dv.input_of_site.begin(), dv.input_of_site.end(), 0);
    dv.site_of_input = dv.input_of_site;
  } else {
    // A duplicate's vertex carries the index of whichever copy was inserted last.
    deduplicate(points, dv);
    for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
      v->info() = dv.site_of_input[v->info()];
    }
  }
  dv.dimension = dt.dimension();
}

// Sorts `items` by key(item), a key below 2^key_bits: a least-significant-digit radix sort,
// so it is stable and the numberings it makes are deterministic.
template <class T, class Key>
void radix_sort(std::vector<T>& items, int key_bits, Key key) {
  std::vector<T> buffer(items.size());
  constexpr int kDigitBits = 12;  // 4096 counters stay in the L1 cache; two passes for keys below 2^24
  constexpr std::uint32_t kDigitMask = (1u << kDigitBits) - 1;
  for (int shift = 0; shift < key_bits; shift += kDigitBits) {
    std::array<std::uint32_t, kDigitMask + 2> start{};
    for (const auto& item : items) ++start[((key(item) >> shift) & kDigitMask) + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    for (const auto& item : items) buffer[start[(key(item) >> shift) & kDigitMask]++] = item;
    items.swap(buffer);
  }
}

// Renumbers the sites in Z order (Morton order) of their positions: sites, input_of_site,
// site_of_input and the info of every vertex of `dt`.
void renumber_sites_in_z_order(cgal::Delaunay& dt, DelaunayVoronoi& dv) {
  const int n = dv.site_count();
  double min_x = dv.sites[0].x, max_x = min_x, min_y = dv.sites[0].y, max_y = min_y;
  for (const auto& p : dv.sites) {
    min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
    min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
  }
  // The finest grid 32-bit keys allow: samples of a curve crowd into few cells of a coarser
  // one, and within a cell they would keep their input order.
  static constexpr int kGridBits = 16;
  static constexpr double last_cell = (1 << kGridBits) - 1;
  const double scale_x = max_x > min_x ? last_cell / (max_x - min_x) : 0.0;
  const double scale_y = max_y > min_y ? last_cell / (max_y - min_y) : 0.0;
  auto to_grid = [](double v) {  // NaN (coordinates near the limits of double) counts as 0
    return v > 0 ? static_cast<std::uint32_t>(std::min(v, last_cell)) : 0u;
  };
  auto spread_bits = [](std::uint32_t v) {  // bit i of v to bit 2i
    v = (v | (v << 8)) & 0x00FF00FFu;
    v = (v | (v << 4)) & 0x0F0F0F0Fu;
    v = (v | (v << 2)) & 0x33333333u;
    return (v | (v << 1)) & 0x55555555u;
  };
  std::vector<std::pair<std::uint32_t, int>> keyed(n);  // (Morton key, old site)
  for (int s = 0; s < n; ++s) {
    const Point2 p = dv.sites[s];
    keyed[s] = {spread_bits(to_grid((p.x - min_x) * scale_x)) | (spread_bits(to_grid((p.y - min_y) * scale_y)) << 1), s};
  }
  radix_sort(keyed, 2 * kGridBits, [](const auto& k) { return k.first; });
  std::vector<int> new_of_old(n);
  std::vector<Point2> sites(n);
  std::vector<int> input_of_site(n);
  for (int s = 0; s < n; ++s) {
    const int old = keyed[s].second;
    new_of_old[old] = s;
    sites[s] = dv.sites[old];
    input_of_site[s] = dv.input_of_site[old];
  }
  dv.sites.swap(sites);
  dv.input_of_site.swap(input_of_site);
  for (int& site : dv.site_of_input) site = new_of_old[site];
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) v->info() = new_of_old[v->info()];
}

// Numbers the sites and the triangles so that neighbours lie close in the arrays. Returns the
// finite faces in triangle order, with each face's info set to its position in that order and
// every infinite face's to kInfinite. CGAL's face container follows the randomized insertion
// order, so two thirds of the neighbours of a face lie thousands of faces away from it, and
// every walk over the triangles (labeling, medial axis, crusts) would wait on memory at each
// step once the arrays outgrow the cache. Faces are ordered by their smallest site, so the
// fans of consecutive sites follow one another, and the sites are put in an order where
// consecutive sites are close:
// - Points that run along the curves (most consecutive points are Delaunay neighbours, as in
//   outlines traced along a contour) keep their order. A walk along the curve, as the
//   labeler's is, then reads every array in sequence (harness/bench/README.md has the
//   measurements against triangles in Z order of centroids).
// - Any other order is replaced by Z order (renumber_sites_in_z_order), so that sites close
//   in the plane are close in the arrays.
std::vector<cgal::Delaunay::Face_handle> number_sites_and_faces(cgal::Delaunay& dt, DelaunayVoronoi& dv) {
  using Face = cgal::Delaunay::Face_handle;
  struct Keyed {
    std::uint32_t smallest_site;
    Face face;
  };
  auto smallest_site = [](Face f) {
    return static_cast<std::uint32_t>(std::min({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}));
  };
  std::vector<Keyed> keyed;
  keyed.reserve(dt.number_of_faces());
  // Each Delaunay edge between consecutive sites once: an interior one is s -> s+1 in exactly
  // one of its two counter-clockwise faces, and a hull edge is in one orientation or the other.
  long long forward_pairs = 0, backward_pairs = 0;
  for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) {
    if (dt.is_infinite(f)) {
      f->info() = kInfinite;
      continue;
    }
    for (int i = 0; i < 3; ++i) {
      const int step = f->vertex((i + 1) % 3)->info() - f->vertex(i)->info();
      forward_pairs += step == 1;
      backward_pairs += step == -1;
    }
    keyed.push_back({smallest_site(f), f});
  }
  // Along the curves if at least half of the consecutive pairs are Delaunay edges. An
  // epsilon-sample in curve order has all of them but one per curve; noise of a fraction of
  // the sample spacing keeps most of them.
  const long long consecutive_pairs = static_cast<long long>(dv.site_count()) - 1;
  if (2 * std::max(forward_pairs, backward_pairs) < consecutive_pairs) {
    renumber_sites_in_z_order(dt, dv);
    for (auto& k : keyed) k.smallest_site = smallest_site(k.face);
  }
  radix_sort(keyed, std::bit_width(static_cast<std::uint32_t>(dv.site_count() - 1)),
             [](const Keyed& k) { return k.smallest_site; });
  std::vector<Face> faces(keyed.size());
  for (std::size_t i = 0; i < keyed.size(); ++i) {
    faces[i] = keyed[i].face;
    faces[i]->info() = static_cast<int>(i);
  }
  return faces;
}

}  // namespace

int bare_delaunay_vertex_count(std::span<const Point2> points) {
  const IndexedPoints indexed = indexed_points(points);
  cgal::Delaunay dt;
  dt.insert(indexed.begin(), indexed.end());
  return static_cast<int>(dt.number_of_vertices());
}

DelaunayVoronoi build_delaunay_voronoi(std::span<const Point2> points) {
  DelaunayVoronoi dv;
  cgal::Delaunay dt;
  triangulate_sites(points, dt, dv);
  const int sites = dv.site_count();
  dv.site_triangle.assign(sites, -1);
  dv.on_hull.assign(sites, 0);
  if (dv.dimension < 2) {
    std::fill(dv.on_hull.begin(), dv.on_hull.end(), 1);
    return dv;
  }

  std::vector<cgal::Delaunay::Face_handle> faces = number_sites_and_faces(dt, dv);
  const int t = static_cast<int>(faces.size());
  // Filled in order of id by push_back into reserved storage: each array is written once,
  // without the zero-filling pass of resize.
  dv.triangles.reserve(t);
  dv.neighbors.reserve(t);
  dv.circumcenters.reserve(t);
  dv.circumradii.reserve(t);
  dv.circumcenter_errors.reserve(t);
  std::vector<int> hull_next(sites, -1);
  for (int id = 0; id < t; ++id) {
    const auto f = faces[id];
    std::array<int, 3> tri, nb;
    Point2 corners[3];  // read from the vertices at hand rather than from dv.sites, in another order
    for (int i = 0; i < 3; ++i) {
      const auto v = f->vertex(i);
      tri[i] = v->info();
      corners[i] = {v->point().x(), v->point().y()};
      nb[i] = f->neighbor(i)->info();
    }
    for (int i = 0; i < 3; ++i) {
      if (dv.site_triangle[tri[i]] < 0) dv.site_triangle[tri[i]] = id;
    }
    for (int k = 0; k < 3; ++k) {
      if (nb[k] != kInfinite) continue;
      // Hull edge from corner k+1 to k+2, counter-clockwise along the hull. For the site at
      // corner k+1 this is the clockwise-most edge of its fan: its walk starts here.
      const int from = tri[(k + 1) % 3], to = tri[(k + 2) % 3];
      dv.on_hull[from] = 1;
      dv.site_triangle[from] = id;
      hull_next[from] = to;
    }
    Point2 center;
    double radius, error;
    circumcircle(corners[0], corners[1], corners[2], center, radius, error);
    dv.triangles.push_back(tri);
    dv.neighbors.push_back(nb);
    dv.circumcenters.push_back(center);
    dv.circumradii.push_back(radius);
    dv.circumcenter_errors.push_back(error);
  }
  const int start = static_cast<int>(std::find(dv.on_hull.begin(), dv.on_hull.end(), 1) - dv.on_hull.begin());
  for (int s = start; s >= 0 && s < sites;) {
    dv.hull.push_back(s);
    s = hull_next[s];
    if (s == start) break;
  }
  return dv;
}

bool is_degenerate_voronoi_edge(const DelaunayVoronoi& dv, int triangle, int corner) {
  const int other = dv.neighbors[triangle][corner];
  if (other == kInfinite) return false;
  const auto& tri = dv.triangles[triangle];
  const auto& opp = dv.triangles[other];
  const int apex = opp[0] != tri[(corner + 1) % 3] && opp[0] != tri[(corner + 2) % 3]
                       ? opp[0]
                       : (opp[1] != tri[(corner + 1) % 3] && opp[1] != tri[(corner + 2) % 3] ? opp[1] : opp[2]);
  auto P = [&](int s) { return cgal::Point(dv.sites[s].x, dv.sites[s].y); };
  return CGAL::side_of_oriented_circle(P(tri[0]), P(tri[1]), P(tri[2]), P(apex)) == CGAL::ON_ORIENTED_BOUNDARY;
}

bool in_convex_hull(const DelaunayVoronoi& dv, Point2 q, int& wedge) {
  const auto& h = dv.hull;
  const int m = static_cast<int>(h.size());
  if (dv.dimension < 2 || m < 3) return false;
  auto P = [&](int s) { return cgal::Point(dv.sites[s].x, dv.sites[s].y); };
  const cgal::Point query(q.x, q.y);
  const cgal::Point origin = P(h[0]);
  const CGAL::Orientation first = CGAL::orientation(origin, P(h[1]), query);
  const CGAL::Orientation last = CGAL::orientation(origin, P(h[m - 1]), query);
  if (first == CGAL::RIGHT_TURN || last == CGAL::LEFT_TURN) return false;
  if (first == CGAL::COLLINEAR || last == CGAL::COLLINEAR) {
    // On the line of a hull edge through the origin. `hull` keeps the sites collinear with
    // the origin there, whose wedges of the fan below are flat and cannot tell a point on the
    // edge from one beyond its end; the query is in the hull exactly when it lies between the
    // two ends of the run of hull sites on that line (the origin is one of them, or inside it).
    const cgal::Point along = P(first == CGAL::COLLINEAR ? h[1] : h[m - 1]);
    int forward = 0, backward = 0;  // the run is h[m - backward], ..., h[0], ..., h[forward]
    while (forward + 1 < m && CGAL::collinear(origin, along, P(h[forward + 1]))) ++forward;
    while (backward + 1 < m - forward && CGAL::collinear(origin, along, P(h[m - 1 - backward]))) ++backward;
    return CGAL::collinear_are_ordered_along_line(P(h[(m - backward) % m]), query, P(h[forward]));
  }
  // The fan wedge: the largest i in [1, m-2] with the query left of or on the ray
  // origin -> h[i]. That holds for every i up to the answer and for none after, and for i = 1.
  auto left_of_ray = [&](int i) { return CGAL::orientation(origin, P(h[i]), query) != CGAL::RIGHT_TURN; };
  const int start = std::clamp(wedge, 1, m - 2);
  int lo = 1, hi = m - 2;  // the answer lies in [lo, hi]: gallop from the hint to narrow it, then bisect
  int step = 1;
  if (left_of_ray(start)) {
    lo = start;
    while (lo + step <= hi && left_of_ray(lo + step)) lo += step, step *= 2;
    hi = std::min(hi, lo + step - 1);
  } else {
    hi = start - 1;
    while (hi - step >= lo && !left_of_ray(hi - step)) hi -= step + 1, step *= 2;
    lo = std::max(lo, hi - step);
  }
  while (lo < hi) {
    const int mid = (lo + hi + 1) / 2;
    if (left_of_ray(mid)) lo = mid; else hi = mid - 1;
  }
  wedge = lo;
  return CGAL::orientation(P(h[lo]), P(h[lo + 1]), query) != CGAL::RIGHT_TURN;
}

}  // namespace curvebench
