// Ground truth beyond the curve: the interior medial axis (numeric against exact) and the
// dominant points (corners, curvature peaks).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "generators/closed_curves.h"
#include "generators/dominant_points.h"
#include "generators/medial_axis.h"
#include "test_support.h"

namespace curvebench {
namespace {

int components(const MedialAxis& axis) {
  std::vector<int> parent(axis.vertices.size());
  for (size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
  auto root = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const Edge& e : axis.edges) parent[root(e[0])] = root(e[1]);
  int count = 0;
  for (size_t i = 0; i < parent.size(); ++i) count += root(static_cast<int>(i)) == static_cast<int>(i);
  return count;
}

// The numeric medial axis of the ellipse a = 2, b = 1 (4096 dense vertices) lies on the
// exact segment |x| <= 1.5 (measured 4e-15), spans it to 1e-3, is one connected piece, and
// its radii are the distances to the curve.
TEST(MedialAxis, NumericMatchesExactOnTheEllipse) {
  const MedialAxis numeric = interior_medial_axis(ellipse_scene(2.0, 1.0, 4096));
  const MedialAxis exact = ellipse_medial_axis(2.0, 1.0);
  double worst = 0, low = 0, high = 0;
  for (const Point2 v : numeric.vertices) {
    worst = std::max(worst, distance_to_segment(v, {-1.5, 0}, {1.5, 0}));
    low = std::min(low, v.x), high = std::max(high, v.x);
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_NEAR(low, -1.5, 1e-3);
  EXPECT_NEAR(high, 1.5, 1e-3);
  EXPECT_EQ(components(numeric), 1);
  EXPECT_EQ(exact.vertices.front(), (Point2{-1.5, 0}));
  EXPECT_NEAR(exact.radii.front(), 0.5, 1e-12);  // b^2/a at the end
  EXPECT_NEAR(exact.radii[exact.radii.size() / 2], 1.0, 1e-12);  // b at the centre
}

TEST(MedialAxis, ConnectedInsideEveryRegion) {
  EXPECT_EQ(components(interior_medial_axis(rose_scene(1.0, 0.3, 5))), 1);
  EXPECT_EQ(components(interior_medial_axis(star_scene(5, 0.45))), 1);
  EXPECT_EQ(components(interior_medial_axis(disjoint_curves_scene(3, 1))), 3);
  // Nested: the region is the ring between the curves, so the axis runs between them.
  const Scene nested = nested_curves_scene(1);
  const MedialAxis ring = interior_medial_axis(nested);
  EXPECT_EQ(components(ring), 1);
  double inner_max = 0;
  for (const Point2 p : nested.curves[1].points) inner_max = std::max(inner_max, norm(p));
  for (const Point2 v : ring.vertices) EXPECT_GT(norm(v), 0.5 * inner_max);
  // Holes: one connected axis in the region between the outer curve and its holes, none of
  // it inside a hole.
  const Scene holes = holes_scene(3, 2);
  const MedialAxis around_holes = interior_medial_axis(holes);
  EXPECT_EQ(components(around_holes), 1);
  for (const Point2 v : around_holes.vertices) {
    for (size_t h = 1; h < holes.curves.size(); ++h) {
      EXPECT_FALSE(testing::inside_polygon(v, holes.curves[h].points)) << "medial-axis vertex inside hole " << h;
    }
  }
}

TEST(DominantPoints, CornersAndCurvaturePeaks) {
  EXPECT_TRUE(true_dominant_points(circle_scene(1.0)).empty());
  const auto ellipse = true_dominant_points(ellipse_scene(2.0, 1.0));
  ASSERT_EQ(ellipse.size(), 2u);
  EXPECT_NEAR(std::abs(ellipse[0].x), 2.0, 1e-9);
  EXPECT_EQ(true_dominant_points(rose_scene(1.0, 0.3, 5)).size(), 10u);  // 5 tips, 5 valleys
  EXPECT_EQ(true_dominant_points(star_scene(6, 0.5)).size(), 12u);
  const auto square = true_dominant_points(square_scene(2.0));
  ASSERT_EQ(square.size(), 4u);
  for (const Point2 p : square) EXPECT_TRUE(std::abs(p.x) == 1.0 && std::abs(p.y) == 1.0);
}

}  // namespace
}  // namespace curvebench
