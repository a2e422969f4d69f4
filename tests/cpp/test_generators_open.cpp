// Open curves: local feature size of an arc as a set (by hand on a circular arc), samplers
// that keep both ends and a path as truth, the truth file's "closed" flag, and the metrics
// that an open truth leaves undefined. Fixed seeds throughout.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "generators/generate.h"
#include "generators/open_curves.h"
#include "generators/polylines_are_simple.h"
#include "generators/samplers.h"
#include "io/ground_truth_json.h"
#include "io/metrics_json.h"
#include "metrics/evaluate_reconstruction.h"
#include "metrics/oracle_l2_error.h"

namespace curvebench {
namespace {

// The medial axis of a circular arc (radius R, centred at the origin, the gap's middle at
// angle pi) is the ray from the centre through the gap: lfs = R sin(delta) where the angle
// delta between p and the gap's middle is below 90 degrees, R elsewhere.
double circular_arc_lfs(Point2 p, double radius) {
  const double delta = std::numbers::pi - std::abs(std::atan2(p.y, p.x));
  return delta < std::numbers::pi / 2 ? radius * std::sin(delta) : radius;
}

TEST(OpenCurves, CircularArcLfsIsTheDistanceToTheRayThroughTheGap) {
  for (const double angle : {120.0, 270.0, 340.0}) {
    const Scene arc = circular_arc_scene(2.0, angle, 2048);
    ASSERT_EQ(arc.curves.size(), 1u);
    const DenseCurve& curve = arc.curves[0];
    EXPECT_FALSE(curve.closed);
    double worst = 0;
    for (size_t i = 0; i < curve.points.size(); ++i) worst = std::max(worst, std::abs(curve.lfs[i] - circular_arc_lfs(curve.points[i], 2.0)));
    EXPECT_LT(worst, 1e-8) << angle;
    // At the ends R sin(angle / 2) beyond 180 degrees, R up to it.
    const double end_lfs = angle > 180 ? 2.0 * std::sin(angle * std::numbers::pi / 360) : 2.0;
    EXPECT_NEAR(curve.lfs.front(), end_lfs, 1e-8) << angle;
    EXPECT_NEAR(curve.lfs.back(), end_lfs, 1e-8) << angle;
    EXPECT_NEAR(curve.points.front().x, 2.0 * std::cos(angle * std::numbers::pi / 360), 1e-12);
    EXPECT_NEAR(curve.points.back().y, 2.0 * std::sin(angle * std::numbers::pi / 360), 1e-12);
  }
}

TEST(OpenCurves, FamiliesAreSimpleWithPositiveLfsAtTheEnds) {
  for (const Scene& scene : {elliptic_arc_scene(2.0, 1.0, 300.0), spiral_scene(2.5, 0.3), open_random_scene(4)}) {
    const DenseCurve& curve = scene.curves[0];
    EXPECT_FALSE(curve.closed);
    EXPECT_EQ(find_polyline_crossing({curve.points}, {false}), "") << scene.name;
    EXPECT_GT(*std::min_element(curve.lfs.begin(), curve.lfs.end()), 0.0) << scene.name;
  }
  // Ellipse arc a = 2, b = 1 over 300 degrees: its ends (-sqrt 3, +-1/2) are equidistant
  // from the negative x axis beyond them, part of the axis, so lfs <= 1/2 there.
  const Scene ellipse_arc = elliptic_arc_scene(2.0, 1.0, 300.0);
  EXPECT_LE(ellipse_arc.curves[0].lfs.front(), 0.5 + 1e-9);
  // The spiral's turns are `gap` apart: lfs is about half of it.
  const Scene spiral = spiral_scene(2.0, 0.3);
  for (const double lfs : spiral.curves[0].lfs) EXPECT_NEAR(lfs, 0.15, 0.01);
  // An open polyline is not closed up when checked: this zigzag is simple, its closure not.
  const std::vector<Point2> zigzag{{0, 0}, {1, 1}, {2, 0}, {3, 1}};
  EXPECT_EQ(find_polyline_crossing({zigzag}, {false}), "");
  EXPECT_NE(find_polyline_crossing({zigzag}), "");
}

TEST(OpenCurves, EverySamplerKeepsBothEndsAndATruePath) {
  const Scene scene = elliptic_arc_scene(2.0, 1.0, 270.0);
  const Point2 first = scene.curves[0].points.front(), last = scene.curves[0].points.back();
  for (const SampledScene& samples : {epsilon_sample(scene, 0.1, 3), epsilon_sample(scene, 0.5, 3), arc_length_sample(scene, 40, false, 3),
                                      arc_length_sample(scene, 40, true, 3)}) {
    const size_t n = samples.points.size();
    EXPECT_EQ(samples.points.front(), first);
    EXPECT_EQ(samples.points.back(), last);
    EXPECT_EQ(samples.parameter.front(), 0.0);
    EXPECT_EQ(samples.parameter.back(), 1.0);
    ASSERT_EQ(samples.true_edges.size(), n - 1);  // a path
    for (size_t i = 0; i + 1 < n; ++i) EXPECT_EQ(samples.true_edges[i], make_edge(static_cast<int>(i), static_cast<int>(i + 1)));
    EXPECT_TRUE(std::is_sorted(samples.parameter.begin(), samples.parameter.end()));
  }
  for (const Scene& open : {circular_arc_scene(1.0, 300.0), spiral_scene(2.0, 0.3), open_random_scene(2)}) {
    for (const double epsilon : {0.1, 0.3, 0.5}) {
      const SampledScene samples = epsilon_sample(open, epsilon, 8);
      EXPECT_LE(achieved_epsilon(open, samples), epsilon) << open.name << " epsilon " << epsilon;
      EXPECT_GE(samples.points.size(), 3u);
    }
  }
}

GeneratedInput generated(const std::string& family, double epsilon) {
  GeneratorSettings settings;
  settings.family = family;
  settings.epsilon = epsilon;
  settings.dense = 2048;
  return generate(settings);
}

TEST(OpenCurves, TruthFileMarksOpenCurvesAndOldFilesReadAsClosed) {
  const GeneratedInput arc = generated("arc", 0.3);
  EXPECT_TRUE(arc.truth.medial_axis.vertices.empty());
  const auto json = ground_truth_to_json(arc.truth);
  EXPECT_EQ(json["curves"][0]["closed"], false);
  EXPECT_FALSE(ground_truth_from_json(json, "arc").curves[0].closed);
  auto bad = json;
  bad["curves"][0]["closed"] = "no";
  EXPECT_THROW(ground_truth_from_json(bad, "arc"), std::runtime_error);
  // Closed curves are written without the flag, as before it existed, and read as closed.
  const auto circle = ground_truth_to_json(generated("circle", 0.3).truth);
  EXPECT_FALSE(circle["curves"][0].contains("closed"));
  EXPECT_TRUE(ground_truth_from_json(circle, "circle").curves[0].closed);
}

TEST(OpenCurves, MetricsOfAnOpenTruth) {
  const GeneratedInput arc = generated("arc", 0.2);
  Reconstruction perfect;
  perfect.curve_edges = arc.truth.edges;
  perfect.medial_axis = MedialAxis{{{0, 0}}, {1.0}, {}};
  const ReconstructionMetrics m = evaluate_reconstruction(arc.truth, arc.points, perfect);
  EXPECT_TRUE(std::isnan(oracle_l2_error(arc.truth, arc.points)));
  ASSERT_TRUE(m.l2_error.has_value());
  EXPECT_TRUE(std::isnan(*m.l2_error));
  EXPECT_FALSE(m.medial_axis_hausdorff.has_value());
  EXPECT_TRUE(m.edges->exact);
  EXPECT_DOUBLE_EQ(m.edges->precision, 1.0);
  // The true arc has no closing segment: the path of its samples is close to it everywhere
  // (a closing chord across the 90 degree gap would be 0.7 of the radius away).
  EXPECT_LT(*m.hausdorff, 0.01);
  const auto json = metrics_to_json(m);
  EXPECT_TRUE(json["l2_error"].is_null());
  EXPECT_FALSE(json.contains("medial_axis_hausdorff"));
}

}  // namespace
}  // namespace curvebench
