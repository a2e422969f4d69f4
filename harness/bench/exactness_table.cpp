// Measures, for every registered algorithm that produces a curve and for each smooth curve
// family, the largest epsilon at which the reconstruction is still exact (edge set equal to
// the true adjacency) on every trial at that epsilon and every smaller one, and the share of
// exact trials at each epsilon. Prints Markdown tables. Deterministic: fixed seeds.
//
// Run: curvebench_exactness [max_epsilon=0.7] [step=0.05]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "core/registry.h"
#include "generators/families.h"
#include "generators/samplers.h"

namespace curvebench {
namespace {

struct Family {
  std::string name;
  std::vector<Scene> scenes;  // each scene is sampled with 3 seeds
};

// From the family table, at the dense vertex counts the baseline tests use.
std::vector<Family> families() {
  std::vector<Family> list;
  list.push_back({"circle", {curve_family_scene("circle", {}, 0, 4096)}});
  list.push_back({"ellipse 2:1", {curve_family_scene("ellipse", {{"a", 2}, {"b", 1}}, 0, 8192)}});
  list.push_back({"ellipse 5:1", {curve_family_scene("ellipse", {{"a", 5}, {"b", 1}}, 0, 8192)}});
  list.push_back({"rose", {curve_family_scene("rose", {}, 0, 8192)}});
  Family random{"random smooth (20)", {}};
  for (std::uint64_t seed = 1; seed <= 20; ++seed) random.scenes.push_back(curve_family_scene("random", {}, seed, 8192));
  list.push_back(std::move(random));
  Family several{"2-5 curves (8)", {}};
  for (int count = 2; count <= 5; ++count)
    for (std::uint64_t seed = 1; seed <= 2; ++seed)
      several.scenes.push_back(curve_family_scene("disjoint", {{"count", count}}, 10 * count + seed, 4096));
  list.push_back(std::move(several));
  return list;
}

bool exact(const Algorithm& algorithm, const SampledScene& samples) {
  try {
    auto result = algorithm.reconstruct(samples.points, {});
    if (!result.curve_edges) return false;
    auto edges = *result.curve_edges;
    auto truth = samples.true_edges;
    std::sort(edges.begin(), edges.end());
    std::sort(truth.begin(), truth.end());
    return edges == truth;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace
}  // namespace curvebench

int main(int argc, char** argv) {
  using namespace curvebench;
  const double max_epsilon = argc > 1 ? std::atof(argv[1]) : 0.7;
  const double step = argc > 2 ? std::atof(argv[2]) : 0.05;
  std::vector<double> epsilons;
  for (int k = 1; k * step <= max_epsilon + 1e-9; ++k) epsilons.push_back(k * step);
  const auto all = families();

  std::vector<const Algorithm*> algorithms;
  for (const Algorithm* a : all_algorithms()) {
    if (a->info().outputs & (kCurve | kNewCurve)) algorithms.push_back(a);
  }
  // exact_share[algorithm][family][epsilon]
  std::vector<std::vector<std::vector<double>>> share(algorithms.size(),
                                                      std::vector<std::vector<double>>(all.size(), std::vector<double>(epsilons.size())));
  for (size_t f = 0; f < all.size(); ++f) {
    for (size_t e = 0; e < epsilons.size(); ++e) {
      std::vector<SampledScene> trials;
      for (const auto& scene : all[f].scenes)
        for (std::uint64_t seed = 1; seed <= 3; ++seed) trials.push_back(epsilon_sample(scene, epsilons[e], seed));
      for (size_t a = 0; a < algorithms.size(); ++a) {
        int ok = 0;
        for (const auto& trial : trials) ok += exact(*algorithms[a], trial);
        share[a][f][e] = static_cast<double>(ok) / static_cast<double>(trials.size());
      }
    }
  }

  std::printf("Largest epsilon with every trial exact at it and below (3 seeds per curve; grid step %.2f):\n\n| algorithm |", step);
  for (const auto& family : all) std::printf(" %s |", family.name.c_str());
  std::printf("\n|---|");
  for (size_t f = 0; f < all.size(); ++f) std::printf("---|");
  std::printf("\n");
  for (size_t a = 0; a < algorithms.size(); ++a) {
    std::printf("| %s |", algorithms[a]->name().c_str());
    for (size_t f = 0; f < all.size(); ++f) {
      double largest = 0;
      for (size_t e = 0; e < epsilons.size() && share[a][f][e] == 1.0; ++e) largest = epsilons[e];
      if (largest > 0) std::printf(" %.2f |", largest); else std::printf(" < %.2f |", epsilons[0]);
    }
    std::printf("\n");
  }
  std::printf("\nShare of exact trials per epsilon (all families pooled, every family weighted equally):\n\n| algorithm |");
  for (double e : epsilons) std::printf(" %.2f |", e);
  std::printf("\n|---|");
  for (size_t e = 0; e < epsilons.size(); ++e) std::printf("---|");
  std::printf("\n");
  for (size_t a = 0; a < algorithms.size(); ++a) {
    std::printf("| %s |", algorithms[a]->name().c_str());
    for (size_t e = 0; e < epsilons.size(); ++e) {
      double sum = 0;
      for (size_t f = 0; f < all.size(); ++f) sum += share[a][f][e];
      std::printf(" %.2f |", sum / static_cast<double>(all.size()));
    }
    std::printf("\n");
  }
  return 0;
}
