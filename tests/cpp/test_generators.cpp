// Curve families, local feature size against exact values, and epsilon-sampling
// (Definition 4 of the paper) certified on the dense polylines. Fixed seeds throughout.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "generators/closed_curves.h"
#include "generators/local_feature_size.h"
#include "generators/polylines_are_simple.h"
#include "generators/samplers.h"

namespace curvebench {
namespace {

double max_relative_error(const std::vector<double>& measured, const std::vector<double>& exact) {
  double worst = 0.0;
  for (size_t i = 0; i < exact.size(); ++i) worst = std::max(worst, std::abs(measured[i] - exact[i]) / exact[i]);
  return worst;
}

// The measured local feature size of a dense circle is its radius: every Voronoi vertex is
// the centre (measured relative error 3e-11 with 2048 vertices, rounding only).
TEST(LocalFeatureSize, CircleMatchesRadius) {
  const Scene circle = circle_scene(2.0, 2048);
  const auto measured = local_feature_size({circle.curves[0].points});
  EXPECT_LT(max_relative_error(measured[0], circle.curves[0].lfs), 1e-9);
}

// Ellipse: lfs at the ends of the major axis is b^2/a, and everywhere it is the distance to
// the medial segment |x| <= (a^2 - b^2)/a. The error of the Voronoi measurement falls as the
// square of the vertex spacing. Measured maximum relative errors (mean in brackets):
//   a=2, b=1:  512 vertices 2.7e-4 (5.9e-5), 2048: 1.7e-5 (3.7e-6), 8192: 1.0e-6 (2.3e-7)
//   a=3, b=1:  512 vertices 1.4e-3 (1.5e-4), 2048: 8.5e-5 (9.2e-6), 8192: 5.3e-6 (5.8e-7)
// the largest at the ends of the major axis, where lfs is smallest.
TEST(LocalFeatureSize, EllipseMatchesDistanceToMedialSegment) {
  const Scene ellipse = ellipse_scene(2.0, 1.0, 8192);
  const auto& curve = ellipse.curves[0];
  const auto measured = local_feature_size({curve.points});
  EXPECT_LT(max_relative_error(measured[0], curve.lfs), 2e-6);
  EXPECT_NEAR(curve.lfs[0], 0.5, 1e-12);  // vertex 0 is (a, 0)
  EXPECT_NEAR(measured[0][0], 0.5, 0.5 * 2e-6);

  const Scene flat = ellipse_scene(3.0, 1.0, 512);
  const auto flat_measured = local_feature_size({flat.curves[0].points});
  EXPECT_LT(max_relative_error(flat_measured[0], flat.curves[0].lfs), 2e-3);
  EXPECT_NEAR(flat_measured[0][0], 1.0 / 3.0, 2e-3 / 3.0);
}

TEST(ClosedCurves, FamiliesAreSimpleCounterClockwiseWithPositiveLfs) {
  for (const Scene& scene : {circle_scene(1.0), ellipse_scene(3.0, 1.0), rose_scene(1.0, 0.4, 5),
                             random_fourier_scene(7), disjoint_curves_scene(4, 11)}) {
    std::vector<std::vector<Point2>> polylines;
    for (const auto& curve : scene.curves) {
      double twice_area = 0.0;
      for (size_t i = 0; i < curve.points.size(); ++i) twice_area += cross(curve.points[i], curve.points[(i + 1) % curve.points.size()]);
      EXPECT_GT(twice_area, 0.0) << scene.name;
      EXPECT_GT(*std::min_element(curve.lfs.begin(), curve.lfs.end()), 0.0) << scene.name;
      polylines.push_back(curve.points);
    }
    EXPECT_EQ(find_polyline_crossing(polylines), "") << scene.name;
  }
  EXPECT_EQ(disjoint_curves_scene(4, 11).curves.size(), 4u);
}

TEST(ClosedCurves, SameSeedSameCurveDifferentSeedDifferentCurve) {
  EXPECT_EQ(random_fourier_scene(3).curves[0].points, random_fourier_scene(3).curves[0].points);
  EXPECT_NE(random_fourier_scene(3).curves[0].points, random_fourier_scene(4).curves[0].points);
  EXPECT_EQ(disjoint_curves_scene(3, 5).curves[2].points, disjoint_curves_scene(3, 5).curves[2].points);
}

TEST(ClosedCurves, BadSettingsThrow) {
  EXPECT_THROW(circle_scene(-1.0), std::invalid_argument);
  EXPECT_THROW(rose_scene(1.0, 1.0, 3), std::invalid_argument);  // r touches 0
  EXPECT_THROW(disjoint_curves_scene(0, 1), std::invalid_argument);
}

TEST(PolylineCrossing, FindsSelfIntersectionAndTouchingCurves) {
  const std::vector<Point2> bowtie{{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  EXPECT_NE(find_polyline_crossing({bowtie}), "");
  const std::vector<Point2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Point2> inner{{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}};
  const std::vector<Point2> touching{{1, 0.5}, {2, 0}, {2, 1}};
  EXPECT_EQ(find_polyline_crossing({square, inner}), "");  // nested is fine
  EXPECT_NE(find_polyline_crossing({square, touching}), "");
  EXPECT_NE(find_polyline_crossing({{{0, 0}, {2, 0}, {1, 0}}}), "");  // folds back on itself
}

TEST(EpsilonSample, CertifiedForEveryFamilyAndEpsilon) {
  for (const Scene& scene : {circle_scene(1.0), ellipse_scene(3.0, 1.0), rose_scene(1.0, 0.4, 5),
                             random_fourier_scene(7), disjoint_curves_scene(3, 11)}) {
    for (const double epsilon : {0.05, 0.2, 0.5}) {
      const SampledScene samples = epsilon_sample(scene, epsilon, 42);
      EXPECT_LE(achieved_epsilon(scene, samples), epsilon) << scene.name << " epsilon " << epsilon;
      // Not wasteful either: the walk takes at least half the largest step.
      EXPECT_GT(achieved_epsilon(scene, samples), 0.3 * epsilon) << scene.name << " epsilon " << epsilon;
    }
  }
}

TEST(EpsilonSample, TruthIsOneCyclePerCurveInParameterOrder) {
  const Scene scene = disjoint_curves_scene(3, 2);
  const SampledScene samples = epsilon_sample(scene, 0.3, 9);
  const size_t n = samples.points.size();
  ASSERT_EQ(samples.curve.size(), n);
  ASSERT_EQ(samples.parameter.size(), n);
  ASSERT_EQ(samples.lfs.size(), n);
  EXPECT_EQ(samples.true_edges.size(), n);  // one cycle per curve: as many edges as samples
  std::vector<int> degree(n, 0);
  for (const Edge& e : samples.true_edges) {
    EXPECT_EQ(samples.curve[e[0]], samples.curve[e[1]]);
    ++degree[e[0]], ++degree[e[1]];
  }
  EXPECT_TRUE(std::all_of(degree.begin(), degree.end(), [](int d) { return d == 2; }));
  std::set<int> curves(samples.curve.begin(), samples.curve.end());
  EXPECT_EQ(curves.size(), 3u);
  for (size_t i = 0; i < n; ++i) {
    EXPECT_GE(samples.parameter[i], 0.0);
    EXPECT_LT(samples.parameter[i], 1.0);
  }
}

TEST(EpsilonSample, DensityVariesAndFollowsLfs) {
  // On the ellipse a = 3, b = 1, lfs ranges over [1/3, ~1]: gaps near the ends of the major
  // axis are shorter than near the ends of the minor axis; random steps vary too.
  const Scene scene = ellipse_scene(3.0, 1.0);
  const SampledScene samples = epsilon_sample(scene, 0.2, 1);
  std::vector<double> gaps;
  double near_major_end = 1e9, near_minor_end = 0;
  for (const Edge& e : samples.true_edges) {
    const double gap = distance(samples.points[e[0]], samples.points[e[1]]);
    gaps.push_back(gap / samples.lfs[e[0]]);
    if (std::abs(samples.points[e[0]].x) > 2.8) near_major_end = std::min(near_major_end, gap);
    if (std::abs(samples.points[e[0]].x) < 0.2) near_minor_end = std::max(near_minor_end, gap);
  }
  EXPECT_LT(near_major_end, near_minor_end);
  const auto [low, high] = std::minmax_element(gaps.begin(), gaps.end());
  EXPECT_GT(*high / *low, 1.3);
}

TEST(EpsilonSample, SameSeedSameSamples) {
  const Scene scene = rose_scene(1.0, 0.3, 4);
  const SampledScene a = epsilon_sample(scene, 0.25, 5), b = epsilon_sample(scene, 0.25, 5), c = epsilon_sample(scene, 0.25, 6);
  EXPECT_EQ(a.points, b.points);
  EXPECT_NE(a.points, c.points);
}

TEST(EpsilonSample, BadEpsilonThrows) {
  const Scene scene = circle_scene(1.0, 64);
  EXPECT_THROW(epsilon_sample(scene, 0.0, 1), std::invalid_argument);
  EXPECT_THROW(epsilon_sample(scene, -0.1, 1), std::invalid_argument);
  EXPECT_THROW(epsilon_sample(scene, std::nan(""), 1), std::invalid_argument);
}

}  // namespace
}  // namespace curvebench
