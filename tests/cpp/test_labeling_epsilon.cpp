// Exactness on epsilon-samples (Definition 4): for points that epsilon-sample smooth closed
// curves, the labeler's curve is exactly the polygon(s) of curve-adjacent samples, at
// epsilon 0.1 and 0.2, with random non-uniform placement and fixed seeds. Every sample set
// is certified an epsilon-sample against the computed local feature size first.
#include <gtest/gtest.h>

#include "core/registry.h"
#include "generators/closed_curves.h"
#include "generators/samplers.h"
#include "test_support.h"

namespace curvebench {
namespace {

void expect_exact(const Scene& scene, double epsilon, std::uint64_t seed) {
  const SampledScene samples = epsilon_sample(scene, epsilon, seed);
  ASSERT_LE(achieved_epsilon(scene, samples), epsilon) << scene.name << ": not an epsilon-sample";
  const auto result = find_algorithm("labeling").reconstruct(samples.points, {});
  EXPECT_EQ(testing::sorted(*result.curve_edges), testing::sorted(samples.true_edges))
      << scene.name << " epsilon " << epsilon << " seed " << seed << " (" << samples.points.size() << " samples)";
}

class LabelingEpsilon : public ::testing::TestWithParam<double> {};

TEST_P(LabelingEpsilon, CircleAtRandomAngles) {
  const Scene circle = circle_scene(1.0);
  for (std::uint64_t seed = 1; seed <= 5; ++seed) expect_exact(circle, GetParam(), seed);
}

TEST_P(LabelingEpsilon, EllipsesWithAspectRatiosTwoAndFive) {
  for (double a : {2.0, 5.0}) {
    const Scene ellipse = ellipse_scene(a, 1.0);
    for (std::uint64_t seed = 1; seed <= 5; ++seed) expect_exact(ellipse, GetParam(), seed);
  }
}

TEST_P(LabelingEpsilon, Rose) {
  const Scene rose = rose_scene(1.0, 0.3, 5);
  for (std::uint64_t seed = 1; seed <= 5; ++seed) expect_exact(rose, GetParam(), seed);
}

TEST_P(LabelingEpsilon, FiftyRandomSmoothClosedCurves) {
  for (std::uint64_t curve = 1; curve <= 50; ++curve) expect_exact(random_fourier_scene(curve), GetParam(), 100 + curve);
}

TEST_P(LabelingEpsilon, ScenesOfTwoToFiveDisjointCurvesEachItsOwnPolygon) {
  for (int count = 2; count <= 5; ++count) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const Scene scene = disjoint_curves_scene(count, 10 * count + seed);
      ASSERT_EQ(static_cast<int>(scene.curves.size()), count);
      expect_exact(scene, GetParam(), seed);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Epsilon, LabelingEpsilon, ::testing::Values(0.1, 0.2),
                         [](const auto& info) { return info.param == 0.1 ? "0_1" : "0_2"; });

TEST(LabelingEpsilonCircle, UniformCircleOfEveryEpsilon) {
  // A uniformly sampled circle (co-circular up to rounding) at the density epsilon asks for:
  // a sample every 2*asin(epsilon/2)... conservatively n = ceil(2*pi/epsilon).
  for (double epsilon : {0.1, 0.2}) {
    const int n = static_cast<int>(std::ceil(2 * std::numbers::pi / epsilon));
    const auto result = find_algorithm("labeling").reconstruct(testing::uniform_circle(n), {});
    EXPECT_EQ(testing::sorted(*result.curve_edges), testing::cycle_edges(n));
  }
}

TEST(LabelingEpsilonInvariance, SameEdgesAndDominantPointsAfterScalingOrTranslation) {
  const SampledScene samples = epsilon_sample(rose_scene(1.0, 0.3, 5), 0.2, 9);
  const Algorithm& labeling = find_algorithm("labeling");
  const auto reference = labeling.reconstruct(samples.points, {});
  for (auto transform : {+[](Point2 p) { return 1e9 * p; }, +[](Point2 p) { return 1e-9 * p; },
                         +[](Point2 p) { return p + Point2{1e6, -1e6}; }}) {
    std::vector<Point2> moved;
    for (const auto& p : samples.points) moved.push_back(transform(p));
    const auto result = labeling.reconstruct(moved, {});
    EXPECT_EQ(testing::sorted(*result.curve_edges), testing::sorted(*reference.curve_edges));
    EXPECT_EQ(*result.dominant_points, *reference.dominant_points);
  }
}

}  // namespace
}  // namespace curvebench
