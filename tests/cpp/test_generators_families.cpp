// More families (smooth, with corners, nested, imported polygons) and the samplers of a
// given count, normal noise and outliers. Fixed seeds throughout.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "generators/closed_curves.h"
#include "generators/polylines_are_simple.h"
#include "generators/samplers.h"
#include "test_support.h"

namespace curvebench {
namespace {

std::vector<std::vector<Point2>> polylines_of(const Scene& scene) {
  std::vector<std::vector<Point2>> out;
  for (const auto& curve : scene.curves) out.push_back(curve.points);
  return out;
}

double smallest_lfs(const Scene& scene) {
  double least = HUGE_VAL;
  for (const auto& curve : scene.curves) least = std::min(least, *std::min_element(curve.lfs.begin(), curve.lfs.end()));
  return least;
}

TEST(Families, SimplePositiveLfsAndCertifiedEpsilonSamples) {
  for (const Scene& scene : {superellipse_scene(1.0, 1.0, 4.0), dumbbell_scene(0.2), concavities_scene(5, 0.7, 0.08),
                             nested_curves_scene(3), holes_scene(1, 2), holes_scene(3, 4), star_scene(5, 0.4), square_scene(2.0), l_shape_scene(0.5),
                             horned_scene(0.8, 0.5)}) {
    EXPECT_EQ(find_polyline_crossing(polylines_of(scene)), "") << scene.name;
    EXPECT_GT(smallest_lfs(scene), 0.0) << scene.name;
    const SampledScene samples = epsilon_sample(scene, 0.3, 5);
    EXPECT_LE(achieved_epsilon(scene, samples), 0.3) << scene.name;
  }
}

TEST(Families, ShapeFacts) {
  // The dumbbell's neck: lfs there is the neck half-width (the medial axis runs along x).
  EXPECT_NEAR(smallest_lfs(dumbbell_scene(0.2)), 0.2, 2e-3);
  // Corners: star 2k, square 4, L 6, crescent 2; smooth families none.
  EXPECT_EQ(star_scene(5, 0.4).curves[0].corners.size(), 10u);
  EXPECT_EQ(square_scene(2.0).curves[0].corners.size(), 4u);
  EXPECT_EQ(l_shape_scene(0.5).curves[0].corners.size(), 6u);
  EXPECT_EQ(horned_scene(0.8, 0.5).curves[0].corners.size(), 2u);
  EXPECT_TRUE(superellipse_scene(1.0, 1.0, 4.0).curves[0].corners.empty());
  // Near a corner the local feature size goes to zero (the medial axis reaches the corner).
  const Scene square = square_scene(2.0);
  EXPECT_LT(square.curves[0].lfs[square.curves[0].corners[0]], 0.01);
  // Nested: two curves, the second inside the first (all its vertices closer to the origin).
  const Scene nested = nested_curves_scene(3);
  ASSERT_EQ(nested.curves.size(), 2u);
  double outer_min = HUGE_VAL, inner_max = 0;
  for (const Point2 p : nested.curves[0].points) outer_min = std::min(outer_min, norm(p));
  for (const Point2 p : nested.curves[1].points) inner_max = std::max(inner_max, norm(p));
  EXPECT_LT(inner_max, outer_min);
}

TEST(Families, HolesLieInsideTheOuterCurveAndTheirLfsSeesTheOuterCurve) {
  for (const int count : {1, 2, 3}) {
    for (const std::uint64_t seed : {1, 2, 3, 4, 5}) {
      const Scene scene = holes_scene(count, seed);
      ASSERT_EQ(scene.curves.size(), static_cast<size_t>(count + 1));
      const auto& outer = scene.curves[0].points;
      for (int h = 1; h <= count; ++h) {
        const auto& hole = scene.curves[h];
        EXPECT_TRUE(testing::inside_polygon(hole.points.front(), outer)) << "seed " << seed << " hole " << h;
        // The medial axis of the ring passes between a hole and the outer curve: no hole point
        // is farther from it than from the outer curve, and the hole's point nearest the outer
        // curve is at most half that distance from it (the midpoint is on the axis).
        double gap = HUGE_VAL, lfs_at_gap = 0;
        for (size_t i = 0; i < hole.points.size(); i += 4) {
          double to_outer = HUGE_VAL;
          for (const Point2 p : outer) to_outer = std::min(to_outer, distance(p, hole.points[i]));
          EXPECT_LE(hole.lfs[i], to_outer) << "seed " << seed << " hole " << h;
          if (to_outer < gap) gap = to_outer, lfs_at_gap = hole.lfs[i];
        }
        EXPECT_LE(lfs_at_gap, 0.51 * gap) << "seed " << seed << " hole " << h;
      }
    }
  }
  EXPECT_EQ(holes_scene(2, 7).curves[1].points, holes_scene(2, 7).curves[1].points);  // seeded
  EXPECT_THROW(holes_scene(0, 1), std::invalid_argument);
  EXPECT_THROW(holes_scene(9, 1), std::invalid_argument);
}

TEST(Families, PolygonImportRejectsSelfIntersectionAndKeepsClockwiseRingsCounterClockwise) {
  EXPECT_THROW(polygon_scene("bowtie", {{{0, 0}, {1, 1}, {1, 0}, {0, 1}}}), std::invalid_argument);
  EXPECT_THROW(polygon_scene("line", {{{0, 0}, {1, 1}, {0, 0}}}), std::invalid_argument);
  const Scene clockwise = polygon_scene("square", {{{0, 0}, {0, 1}, {1, 1}, {1, 0}, {0, 0}}}, 400);
  const auto& curve = clockwise.curves[0];
  double twice_area = 0;
  for (size_t i = 0; i < curve.points.size(); ++i) twice_area += cross(curve.points[i], curve.points[(i + 1) % curve.points.size()]);
  EXPECT_NEAR(twice_area, 2.0, 1e-12);
  ASSERT_EQ(curve.corners.size(), 4u);
  for (const int corner : curve.corners) {
    const Point2 p = curve.points[corner];
    EXPECT_TRUE((p.x == 0 || p.x == 1) && (p.y == 0 || p.y == 1));
  }
}

TEST(Samplers, ArcLengthSampleCountsAndSpacing) {
  const Scene scene = disjoint_curves_scene(3, 4);
  const SampledScene uniform = arc_length_sample(scene, 200, false, 1);
  EXPECT_EQ(uniform.points.size(), 200u);
  EXPECT_EQ(uniform.true_edges.size(), 200u);
  const SampledScene circle = arc_length_sample(circle_scene(1.0), 100, false, 1);
  for (const Edge& e : circle.true_edges) EXPECT_NEAR(distance(circle.points[e[0]], circle.points[e[1]]), 2 * std::sin(M_PI / 100), 1e-6);
  const SampledScene random = arc_length_sample(circle_scene(1.0), 100, true, 1);
  double shortest = HUGE_VAL, longest = 0;
  for (const Edge& e : random.true_edges) {
    shortest = std::min(shortest, distance(random.points[e[0]], random.points[e[1]]));
    longest = std::max(longest, distance(random.points[e[0]], random.points[e[1]]));
  }
  EXPECT_GT(longest / shortest, 5.0);
  EXPECT_THROW(arc_length_sample(scene, 8, false, 1), std::invalid_argument);  // fewer than 3 per curve
}

TEST(Samplers, NormalNoiseMovesAlongTheNormalWithTheRequestedScale) {
  const Scene circle = circle_scene(2.0);
  SampledScene samples = arc_length_sample(circle, 2000, false, 3);
  const SampledScene clean = samples;
  add_normal_noise(circle, samples, 0.05, NoiseScale::local_feature_size, 9);
  double sum2 = 0, tangential = 0;
  for (size_t i = 0; i < samples.points.size(); ++i) {
    const double radial = norm(samples.points[i]) - norm(clean.points[i]);
    sum2 += radial * radial;
    tangential = std::max(tangential, std::abs(cross(clean.points[i], samples.points[i])) / norm(clean.points[i]) / norm(samples.points[i]));
  }
  EXPECT_NEAR(std::sqrt(sum2 / samples.points.size()), 0.05 * 2.0, 0.01);  // sigma = 0.05 * lfs
  EXPECT_LT(tangential, 2e-3);                                              // sin of the angle moved: tiny
  EXPECT_EQ(samples.true_edges, clean.true_edges);
  SampledScene by_diagonal = clean;
  add_normal_noise(circle, by_diagonal, 0.01, NoiseScale::bounding_box_diagonal, 9);
  sum2 = 0;
  for (size_t i = 0; i < samples.points.size(); ++i) sum2 += std::pow(norm(by_diagonal.points[i]) - 2.0, 2);
  EXPECT_NEAR(std::sqrt(sum2 / samples.points.size()), 0.01 * 4 * std::sqrt(2.0), 0.01);
  EXPECT_THROW(add_normal_noise(circle, samples, std::nan(""), NoiseScale::local_feature_size, 1), std::invalid_argument);
}

TEST(Samplers, UniformNoiseFillsTheBandOfHalfWidthNoiseTimesScale) {
  const Scene circle = circle_scene(2.0);
  const SampledScene clean = arc_length_sample(circle, 4000, false, 3);
  SampledScene samples = clean;
  add_normal_noise(circle, samples, 0.1, NoiseScale::local_feature_size, 9, NoiseModel::uniform);
  const double half_width = 0.1 * 2.0;  // noise x lfs
  double largest = 0, sum = 0, sum2 = 0;
  for (size_t i = 0; i < samples.points.size(); ++i) {
    const double radial = norm(samples.points[i]) - norm(clean.points[i]);
    largest = std::max(largest, std::abs(radial));
    sum += radial, sum2 += radial * radial;
  }
  const double n = static_cast<double>(samples.points.size());
  EXPECT_LE(largest, half_width * (1 + 1e-9));
  EXPECT_GT(largest, 0.99 * half_width);                                   // the band is filled to its edges
  EXPECT_NEAR(sum / n, 0.0, 0.01 * half_width * 3);                        // centred on the curve
  EXPECT_NEAR(std::sqrt(sum2 / n), half_width / std::sqrt(3.0), 0.02 * half_width);  // uniform: w / sqrt 3
  EXPECT_EQ(samples.true_edges, clean.true_edges);
}

TEST(Samplers, OutliersAreAFractionInsideTheGrownBox) {
  const Scene scene = ellipse_scene(2.0, 1.0);
  SampledScene samples = epsilon_sample(scene, 0.2, 1);
  const size_t on_curve = samples.points.size();
  add_normal_noise(scene, samples, 0.02, NoiseScale::local_feature_size, 2);
  add_outliers(scene, samples, 0.4, 3);
  const size_t outliers = samples.points.size() - on_curve;
  EXPECT_EQ(outliers, static_cast<size_t>(std::lround(0.4 * on_curve)));
  for (size_t i = on_curve; i < samples.points.size(); ++i) {
    EXPECT_EQ(samples.curve[i], -1);
    EXPECT_TRUE(std::isnan(samples.parameter[i]));
    EXPECT_LE(std::abs(samples.points[i].x), 2.0 * 1.2);
    EXPECT_LE(std::abs(samples.points[i].y), 1.0 * 1.2);
  }
  for (const Edge& e : samples.true_edges) EXPECT_LT(static_cast<size_t>(e[1]), on_curve);
  EXPECT_THROW(add_outliers(scene, samples, -0.1, 1), std::invalid_argument);
}

}  // namespace
}  // namespace curvebench
