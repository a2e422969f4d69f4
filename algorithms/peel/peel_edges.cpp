#include "peel/peel_edges.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace curvebench {
namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// An edge of the curve as the authors store it: oriented (the orientation matters only to the
// reference degree test), plus the Delaunay edge it is, to mark it taken (see delaunay_edge_id).
struct CurveEdge {
  int first;
  int second;
  int delaunay_edge;
};

// Bit k of entry t: the side of triangle t opposite corner k is a longest side (non-strict,
// spec step A: with ties every tied side counts). Squared lengths order sides as lengths do;
// beyond 1e154 they overflow to infinity, tie, and every such side counts as longest.
std::vector<std::uint8_t> longest_sides(const DelaunayVoronoi& dv) {
  std::vector<std::uint8_t> longest(dv.triangles.size());
  for (int t = 0; t < dv.triangle_count(); ++t) {
    const auto& v = dv.triangles[t];
    const double side[3] = {squared_distance(dv.sites[v[1]], dv.sites[v[2]]),
                            squared_distance(dv.sites[v[2]], dv.sites[v[0]]),
                            squared_distance(dv.sites[v[0]], dv.sites[v[1]])};
    std::uint8_t bits = 0;
    for (int k = 0; k < 3; ++k) {
      if (side[k] >= side[(k + 1) % 3] && side[k] >= side[(k + 2) % 3]) bits |= std::uint8_t(1u << k);
    }
    longest[t] = bits;
  }
  return longest;
}

// The corner of `triangle` whose opposite side it shares with `across`.
int corner_facing(const DelaunayVoronoi& dv, int triangle, int across) {
  const auto& n = dv.neighbors[triangle];
  return n[0] == across ? 0 : (n[1] == across ? 1 : 2);
}

// Each Delaunay edge once: 3 t + k, with t the lower-numbered of its triangles (the only one
// on the hull) and k the corner of t opposite the edge.
int delaunay_edge_id(const DelaunayVoronoi& dv, int triangle, int corner) {
  const int across = dv.neighbors[triangle][corner];
  if (across == kInfinite || triangle < across) return 3 * triangle + corner;
  return 3 * across + corner_facing(dv, across, triangle);
}

// Spec step A. S is a set; its order and orientations follow the authors' insertion rule
// applied to our triangles in index order, corners in stored order (v0, v1, v2), where the
// authors scan CGAL's faces: if v0v1 is longest they insert (v0, v2), (v2, v1); if v0v2:
// (v0, v1), (v1, v2); if v1v2: (v0, v1), (v0, v2). An edge keeps the place and orientation of
// its first insertion, which is in the lower-numbered of its triangles.
std::vector<CurveEdge> peel(const DelaunayVoronoi& dv) {
  const std::vector<std::uint8_t> longest = longest_sides(dv);
  // (first corner, second corner, opposite corner) inserted when the side opposite corner
  // 2, 1, 0 (v0v1, v0v2, v1v2) is longest.
  struct Insertion {
    int from, to, opposite;
  };
  static constexpr Insertion kInsertions[3][2] = {{{0, 2, 1}, {2, 1, 0}}, {{0, 1, 2}, {1, 2, 0}}, {{0, 1, 2}, {0, 2, 1}}};
  static constexpr int kLongestCorner[3] = {2, 1, 0};

  std::vector<CurveEdge> s;
  s.reserve(dv.sites.size() + dv.sites.size() / 2);
  for (int t = 0; t < dv.triangle_count(); ++t) {
    const auto& v = dv.triangles[t];
    std::uint8_t emitted = 0;
    for (int rule = 0; rule < 3; ++rule) {
      if (!(longest[t] >> kLongestCorner[rule] & 1)) continue;
      for (const Insertion& insertion : kInsertions[rule]) {
        const int k = insertion.opposite;
        const int across = dv.neighbors[t][k];
        if (longest[t] >> k & 1 || emitted >> k & 1) continue;
        if (across != kInfinite && across < t) continue;  // inserted from `across` already
        if (across != kInfinite && longest[across] >> corner_facing(dv, across, t) & 1) continue;
        emitted |= std::uint8_t(1u << k);
        s.push_back({v[insertion.from], v[insertion.to], 3 * t + k});
      }
    }
  }
  return s;
}

// Spec step B. Every test reads S, not the partly filtered result. ca = #{x in A : d(a, x) < L}
// reaches 2 exactly when the second shortest S-edge at a is shorter than L (the edge itself,
// of length L, is never shorter than L), so the symmetric rule needs only the two shortest
// S-edges at each site and does not depend on order or orientation.
std::vector<CurveEdge> degree_filter(const DelaunayVoronoi& dv, const std::vector<CurveEdge>& s, bool reference_cb) {
  const int n = dv.site_count();
  std::vector<double> shortest(n, kUnbounded), second_shortest(n, kUnbounded);
  auto record = [&](int site, double length2) {
    if (length2 < shortest[site]) {
      second_shortest[site] = shortest[site];
      shortest[site] = length2;
    } else if (length2 < second_shortest[site]) {
      second_shortest[site] = length2;
    }
  };
  for (const CurveEdge& e : s) {
    const double length2 = squared_distance(dv.sites[e.first], dv.sites[e.second]);
    record(e.first, length2);
    record(e.second, length2);
  }

  // The reference rule for b (spec step B, kept for comparison, spec section 3) reads S's
  // adjacency lists: cb = #{x in A + B, a multiset : d(b, x) < L} if |A| + |B| >= 2.
  std::vector<int> start, neighbours;
  if (reference_cb) {
    start.assign(n + 1, 0);
    for (const CurveEdge& e : s) ++start[e.first + 1], ++start[e.second + 1];
    for (int i = 0; i < n; ++i) start[i + 1] += start[i];
    neighbours.resize(start[n]);
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (const CurveEdge& e : s) neighbours[fill[e.first]++] = e.second, neighbours[fill[e.second]++] = e.first;
  }
  auto reference_cb_at_most_one = [&](int a, int b, double length2) {
    const int others = (start[a + 1] - start[a] - 1) + (start[b + 1] - start[b] - 1);
    if (others < 2) return true;
    int count = 0;
    for (int i = start[a]; i < start[a + 1]; ++i) {
      if (neighbours[i] != b && squared_distance(dv.sites[b], dv.sites[neighbours[i]]) < length2) ++count;
    }
    for (int i = start[b]; i < start[b + 1]; ++i) {
      if (neighbours[i] != a && squared_distance(dv.sites[b], dv.sites[neighbours[i]]) < length2) ++count;
    }
    return count <= 1;
  };

  std::vector<CurveEdge> kept;
  kept.reserve(s.size());
  for (const CurveEdge& e : s) {
    const double length2 = squared_distance(dv.sites[e.first], dv.sites[e.second]);
    const bool ca_at_most_one = !(second_shortest[e.first] < length2);
    const bool cb_at_most_one = reference_cb ? reference_cb_at_most_one(e.first, e.second, length2)
                                             : !(second_shortest[e.second] < length2);
    if (ca_at_most_one && cb_at_most_one) kept.push_back(e);
  }
  return kept;
}

// The Delaunay edge (end, x) to the neighbour x nearest to `end` with d(end, x)^2 < bound2
// that is not taken, or site -1. Walks the triangle fan of `end` counter-clockwise from
// site_triangle (on the hull the first triangle of the fan, so the walk covers it). The
// authors keep the first nearest in CGAL's face order; here equally near neighbours go to the
// smaller site index.
CurveEdge nearest_free_neighbour(const DelaunayVoronoi& dv, int end, double bound2, const std::vector<std::uint8_t>& taken) {
  CurveEdge best{-1, end, -1};
  double best2 = bound2;
  auto consider = [&](int t, int k) {  // the side of t opposite corner k, which has `end` on it
    const int id = delaunay_edge_id(dv, t, k);
    if (taken[id]) return;
    const auto& v = dv.triangles[t];
    const int x = v[(k + 1) % 3] == end ? v[(k + 2) % 3] : v[(k + 1) % 3];
    const double d2 = squared_distance(dv.sites[end], dv.sites[x]);
    if (d2 < best2 || (d2 == best2 && best.first >= 0 && x < best.first)) {
      best = {x, end, id};
      best2 = d2;
    }
  };
  const int first = dv.site_triangle[end];
  int t = first;
  while (t != kInfinite) {
    const int c = corner_of_site(dv, t, end);
    consider(t, (c + 2) % 3);                        // end - v[c + 1]
    const int next = dv.neighbors[t][(c + 1) % 3];  // across end - v[c + 2]: counter-clockwise
    if (next == kInfinite) consider(t, (c + 1) % 3);  // the last side of a hull site's fan
    if (next == first) break;
    t = next;
  }
  return best;
}

// Spec step C, on the filtered edges in S order, also visiting the edges it appends. Both
// ends' counts are taken before anything is appended for the edge; then a, then b, if it has
// no other edge, gets the edge (x, end). Each appended edge is a Delaunay edge not yet taken,
// so the scan ends after at most as many edges as the triangulation has.
void reconnect_loose_ends(const DelaunayVoronoi& dv, double len, std::vector<CurveEdge>& curve) {
  std::vector<int> degree(dv.site_count(), 0);
  std::vector<std::uint8_t> taken(3 * dv.triangles.size(), 0);
  for (const CurveEdge& e : curve) {
    ++degree[e.first];
    ++degree[e.second];
    taken[e.delaunay_edge] = 1;
  }
  for (std::size_t i = 0; i < curve.size(); ++i) {
    const CurveEdge e = curve[i];  // a copy: appending may move the array
    const bool loose[2] = {degree[e.first] == 1, degree[e.second] == 1};
    const double bound2 = len * len * squared_distance(dv.sites[e.first], dv.sites[e.second]);
    for (const int end : {e.first, e.second}) {
      if (!loose[end == e.first ? 0 : 1]) continue;
      const CurveEdge added = nearest_free_neighbour(dv, end, bound2, taken);
      if (added.first < 0) continue;
      taken[added.delaunay_edge] = 1;
      ++degree[added.first];
      ++degree[end];
      curve.push_back(added);
    }
  }
}

}  // namespace

std::vector<Edge> peel_edges(const DelaunayVoronoi& dv, double len, bool reference_cb) {
  // Below dimension 2 there is no finite triangle, so nothing is peeled (spec section 2).
  if (dv.dimension < 2 || dv.triangles.empty()) return {};
  std::vector<CurveEdge> curve = degree_filter(dv, peel(dv), reference_cb);
  if (len > 0) reconnect_loose_ends(dv, len, curve);
  std::vector<Edge> edges;
  edges.reserve(curve.size());
  for (const CurveEdge& e : curve) edges.push_back(make_edge(e.first, e.second));
  std::sort(edges.begin(), edges.end());
  return edges;
}

}  // namespace curvebench
