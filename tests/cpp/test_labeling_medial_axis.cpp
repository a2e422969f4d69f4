// The interior medial axis converges: an ellipse with semi-axes 2 and 1 sampled ever more
// densely; its true medial axis is the segment between the centres of curvature of the
// ends of the major axis, (-1.5, 0) to (1.5, 0). Samples are at random parameters (a
// symmetric sampling would put every Voronoi vertex exactly on the axis and prove nothing).
#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "core/registry.h"
#include "test_support.h"

namespace curvebench {
namespace {


// Symmetric Hausdorff distance between a medial axis (vertices and straight edges) and the
// segment ab. Medial-axis side: distance to a segment is convex along a straight edge, so
// the vertices attain the maximum. Segment side: dense points on ab against every edge.
double hausdorff_to_segment(const MedialAxis& axis, Point2 a, Point2 b) {
  double worst = 0;
  for (const auto& v : axis.vertices) worst = std::max(worst, distance_to_segment(v, a, b));
  for (int k = 0; k <= 2000; ++k) {
    const Point2 q = a + (k / 2000.0) * (b - a);
    double nearest = std::numeric_limits<double>::max();
    for (const auto& v : axis.vertices) nearest = std::min(nearest, distance(q, v));
    for (const auto& e : axis.edges) {
      nearest = std::min(nearest, distance_to_segment(q, axis.vertices[e[0]], axis.vertices[e[1]]));
    }
    worst = std::max(worst, nearest);
  }
  return worst;
}

TEST(LabelingMedialAxis, EllipseMedialAxisConvergesToTheTrueSegment) {
  const double diagonal = std::hypot(4.0, 2.0);
  double previous = std::numeric_limits<double>::max();
  for (int n : {200, 800, 3200}) {
    std::mt19937_64 rng(7);
    std::vector<double> parameters(n);
    for (auto& t : parameters) t = 2 * std::numbers::pi * static_cast<double>(rng() >> 11) * 0x1.0p-53;
    std::sort(parameters.begin(), parameters.end());
    std::vector<Point2> points;
    for (double t : parameters) points.push_back({2 * std::cos(t), std::sin(t)});
    const auto result = find_algorithm("labeling").reconstruct(points, {});
    EXPECT_EQ(testing::sorted(*result.curve_edges), testing::cycle_edges(n));
    const double error = hausdorff_to_segment(*result.medial_axis, {-1.5, 0}, {1.5, 0}) / diagonal;
    RecordProperty("hausdorff_over_diagonal_" + std::to_string(n), std::to_string(error));
    std::printf("ellipse n=%d: medial-axis Hausdorff / diagonal = %.5f\n", n, error);
    EXPECT_LT(error, previous) << "no convergence at n = " << n;
    previous = error;
  }
  EXPECT_LT(previous, 0.02);
}

}  // namespace
}  // namespace curvebench
