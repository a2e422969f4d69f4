// The sparse-sample methods through the interface: HNN-crust is exact on epsilon-samples of
// every smooth family at epsilon 0.4 (its authors prove epsilon < 0.47); Crawl, Peel and
// shape-hull have no proved bound, and their own tests (test_crawl.cpp, test_peel.cpp,
// test_shape_hull.cpp) check what their specifications state. Here: all four keep the skeleton's
// contract on duplicates (input indices, first occurrences).
#include <gtest/gtest.h>

#include "baseline_families.h"
#include "core/registry.h"
#include "test_support.h"

namespace curvebench {
namespace {

TEST(HnnCrust, ExactOnEpsilonSamplesAtFourTenths) { testing::expect_exact_on_all_families("hnn-crust", 0.4, 4); }

TEST(SparseSampleMethods, DuplicatesMapToTheirFirstOccurrence) {
  for (const char* name : {"hnn-crust", "crawl", "peel", "shape-hull"}) {
    auto points = testing::uniform_circle(40);
    const auto reference = testing::sorted(*find_algorithm(name).reconstruct(points, {}).curve_edges);
    points.push_back(points[7]);
    points.push_back(points[0]);
    const auto result = find_algorithm(name).reconstruct(points, {});
    EXPECT_EQ(result.distinct_points, 40) << name;
    EXPECT_EQ(testing::sorted(*result.curve_edges), reference) << name << ": duplicates get no edges of their own";
  }
}

}  // namespace
}  // namespace curvebench
