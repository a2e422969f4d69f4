#include "labeling-holes/label_voronoi_vertices_with_holes.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "labeling-holes/enclosed_samples.h"
#include "labeling-holes/walk_region_from_its_boundary.h"

namespace curvebench {
namespace {

// The parts of `region` the walk did not keep that lie across missed closed curves: a part
// (grown through the Voronoi edges between its vertices, from the cells of the enclosed
// samples) is taken when its boundary, the Delaunay edges dual to the Voronoi edges leaving
// it, is a set of closed curves through enclosed samples only (every one of its samples has
// two boundary edges). Such a part is cut off by samples that no walk reached, and its new
// curve edges leave every curve the paper found as it was. A part touching a found curve, or
// with a branching boundary, is the walk going astray (inside a pocket that the paper's
// labeling closed off at its mouth, the frontier lies on the wrong side of the pocket walls)
// and keeps the paper's labels.
std::vector<std::uint8_t> parts_across_missed_curves(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& region,
                                                     const std::vector<std::uint8_t>& kept,
                                                     const std::vector<int>& enclosed_samples) {
  const int triangles = dv.triangle_count();
  std::vector<std::uint8_t> across(triangles, 0), seen(triangles, 0), enclosed(dv.site_count(), 0);
  for (int site : enclosed_samples) enclosed[site] = 1;
  std::vector<int> boundary_degree(dv.site_count(), 0);
  std::vector<int> part, stack;
  std::vector<Edge> boundary;
  auto unkept = [&](int t) { return t != kInfinite && region[t] && !kept[t]; };

  auto grow_part = [&](int start) {
    part.clear();
    boundary.clear();
    seen[start] = 1;
    stack.push_back(start);
    while (!stack.empty()) {
      const int vertex = stack.back();
      stack.pop_back();
      part.push_back(vertex);
      for (int k = 0; k < 3; ++k) {
        const int next = dv.neighbors[vertex][k];
        if (!unkept(next)) {
          boundary.push_back({dv.triangles[vertex][(k + 1) % 3], dv.triangles[vertex][(k + 2) % 3]});
        } else if (!seen[next]) {
          seen[next] = 1;
          stack.push_back(next);
        }
      }
    }
  };
  auto bounded_by_missed_closed_curves = [&] {
    for (const Edge& e : boundary) {
      ++boundary_degree[e[0]];
      ++boundary_degree[e[1]];
    }
    bool closed = true;
    for (const Edge& e : boundary) {
      for (int site : e) closed = closed && enclosed[site] && boundary_degree[site] == 2;
    }
    for (const Edge& e : boundary) boundary_degree[e[0]] = boundary_degree[e[1]] = 0;
    return closed;
  };

  for (int site : enclosed_samples) {
    // Around the cell of an enclosed sample, a bounded cell (never the infinite vertex).
    const int first = dv.site_triangle[site];
    int t = first;
    do {
      if (unkept(t) && !seen[t]) {
        grow_part(t);
        if (bounded_by_missed_closed_curves()) {
          for (int vertex : part) across[vertex] = 1;
        }
      }
      const auto& tri = dv.triangles[t];
      const int corner = tri[0] == site ? 0 : (tri[1] == site ? 1 : 2);
      t = dv.neighbors[t][(corner + 1) % 3];
    } while (t != first);
  }
  return across;
}

}  // namespace

VoronoiLabels label_voronoi_vertices_with_holes(const DelaunayVoronoi& dv) {
  VoronoiLabels labels = label_voronoi_vertices(dv);
  // After the paper's walks, a sample's cell holds an outer vertex exactly when a walk paired
  // the sample: every outer vertex is one a walk kept, keeping it pairs its unpaired samples
  // (Algorithm 1, lines 1-2), and hull samples are paired with the infinite vertex. So the
  // paper's enclosed samples are among its unpaired ones, and one pass over the sources
  // settles the common case, every sample paired, without a pass over the triangles.
  if (std::find(labels.source_vertex.begin(), labels.source_vertex.end(), kUnpaired) == labels.source_vertex.end()) {
    return labels;
  }
  std::vector<int> enclosed = samples_enclosed_by_region(dv, labels.inner);
  if (enclosed.empty()) return labels;  // the paper's walks reached every sample's curve

  std::vector<std::uint8_t> region = labels.inner;
  while (!enclosed.empty()) {
    const std::vector<std::uint8_t> kept = walk_region_from_its_boundary(dv, region);
    region = parts_across_missed_curves(dv, region, kept, enclosed);
    for (int t = 0; t < dv.triangle_count(); ++t) {
      if (region[t]) labels.inner[t] ^= 1;
    }
    enclosed = samples_enclosed_by_region(dv, region);
  }
  return labels;
}

}  // namespace curvebench
