#include "labeling-holes/walk_region_from_its_boundary.h"

#include <cstdint>

#include "labeling/walk_steps.h"
#include "voronoi/sort_by_decreasing_circumradius.h"

namespace curvebench {

std::vector<int> walk_region_from_its_boundary(const DelaunayVoronoi& dv, std::span<const std::uint8_t> region,
                                               std::span<const int> region_vertices) {
  // One byte of flags per vertex, so that a step of the walk reads one array, not four.
  enum : std::uint8_t { kInRegion = 1, kSeed = 2, kVisited = 4, kKept = 8 };
  std::vector<std::uint8_t> state(dv.triangle_count(), 0);
  // Without branches (a frontier vertex follows no pattern on noisy input): every vertex is
  // written as a seed, and the count moves past it only if it is one.
  auto in_region = [&](int t) { return unsigned{t != kInfinite} & unsigned{region[t == kInfinite ? 0 : t] != 0}; };
  std::vector<int> seeds(region_vertices.size());
  std::size_t seed_count = 0;
  for (int t : region_vertices) {
    const auto& next = dv.neighbors[t];
    const unsigned frontier = (in_region(next[0]) & in_region(next[1]) & in_region(next[2])) ^ 1u;
    state[t] = static_cast<std::uint8_t>(kInRegion | (frontier * kSeed));
    seeds[seed_count] = t;
    seed_count += frontier;
  }
  seeds.resize(seed_count);

  std::vector<int> source(dv.site_count(), kUnpaired);
  std::vector<int> stack;
  // Seeds in Algorithm 2's order; one reached by an earlier seed's walk starts none of its own.
  auto reached = [&](int t) { return (state[t] & kVisited) != 0; };
  for_each_by_decreasing_circumradius(dv, seeds, reached, [&](int root) {
    stack.assign(1, root);
    while (!stack.empty()) {
      const int vertex = stack.back();
      stack.pop_back();
      const std::uint8_t flags = state[vertex];
      if (flags & kVisited) continue;  // reached by an earlier branch
      state[vertex] = flags | kVisited;
      // Gap 2 of labeling/README.md: a stopped vertex ends its branch.
      if (!(flags & kSeed) && crosses_a_tangent_line(dv, source, vertex)) continue;
      state[vertex] |= kKept;
      pair_samples_with(dv, source, vertex);
      for (int k = 2; k >= 0; --k) {
        const int next = dv.neighbors[vertex][k];
        if (next != kInfinite && (state[next] & (kInRegion | kVisited)) == kInRegion) stack.push_back(next);
      }
    }
  }, [&](int root) {
    // What a root's first step reads: its flags, samples, neighbours and circumcentre.
    __builtin_prefetch(&state[root]);
    __builtin_prefetch(&dv.triangles[root]);
    __builtin_prefetch(&dv.neighbors[root]);
    __builtin_prefetch(&dv.circumcenters[root]);
  });
  std::vector<int> unkept(region_vertices.size());
  std::size_t unkept_count = 0;
  for (int t : region_vertices) {
    unkept[unkept_count] = t;
    unkept_count += (state[t] & kKept) == 0;
  }
  unkept.resize(unkept_count);
  return unkept;
}

}  // namespace curvebench
