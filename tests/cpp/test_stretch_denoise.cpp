// StretchDenoise (stretchdenoise.md): pass 1 connectivity and pass 2 denoising on small cases.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "fitconnect/fitconnect.h"
#include "fitconnect/fitted_neighborhoods.h"
#include "generators/generate.h"
#include "metrics/distance_to_curve.h"
#include "metrics/true_curve_segments.h"
#include "stretchdenoise/denoise_along_normals.h"
#include "stretchdenoise/stretch_denoise.h"
#include "test_support.h"

namespace curvebench {
namespace {

using testing::cycle_edges;
using testing::sorted;

// Samples of the unit circle at angles `angles`, moved radially by uniform noise in [-band, band]
// (the bounded noise model StretchDenoise's guarantees assume).
std::vector<Point2> circle_in_band(const std::vector<double>& angles, double band, unsigned seed,
                                   Point2 center = {0, 0}) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> offset(-band, band);
  std::vector<Point2> points;
  for (double t : angles) {
    const double r = 1 + offset(rng);
    points.push_back(center + Point2{r * std::cos(t), r * std::sin(t)});
  }
  return points;
}

std::vector<double> even_angles(int n) {
  std::vector<double> angles;
  for (int k = 0; k < n; ++k) angles.push_back(2 * std::numbers::pi * k / n);
  return angles;
}

std::vector<int> degrees_of(const std::vector<Edge>& edges, int n) {
  std::vector<int> degree(n, 0);
  for (const Edge& e : edges) ++degree[e[0]], ++degree[e[1]];
  return degree;
}

double mean_distance_to_unit_circle(const std::vector<Point2>& points, const std::vector<int>& which) {
  double sum = 0;
  for (int i : which) sum += std::abs(norm(points[i]) - 1);
  return sum / which.size();
}

TEST(StretchDenoise, NoisyCircleIsOneExactPolygon) {
  // FitConnect §4 / StretchDenoise §4: 100 samples, +-2 % noise per coordinate: exact.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> offset(-0.02, 0.02);
  std::vector<Point2> points = testing::uniform_circle(100);
  for (Point2& p : points) p = p + Point2{offset(rng), offset(rng)};
  const DenoisedCurve curve = stretch_denoise(points);
  EXPECT_EQ(sorted(curve.edges), cycle_edges(100));
  ASSERT_EQ(curve.positions.size(), points.size());
}

TEST(StretchDenoise, EstimatedExtentsFreezeMostVerticesAndKeepEveryMoveInsideItsExtent) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> offset(-0.03, 0.03);
  std::vector<Point2> points = testing::uniform_circle(100);
  for (Point2& p : points) p = p + Point2{offset(rng), offset(rng)};
  const FittedNeighborhoods fits = connect_fitted_neighborhoods(points);
  ASSERT_EQ(sorted(fits.edges), cycle_edges(100));
  const std::vector<Point2> moved = denoise_along_normals(points, fits, fits.residuals);
  int moving = 0;
  for (int i = 0; i < 100; ++i) {
    const double shift = distance(moved[i], points[i]);
    EXPECT_LE(shift, fits.residuals[i] + 1e-11) << i;  // spec 2.9 bounds (extents floored at 1e-12 of the size)
    moving += shift > 1e-9;
  }
  // Spec §4: a three-point neighbourhood is interpolated, so most extents vanish; some move.
  EXPECT_GT(moving, 0);
  EXPECT_LT(moving, 80);
}

TEST(StretchDenoise, RandomAngleSamplesDropSomeClosePairsAndKeepThemInPlace) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi);
  std::vector<double> angles(200);
  for (double& t : angles) t = angle(rng);
  const std::vector<Point2> points = circle_in_band(angles, 0, 1);
  const DenoisedCurve curve = stretch_denoise(points, 0.01);
  const std::vector<int> degree = degrees_of(curve.edges, 200);
  std::vector<int> kept;
  for (int i = 0; i < 200; ++i) {
    EXPECT_TRUE(degree[i] == 0 || degree[i] == 2) << i;
    if (degree[i] == 2) kept.push_back(i);
  }
  // FitConnect §4: a few percent of random-angle samples are dropped (close pairs).
  EXPECT_LT(kept.size(), 200u);
  EXPECT_GT(kept.size(), 170u);
  // The kept samples form the polygon in angular order.
  std::sort(kept.begin(), kept.end(), [&](int a, int b) { return angles[a] < angles[b]; });
  std::vector<Edge> expected;
  for (std::size_t k = 0; k < kept.size(); ++k) expected.push_back(make_edge(kept[k], kept[(k + 1) % kept.size()]));
  EXPECT_EQ(sorted(curve.edges), sorted(expected));
  for (int i = 0; i < 200; ++i)
    if (degree[i] == 0) {
      EXPECT_EQ(curve.positions[i], points[i]) << "dropped sample " << i << " moved";
    }
}

TEST(StretchDenoise, TwoNoisyDisjointCirclesAreTwoPolygonsAndBothAreDenoised) {
  std::vector<Point2> points = circle_in_band(even_angles(60), 0.02, 5);
  const std::vector<Point2> second = circle_in_band(even_angles(60), 0.02, 6, {3, 0});
  points.insert(points.end(), second.begin(), second.end());
  const DenoisedCurve curve = stretch_denoise(points, 0.02);
  std::vector<Edge> expected = cycle_edges(60);
  const std::vector<Edge> other = cycle_edges(60, 60);
  expected.insert(expected.end(), other.begin(), other.end());
  EXPECT_EQ(sorted(curve.edges), sorted(expected));
  // The reference moves only the circle holding the lowest-index vertex (spec §3); both move here.
  int moved[2] = {0, 0};
  for (int i = 0; i < 120; ++i) moved[i / 60] += distance(curve.positions[i], points[i]) > 1e-9;
  EXPECT_GT(moved[0], 10);
  EXPECT_GT(moved[1], 10);
}

TEST(StretchDenoise, OpenArcIsAPathWithFixedLeafEnds) {
  // Noise-free arc of 50 samples over half the circle: a path with two LEAF ends.
  std::vector<double> angles;
  for (int k = 0; k < 50; ++k) angles.push_back(std::numbers::pi * k / 49);
  const std::vector<Point2> points = circle_in_band(angles, 0, 1);
  const FittedNeighborhoods fits = connect_fitted_neighborhoods(points);
  std::vector<Edge> path;
  for (int k = 0; k + 1 < 50; ++k) path.push_back(make_edge(k, k + 1));
  EXPECT_EQ(sorted(fits.edges), path);
  EXPECT_EQ(fits.states[0], SampleState::Leaf);
  EXPECT_EQ(fits.states[49], SampleState::Leaf);
  // Chain ends stay where they are even with a large extent (the reference writes past them).
  const std::vector<double> sigma(50, 0.05);
  const std::vector<Point2> moved = denoise_along_normals(points, fits, sigma);
  EXPECT_EQ(moved[0], points[0]);
  EXPECT_EQ(moved[49], points[49]);
  for (int i = 0; i < 50; ++i) EXPECT_LE(distance(moved[i], points[i]), 0.05 + 1e-12);
}

TEST(StretchDenoise, SquareCornersAreKept) {
  // FitConnect §4: a square is reconstructed exactly.
  const std::vector<Point2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Point2> points = testing::sample_polygon_evenly(square, 40);
  const DenoisedCurve curve = stretch_denoise(points, 0.005);
  EXPECT_EQ(sorted(curve.edges), cycle_edges(40));
  // A corner cannot be fitted by a line within the extents: it is sharp and ends windows, so
  // the corner samples stay within their discs and the square keeps its corners.
  for (int corner : {0, 10, 20, 30}) EXPECT_LE(distance(curve.positions[corner], points[corner]), 0.005 + 1e-12);
}

TEST(StretchDenoise, FewerThanThreePointsGiveNoEdgesAndUnmovedPoints) {
  for (int n = 0; n < 3; ++n) {
    std::vector<Point2> points;
    for (int i = 0; i < n; ++i) points.push_back({static_cast<double>(i), 0.5 * i});
    const DenoisedCurve curve = stretch_denoise(points, 0.1);
    EXPECT_TRUE(curve.edges.empty());
    EXPECT_EQ(curve.positions, points);
  }
}

// Denoising with the extent of a uniform band noise brings the vertices closer to the curve.
void expect_closer_after_denoising(int samples, double band, unsigned seed) {
  const std::vector<Point2> points = circle_in_band(even_angles(samples), band, seed);
  const DenoisedCurve curve = stretch_denoise(points, band);
  ASSERT_EQ(sorted(curve.edges), cycle_edges(samples)) << "band " << band;
  std::vector<int> all(samples);
  std::iota(all.begin(), all.end(), 0);
  const double before = mean_distance_to_unit_circle(points, all);
  const double after = mean_distance_to_unit_circle(curve.positions, all);
  EXPECT_LT(after, 0.8 * before) << "band " << band << " seed " << seed;
}

TEST(StretchDenoise, DenoisingBringsVerticesCloserAtFivePercentNoise) {
  for (unsigned seed : {1u, 2u, 3u}) expect_closer_after_denoising(60, 0.05, seed);
}

TEST(StretchDenoise, DenoisingBringsVerticesCloserAtTenPercentNoise) {
  for (unsigned seed : {1u, 2u, 3u}) expect_closer_after_denoising(30, 0.1, seed);
}

// Mean distance from the ends of `edges`, at `positions`, to the true curves.
double mean_vertex_distance(const std::vector<Segment2>& curve, const std::vector<Point2>& positions,
                            const std::vector<Edge>& edges) {
  std::vector<char> on_curve(positions.size(), 0);
  for (const Edge& e : edges) on_curve[e[0]] = on_curve[e[1]] = 1;
  std::vector<Point2> vertices;
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (on_curve[i]) vertices.push_back(positions[i]);
  return distance_to_curve(curve, vertices).mean;
}

// The case: epsilon-samples of the smooth families, moved along the normal uniformly in
// a band of half-width `band` times the local feature size. Given the band as its noise extent
// (a sensor model; the smallest band of any sample, so that no extent exceeds its sample's),
// StretchDenoise brings the vertices markedly closer to the true curve. With extents estimated
// from pass 1 (the default) most samples are frozen (a 3-point fit interpolates, spec 2.4): the
// few that move, within tiny extents, to the optimum of the model's angles and balance (not of
// their distance to the curve), leave the mean distance within 0.01% of the input's, and
// FitConnect's blend must not move the vertices farther from the curve on average.
void expect_denoising_on_smooth_families(double band) {
  for (const std::string family : {"circle", "ellipse", "superellipse", "rose", "random", "dumbbell"}) {
    for (std::uint64_t seed : {1u, 2u}) {
      GeneratorSettings settings;
      settings.family = family;
      settings.epsilon = 0.1;
      settings.noise = band;
      settings.noise_model = "uniform";
      settings.seed = seed;
      settings.dense = 2048;
      const GeneratedInput input = generate(settings);
      const std::vector<Segment2> curve = true_curve_segments(input.truth);
      double smallest_lfs = std::numeric_limits<double>::infinity();
      for (const GroundTruthSample& sample : input.truth.samples) smallest_lfs = std::min(smallest_lfs, sample.lfs);
      const std::string which = family + " seed " + std::to_string(seed) + " band " + std::to_string(band);

      const DenoisedCurve given = stretch_denoise(input.points, band * smallest_lfs);
      const double before = mean_vertex_distance(curve, input.points, given.edges);
      EXPECT_LT(mean_vertex_distance(curve, given.positions, given.edges), 0.85 * before) << which;

      const DenoisedCurve estimated = stretch_denoise(input.points);
      EXPECT_LE(mean_vertex_distance(curve, estimated.positions, estimated.edges),
                mean_vertex_distance(curve, input.points, estimated.edges) * (1 + 1e-4))
          << which;
      const DenoisedCurve blended = fitconnect(input.points);
      EXPECT_LE(mean_vertex_distance(curve, blended.positions, blended.edges),
                mean_vertex_distance(curve, input.points, blended.edges) * (1 + 1e-9))
          << which;
    }
  }
}

// Spec §3: the bounded least-squares problem solved to its optimum, not by the reference's
// clamping and freezing (a value frozen at its bound never comes back). Random samples of a
// circle in a band of 0.01 (its radius is 1), given the band as extent: the mean distance to
// the circle falls by a fifth or more on each of 20 seeds. Clamping and freezing fell short of
// that on 11 of them (seed 11: 0.99 of the input's).
TEST(StretchDenoise, GivenTheBandAsExtentEveryRandomCircleComesCloserByAFifth) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    GeneratorSettings settings;
    settings.family = "circle";
    settings.sampler = "random";
    settings.count = 150;
    settings.noise = 0.01;
    settings.noise_model = "uniform";
    settings.seed = seed;
    const GeneratedInput input = generate(settings);
    const std::vector<Segment2> curve = true_curve_segments(input.truth);
    const DenoisedCurve denoised = stretch_denoise(input.points, 0.01);
    EXPECT_LT(mean_vertex_distance(curve, denoised.positions, denoised.edges),
              0.8 * mean_vertex_distance(curve, input.points, denoised.edges))
        << "seed " << seed;
  }
}

TEST(StretchDenoise, DenoisingBringsEpsilonSamplesOfSmoothFamiliesCloserAtFivePercentOfLfs) {
  expect_denoising_on_smooth_families(0.05);
}

TEST(StretchDenoise, DenoisingBringsEpsilonSamplesOfSmoothFamiliesCloserAtTenPercentOfLfs) {
  expect_denoising_on_smooth_families(0.1);
}

}  // namespace
}  // namespace curvebench
