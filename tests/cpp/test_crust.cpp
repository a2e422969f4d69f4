// The crust (Amenta, Bern, Eppstein 1998): exact on epsilon-samples below 0.252, shown at
// 0.2 on every curve family; exactly co-circular input; input it must refuse.
#include <gtest/gtest.h>

#include "baseline_families.h"
#include "core/registry.h"
#include "crust/crust_triangulation.h"
#include "voronoi/delaunay_voronoi.h"
#include "test_support.h"

namespace curvebench {
namespace {

using testing::cycle_edges;
using testing::sorted;

std::vector<Edge> crust_of(const std::vector<Point2>& points) {
  return sorted(*find_algorithm("crust").reconstruct(points, {}).curve_edges);
}

TEST(Crust, ExactOnEpsilonSamplesAtTwoTenths) { testing::expect_exact_on_all_families("crust", 0.2, 4); }

TEST(Crust, UniformCircleIsTheRegularPolygon) {
  for (int n : {3, 4, 6, 12, 50, 1000}) EXPECT_EQ(crust_of(testing::uniform_circle(n)), cycle_edges(n)) << n;
}

TEST(Crust, ExactlyCocircularCircleIsThePolygon) {
  // 180 integer points on x^2 + y^2 = 5525^2: all 178 Voronoi vertices coincide at the centre.
  EXPECT_EQ(crust_of(testing::lattice_circle(5525)), cycle_edges(180));
}

TEST(Crust, DuplicatesMapToTheirFirstOccurrence) {
  auto points = testing::uniform_circle(40);
  const auto once = points;
  points.insert(points.end(), once.begin(), once.end());
  const auto result = find_algorithm("crust").reconstruct(points, {});
  EXPECT_EQ(result.distinct_points, 40);
  EXPECT_EQ(sorted(*result.curve_edges), cycle_edges(40));
}

TEST(Crust, EdgesAreDelaunayEdgesOfTheSamples) {
  const SampledScene samples = epsilon_sample(rose_scene(1.0, 0.3, 5), 0.4, 3);
  const DelaunayVoronoi dv = build_delaunay_voronoi(samples.points);
  std::vector<Edge> delaunay;
  for (const auto& tri : dv.triangles) {
    for (int k = 0; k < 3; ++k) delaunay.push_back(make_edge(tri[k], tri[(k + 1) % 3]));
  }
  std::sort(delaunay.begin(), delaunay.end());
  const auto crust = delaunay_edges_with_voronoi_vertices(dv);
  for (const Edge& e : crust) EXPECT_TRUE(std::binary_search(delaunay.begin(), delaunay.end(), e));
}

TEST(Crust, RefusesInputWithoutAClosedCurve) {
  const auto& crust = find_algorithm("crust");
  EXPECT_THROW(crust.reconstruct(std::vector<Point2>{}, {}), InputError);
  EXPECT_THROW(crust.reconstruct(std::vector<Point2>{{0, 0}, {1, 1}, {0, 0}}, {}), InputError);
  EXPECT_THROW(crust.reconstruct(std::vector<Point2>{{0, 0}, {1, 1}, {2, 2}, {3, 3}}, {}), InputError);
  EXPECT_THROW(crust.reconstruct(testing::uniform_circle(5), {{"epsilon", 1.0}}), InputError);
}

}  // namespace
}  // namespace curvebench
