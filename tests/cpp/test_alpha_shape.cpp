// CGAL's regularized alpha shape behind the interface: the automatic alpha on convex curves,
// the override, the components rule for disjoint curves, bad parameters and refused input.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/registry.h"
#include "generators/closed_curves.h"
#include "generators/samplers.h"
#include "test_support.h"

namespace curvebench {
namespace {

using testing::cycle_edges;
using testing::sorted;

std::vector<Edge> alpha_shape_of(const std::vector<Point2>& points, const ParameterAssignments& params = {}) {
  return sorted(*find_algorithm("alpha-shape").reconstruct(points, params).curve_edges);
}

TEST(AlphaShape, OptimalAlphaFillsConvexCurves) {
  EXPECT_EQ(alpha_shape_of(testing::uniform_circle(200)), cycle_edges(200));
  EXPECT_EQ(alpha_shape_of(testing::lattice_circle(5525)), cycle_edges(180));
  const SampledScene ellipse = epsilon_sample(ellipse_scene(2.0, 1.0), 0.2, 1);
  EXPECT_EQ(alpha_shape_of(ellipse.points), ellipse.true_edges);
}

TEST(AlphaShape, AlphaOverridesTheRule) {
  // A disk smaller than half the spacing erases everything; one larger than the circle
  // leaves the convex hull.
  EXPECT_TRUE(alpha_shape_of(testing::uniform_circle(100), {{"alpha", 1e-6}}).empty());
  EXPECT_EQ(alpha_shape_of(testing::uniform_circle(100), {{"alpha", 4.0}}), cycle_edges(100));
}

TEST(AlphaShape, ComponentsLetsDisjointCurvesStaySeparate) {
  const SampledScene samples = epsilon_sample(disjoint_curves_scene(3, 11), 0.1, 1);
  auto joins_two_curves = [&](const std::vector<Edge>& edges) {
    return std::any_of(edges.begin(), edges.end(), [&](Edge e) { return samples.curve[e[0]] != samples.curve[e[1]]; });
  };
  // One solid component bridges the curves; allowing three, no edge joins two curves.
  EXPECT_TRUE(joins_two_curves(alpha_shape_of(samples.points)));
  EXPECT_FALSE(joins_two_curves(alpha_shape_of(samples.points, {{"components", 3}})));
}

TEST(AlphaShape, RefusesBadParametersAndInputWithoutAClosedCurve) {
  const auto& alpha_shape = find_algorithm("alpha-shape");
  const auto circle = testing::uniform_circle(10);
  EXPECT_THROW(alpha_shape.reconstruct(circle, {{"alpha", -1}}), InputError);
  EXPECT_THROW(alpha_shape.reconstruct(circle, {{"components", 0}}), InputError);
  EXPECT_THROW(alpha_shape.reconstruct(circle, {{"components", 1.5}}), InputError);
  EXPECT_THROW(alpha_shape.reconstruct(std::vector<Point2>{{0, 0}, {1, 1}}, {}), InputError);
  EXPECT_THROW(alpha_shape.reconstruct(std::vector<Point2>{{0, 0}, {1, 1}, {2, 2}}, {}), InputError);
}

TEST(AlphaShape, DuplicatesMapToTheirFirstOccurrence) {
  auto points = testing::uniform_circle(30);
  points.push_back(points[3]);
  const auto result = find_algorithm("alpha-shape").reconstruct(points, {});
  EXPECT_EQ(result.distinct_points, 30);
  EXPECT_EQ(sorted(*result.curve_edges), cycle_edges(30));
}

}  // namespace
}  // namespace curvebench
