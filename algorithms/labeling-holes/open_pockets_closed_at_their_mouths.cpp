#include "labeling-holes/open_pockets_closed_at_their_mouths.h"

#include <algorithm>

#include "labeling-holes/missed_curves_stand_apart.h"
#include "labeling/walk_steps.h"

namespace curvebench {
namespace {

bool is_inner(const std::vector<std::uint8_t>& inner, int t) { return t != kInfinite && inner[t] != 0; }

// The curve edges at `site`: the Delaunay edges of its fan with different labels on their two
// sides (the infinite vertex is outer). Counter-clockwise from site_triangle, which for a hull
// site is the first triangle of its open fan (delaunay_voronoi.h).
int curve_edges_at(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner, int site) {
  const int first = dv.site_triangle[site];
  int count = 0;
  if (dv.neighbors[first][(corner_of_site(dv, first, site) + 2) % 3] == kInfinite) count += inner[first];
  int t = first;
  do {
    const int next = dv.neighbors[t][(corner_of_site(dv, t, site) + 1) % 3];
    count += inner[t] != is_inner(inner, next);
    t = next;
  } while (t != kInfinite && t != first);
  return count;
}

// Mouths: inner triangles whose edge opposite an enclosed sample c faces an outer vertex (a
// curve edge a-b) and is the triangle's longest. On an epsilon-sample a curve edge joins
// consecutive samples, so its diametral disk holds no other sample and it is never the
// longest edge of a triangle whose third sample lies in that disk's neighbourhood; a pocket's
// mouth is wider than the way from its ends to the first samples down its walls. The test
// keeps the thin strokes of a glyph out: there the curve edge is the triangle's shortest, and
// the enclosed sample across the stroke lies on a hole's curve.
std::vector<int> mouths_in_order(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner,
                                 std::span<const int> enclosed_samples) {
  std::vector<int> mouths;
  for (int site : enclosed_samples) {
    const int first = dv.site_triangle[site];
    int t = first;
    do {
      const int corner = corner_of_site(dv, t, site);
      const Point2 c = dv.sites[site], a = dv.sites[dv.triangles[t][(corner + 1) % 3]],
                   b = dv.sites[dv.triangles[t][(corner + 2) % 3]];
      if (!is_inner(inner, dv.neighbors[t][corner]) &&
          squared_distance(a, b) > std::max(squared_distance(a, c), squared_distance(b, c))) {
        mouths.push_back(t);
      }
      t = dv.neighbors[t][(corner + 1) % 3];  // an enclosed sample's fan is closed and all inner
    } while (t != first);
  }
  // Algorithm 2's heap order, ties by index; a mouth seen from two enclosed samples once.
  std::sort(mouths.begin(), mouths.end(), [&](int a, int b) {
    return dv.circumradii[a] > dv.circumradii[b] || (dv.circumradii[a] == dv.circumradii[b] && a < b);
  });
  mouths.erase(std::unique(mouths.begin(), mouths.end()), mouths.end());
  return mouths;
}

}  // namespace

int open_pockets_closed_at_their_mouths(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner,
                                        std::span<const int> enclosed_samples) {
  std::vector<std::uint8_t> enclosed(dv.site_count(), 0);
  for (int site : enclosed_samples) enclosed[site] = 1;
  auto has_an_enclosed_sample = [&](int t) {
    const auto& tri = dv.triangles[t];
    return enclosed[tri[0]] || enclosed[tri[1]] || enclosed[tri[2]];
  };
  const std::vector<int> mouths = mouths_in_order(dv, inner, enclosed_samples);

  // Per-walk scratch, reset after each walk: sources, vertex flags, boundary degrees.
  enum : std::uint8_t { kReached = 1, kInPocket = 2 };
  std::vector<int> source(dv.site_count(), kUnpaired);
  std::vector<std::uint8_t> flags(dv.triangle_count(), 0);
  std::vector<int> degree(dv.site_count(), 0);
  std::vector<int> reached, pocket, stack, samples, edges_before;
  std::vector<Edge> boundary, walls;
  MissedCurvesStandApart stand_apart(dv);
  int relabelled = 0;
  for (int mouth : mouths) {
    if (!inner[mouth]) continue;  // in a pocket opened already
    // Algorithm 1 from the mouth, which is taken outer untested (the paper's walk stopped it).
    reached.clear();
    pocket.clear();
    stack.assign(1, mouth);
    while (!stack.empty()) {
      const int vertex = stack.back();
      stack.pop_back();
      if (flags[vertex] & kReached) continue;
      flags[vertex] |= kReached;
      reached.push_back(vertex);
      // Gap 2: a vertex across a tangent line ends its branch.
      if (vertex != mouth && crosses_a_tangent_line(dv, source, vertex)) continue;
      flags[vertex] |= kInPocket;
      pocket.push_back(vertex);
      pair_samples_with(dv, source, vertex);
      for (int k = 2; k >= 0; --k) {
        const int next = dv.neighbors[vertex][k];
        if (is_inner(inner, next) && !(flags[next] & kReached) && has_an_enclosed_sample(next)) stack.push_back(next);
      }
    }

    // The pocket's boundary (its walls and its mouth) must be one closed curve through each of
    // its samples once, and its walls, the edges that join the curve when it opens, must stand
    // apart like a hole's (missed_curves_stand_apart.h). Not the mouth: it is the chord the
    // paper drew, its triangle's longest edge by construction, and would count its ends
    // against the pocket; a corridor between two curves has two mouths and few other samples
    // (disjoint at epsilon 0.8, seed 4: mouths 24-42 and 26-40, walls 24-25-26 and 40-41-42).
    boundary.clear();
    walls.clear();
    for (int t : pocket) {
      for (int k = 0; k < 3; ++k) {
        const int next = dv.neighbors[t][k];
        if (next != kInfinite && (flags[next] & kInPocket)) continue;
        const Edge e{dv.triangles[t][(k + 1) % 3], dv.triangles[t][(k + 2) % 3]};
        boundary.push_back(e);
        if (is_inner(inner, next)) walls.push_back(e);  // not a curve edge yet: a wall
      }
    }
    bool simple = true;
    for (const Edge& e : boundary) simple = ++degree[e[0]] <= 2 && ++degree[e[1]] <= 2 && simple;
    for (const Edge& e : boundary) degree[e[0]] = degree[e[1]] = 0;
    bool take = simple && stand_apart(walls);

    // And afterwards every sample of the pocket has exactly two curve edges, one of them
    // having had none (a wall joins the curve).
    if (take) {
      samples.clear();
      for (int t : pocket) samples.insert(samples.end(), dv.triangles[t].begin(), dv.triangles[t].end());
      std::sort(samples.begin(), samples.end());
      samples.erase(std::unique(samples.begin(), samples.end()), samples.end());
      edges_before.clear();
      for (int site : samples) edges_before.push_back(curve_edges_at(dv, inner, site));
      for (int t : pocket) inner[t] = 0;
      bool gains = false;
      for (std::size_t i = 0; i < samples.size() && take; ++i) {
        take = curve_edges_at(dv, inner, samples[i]) == 2;
        gains = gains || edges_before[i] == 0;
      }
      take = take && gains;
      if (!take) {
        for (int t : pocket) inner[t] = 1;
      }
    }
    if (take) relabelled += static_cast<int>(pocket.size());
    // Fresh sources and flags for the next mouth: a vertex this walk stopped may be reached
    // again from another mouth.
    for (int t : reached) {
      flags[t] = 0;
      for (int site : dv.triangles[t]) source[site] = kUnpaired;
    }
  }
  return relabelled;
}

}  // namespace curvebench
