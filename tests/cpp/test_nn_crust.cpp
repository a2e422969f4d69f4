// The NN-crust (Dey, Kumar 1999): exact on epsilon-samples below 1/3, shown at 0.3 on every
// curve family; ties on uniform and exactly co-circular circles; input it must refuse.
#include <gtest/gtest.h>

#include "baseline_families.h"
#include "core/registry.h"
#include "test_support.h"

namespace curvebench {
namespace {

using testing::cycle_edges;
using testing::sorted;

std::vector<Edge> nn_crust_of(const std::vector<Point2>& points) {
  return sorted(*find_algorithm("nn-crust").reconstruct(points, {}).curve_edges);
}

TEST(NnCrust, ExactOnEpsilonSamplesAtThreeTenths) { testing::expect_exact_on_all_families("nn-crust", 0.3, 4); }

TEST(NnCrust, UniformCircleIsTheRegularPolygon) {
  // Both neighbours are equally near: one is the nearest, the other the half neighbour.
  for (int n : {4, 6, 12, 50, 1000}) EXPECT_EQ(nn_crust_of(testing::uniform_circle(n)), cycle_edges(n)) << n;
}

TEST(NnCrust, EquilateralTriangleStaysOpenByDefinition) {
  // The other sample is 60 degrees from the nearest neighbour: no half neighbours, so only
  // nearest-neighbour edges, two of the three sides.
  EXPECT_EQ(nn_crust_of(testing::uniform_circle(3)).size(), 2u);
}

TEST(NnCrust, ExactlyCocircularCircleIsThePolygon) {
  EXPECT_EQ(nn_crust_of(testing::lattice_circle(5525)), cycle_edges(180));
}

TEST(NnCrust, EdgesAreUniqueAndDuplicatesMapToTheirFirstOccurrence) {
  auto points = testing::uniform_circle(40);
  points.push_back(points[7]);
  points.push_back(points[0]);
  const auto result = find_algorithm("nn-crust").reconstruct(points, {});
  EXPECT_EQ(result.distinct_points, 40);
  EXPECT_EQ(result.curve_edges->size(), 40u) << "each edge once";
  EXPECT_EQ(sorted(*result.curve_edges), cycle_edges(40));
}

TEST(NnCrust, RefusesInputWithoutAClosedCurve) {
  const auto& nn_crust = find_algorithm("nn-crust");
  EXPECT_THROW(nn_crust.reconstruct(std::vector<Point2>{{0, 0}, {1, 0}}, {}), InputError);
  EXPECT_THROW(nn_crust.reconstruct(std::vector<Point2>{{0, 0}, {1, 0}, {2, 0}, {1, 0}}, {}), InputError);
}

}  // namespace
}  // namespace curvebench
