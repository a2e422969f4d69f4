// The curve families the baseline tests (crust, NN-crust, local crust) share with the
// labeler's, from the family table (generators/families.h): a circle, ellipses of aspect 2
// and 5, the rose r = 1 + 0.3 cos(5t), random smooth closed curves and scenes of several
// disjoint curves, with fixed seeds. Plus the
// helpers to epsilon-sample them and to ask whether a reconstruction is exact.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "core/registry.h"
#include "generators/families.h"
#include "generators/samplers.h"

namespace curvebench::testing {

struct Family {
  std::string name;
  Scene scene;
};

// Built once: the dense curves and their local feature size take a moment.
inline const std::vector<Family>& curve_families() {
  static const std::vector<Family> families = [] {
    std::vector<Family> list = {
        {"circle", curve_family_scene("circle", {}, 0, 4096)},
        {"ellipse 2:1", curve_family_scene("ellipse", {{"a", 2}, {"b", 1}}, 0, 8192)},
        {"ellipse 5:1", curve_family_scene("ellipse", {{"a", 5}, {"b", 1}}, 0, 8192)},
        {"rose", curve_family_scene("rose", {}, 0, 8192)},
    };
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      list.push_back({"random curve " + std::to_string(seed), curve_family_scene("random", {}, seed, 8192)});
    }
    for (int count = 2; count <= 5; ++count) {
      list.push_back({std::to_string(count) + " disjoint curves", curve_family_scene("disjoint", {{"count", count}}, 10 * count + 1, 4096)});
    }
    return list;
  }();
  return families;
}

// True if `algorithm` reconstructs `samples` exactly: its edge set is the true adjacency.
inline bool reconstructs_exactly(const std::string& algorithm, const SampledScene& samples) {
  auto edges = *find_algorithm(algorithm).reconstruct(samples.points, {}).curve_edges;
  std::sort(edges.begin(), edges.end());
  return edges == samples.true_edges;
}

// Every family, epsilon-sampled with `seeds` fixed seeds, comes out exact.
inline void expect_exact_on_all_families(const std::string& algorithm, double epsilon, int seeds) {
  for (const auto& family : curve_families()) {
    for (int seed = 1; seed <= seeds; ++seed) {
      const SampledScene samples = epsilon_sample(family.scene, epsilon, seed);
      ASSERT_LE(achieved_epsilon(family.scene, samples), epsilon) << family.name << " seed " << seed;
      EXPECT_TRUE(reconstructs_exactly(algorithm, samples))
          << algorithm << " on " << family.name << ", epsilon " << epsilon << ", seed " << seed << ", "
          << samples.points.size() << " samples";
    }
  }
}

}  // namespace curvebench::testing
