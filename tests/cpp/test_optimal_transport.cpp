// CGAL's optimal-transport reconstruction behind the interface: it reports new vertices, its
// edges index them, a densely sampled curve gives a closed polygon near the curve, and the
// vertex target, bad parameters and refused input.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "core/registry.h"
#include "generators/closed_curves.h"
#include "generators/samplers.h"
#include "test_support.h"

namespace curvebench {
namespace {

Reconstruction transport_of(const std::vector<Point2>& points, const ParameterAssignments& params = {}) {
  return find_algorithm("optimal-transport").reconstruct(points, params);
}

// Every vertex of the edge set has degree 2.
bool is_closed_polygon(const std::vector<Edge>& edges) {
  std::map<int, int> degree;
  for (const auto& e : edges) ++degree[e[0]], ++degree[e[1]];
  return !degree.empty() && std::all_of(degree.begin(), degree.end(), [](auto entry) { return entry.second == 2; });
}

TEST(OptimalTransport, DenseEllipseGivesAClosedPolygonOfNewVerticesNearTheCurve) {
  const SampledScene samples = epsilon_sample(ellipse_scene(2.0, 1.0), 0.02, 1);
  const auto result = transport_of(samples.points);
  ASSERT_TRUE(result.new_curve.has_value());
  EXPECT_FALSE(result.curve_edges.has_value()) << "no edges between input points";
  const auto& vertices = result.new_curve->vertices;
  EXPECT_LT(vertices.size(), samples.points.size()) << "a simplification";
  for (const auto& e : result.new_curve->edges) {
    ASSERT_LT(e[1], static_cast<int>(vertices.size())) << "edges index the new vertices";
    EXPECT_LT(e[0], e[1]);
  }
  EXPECT_TRUE(is_closed_polygon(result.new_curve->edges));
  for (const Point2& v : vertices) EXPECT_NEAR(v.x * v.x / 4 + v.y * v.y, 1.0, 0.02);
}

TEST(OptimalTransport, VerticesParameterSetsTheOutputSize) {
  const auto result = transport_of(testing::uniform_circle(300), {{"vertices", 24}});
  EXPECT_EQ(result.new_curve->vertices.size(), 24u);
  EXPECT_TRUE(is_closed_polygon(result.new_curve->edges));
}

TEST(OptimalTransport, SameInputSameOutput) {
  const auto points = epsilon_sample(rose_scene(1.0, 0.3, 5), 0.05, 4).points;
  const auto a = transport_of(points), b = transport_of(points);
  EXPECT_EQ(a.new_curve->vertices, b.new_curve->vertices);
  EXPECT_EQ(a.new_curve->edges, b.new_curve->edges);
}

TEST(OptimalTransport, RefusesBadParametersAndInputWithoutAClosedCurve) {
  const auto circle = testing::uniform_circle(20);
  EXPECT_THROW(transport_of(circle, {{"tolerance", 0}}), InputError);
  EXPECT_THROW(transport_of(circle, {{"vertices", -3}}), InputError);
  EXPECT_THROW(transport_of(circle, {{"relocation", 0.5}}), InputError);
  EXPECT_THROW(transport_of(std::vector<Point2>{{0, 0}, {1, 1}, {0, 0}}), InputError);
  EXPECT_THROW(transport_of(std::vector<Point2>{{0, 0}, {1, 1}, {2, 2}}), InputError);
}

}  // namespace
}  // namespace curvebench
