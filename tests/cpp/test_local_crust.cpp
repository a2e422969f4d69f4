// The one-step crust and anti-crust (Gold 1999): exact on epsilon-samples at 0.1 on every
// curve family; its interior anti-crust is the labeler's medial axis wherever both are exact;
// co-circular vertices merge; the classification against its definition; its skeleton stays
// inside its region on glyph outlines with straight strokes; refused input.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "baseline_families.h"
#include "core/registry.h"
#include "generators/generate.h"
#include "local-crust/anti_crust_medial_axis.h"
#include "local-crust/one_step_crust.h"
#include "metrics/evaluate_reconstruction.h"
#include "metrics/even_odd_areas.h"
#include "metrics/segments.h"
#include "test_support.h"

namespace curvebench {
namespace {

using testing::cycle_edges;
using testing::sorted;

Reconstruction local_crust_of(const std::vector<Point2>& points) {
  return find_algorithm("local-crust").reconstruct(points, {});
}

TEST(LocalCrust, ExactOnEpsilonSamplesAtOneTenth) { testing::expect_exact_on_all_families("local-crust", 0.1, 4); }

TEST(LocalCrust, UniformCircleIsTheRegularPolygon) {
  for (int n : {3, 4, 6, 12, 50, 1000}) {
    EXPECT_EQ(sorted(*local_crust_of(testing::uniform_circle(n)).curve_edges), cycle_edges(n)) << n;
  }
}

TEST(LocalCrust, ExactlyCocircularCircleIsThePolygonAndItsCentreIsTheSkeleton) {
  const auto result = local_crust_of(testing::lattice_circle(5525));
  EXPECT_EQ(sorted(*result.curve_edges), cycle_edges(180));
  ASSERT_EQ(result.medial_axis->vertices.size(), 1u) << "the 178 coinciding vertices merge";
  EXPECT_NEAR(norm(result.medial_axis->vertices[0]), 0.0, 1e-6);
  EXPECT_NEAR(result.medial_axis->radii[0], 5525.0, 1e-6);
  EXPECT_TRUE(result.medial_axis->edges.empty());
}

// With the curve exact, the Voronoi edges between inside vertices are exactly the interior
// anti-crust, so the two medial axes compared in the paper's Figure 18 coincide.
TEST(LocalCrust, InteriorSkeletonIsTheLabelersMedialAxisWhenBothAreExact) {
  int compared = 0;
  for (const auto& family : testing::curve_families()) {
    const SampledScene samples = epsilon_sample(family.scene, 0.1, 5);
    const auto ours = local_crust_of(samples.points);
    const auto labeler = find_algorithm("labeling").reconstruct(samples.points, {});
    if (sorted(*ours.curve_edges) != samples.true_edges || sorted(*labeler.curve_edges) != samples.true_edges) continue;
    ++compared;
    EXPECT_EQ(ours.medial_axis->vertices, labeler.medial_axis->vertices) << family.name;
    EXPECT_EQ(ours.medial_axis->radii, labeler.medial_axis->radii) << family.name;
    EXPECT_EQ(sorted(ours.medial_axis->edges), sorted(labeler.medial_axis->edges)) << family.name;
  }
  EXPECT_EQ(compared, static_cast<int>(testing::curve_families().size()));
}

TEST(LocalCrust, SkeletonOfAnEllipseLiesInsideItNearItsMedialSegment) {
  const Scene ellipse = ellipse_scene(2.0, 1.0);
  const auto result = local_crust_of(epsilon_sample(ellipse, 0.05, 1).points);
  ASSERT_FALSE(result.medial_axis->edges.empty());
  for (const Point2& v : result.medial_axis->vertices) {
    EXPECT_LT(v.x * v.x / 4 + v.y * v.y, 1.0);
    EXPECT_LT(std::abs(v.y), 0.1) << "the medial axis is the segment |x| <= 1.5, y = 0";
    EXPECT_LT(std::abs(v.x), 1.6);
  }
}

// Every Delaunay edge is crust exactly when its two opposite angles sum to less than 90
// degrees (a hull edge: when its one opposite angle is acute), checked in long double.
TEST(LocalCrust, ClassificationMatchesTheAngleCondition) {
  const SampledScene samples = epsilon_sample(rose_scene(1.0, 0.3, 5), 0.5, 2);
  const DelaunayVoronoi dv = build_delaunay_voronoi(samples.points);
  const OneStepCrust crust = one_step_crust(dv);
  auto angle = [&](int apex, int p, int q) {
    const Point2 u = dv.sites[p] - dv.sites[apex], w = dv.sites[q] - dv.sites[apex];
    return std::atan2(std::abs(static_cast<long double>(cross(u, w))), static_cast<long double>(dot(u, w)));
  };
  int crust_edges = 0;
  for (int t = 0; t < dv.triangle_count(); ++t) {
    const auto& tri = dv.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int p = tri[(k + 1) % 3], q = tri[(k + 2) % 3], other = dv.neighbors[t][k];
      long double sum = angle(tri[k], p, q);
      if (other != kInfinite) {
        const auto& o = dv.triangles[other];
        const int s = o[0] != p && o[0] != q ? o[0] : (o[1] != p && o[1] != q ? o[1] : o[2]);
        sum += angle(s, p, q);
      }
      EXPECT_EQ(crust.is_crust[t][k] == 1, sum < std::acos(0.0L)) << "triangle " << t << " corner " << k;
      if (crust.is_crust[t][k] && (other == kInfinite || other > t)) ++crust_edges;
    }
  }
  EXPECT_EQ(crust_edges, static_cast<int>(crust.curve.size()));
}

// DejaVu Sans 'A' as generators/real_outlines.py writes it (glyph_0041.rings): straight
// strokes, where three random samples on one stroke make a flat triangle whose circumcentre
// lies across the letter, far outside it: the skeleton kept such vertices before it was
// restricted to its region (algorithms/local-crust/README.md).
constexpr const char* kGlyphA = R"(0.341875 0.631875
0.20796875 0.2690625
0.47609375 0.2690625

0.28609375 0.7290625000000001
0.39796875 0.7290625000000001
0.67578125 0.0
0.57328125 0.0
0.506875 0.18703125
0.17828125 0.18703125
0.111875 0.0
0.0078125 0.0
)";

TEST(LocalCrust, SkeletonOfAGlyphWithStraightStrokesLiesInsideItsRegion) {
  const auto rings = std::filesystem::temp_directory_path() / ("curvebench_glyph_a_" + std::to_string(::getpid()) + ".rings");
  std::ofstream(rings) << kGlyphA;
  int vertices_checked = 0;
  for (const auto& [count, seed] : std::vector<std::pair<int, int>>{{200, 1}, {400, 2}, {800, 1}}) {
    GeneratorSettings settings;
    settings.family = "outline";
    settings.input = rings.string();
    settings.sampler = "random";
    settings.count = count;
    settings.seed = seed;
    settings.dense = 2048;
    const GeneratedInput input = generate(settings);
    const auto result = local_crust_of(input.points);
    const auto crust = edge_segments(input.points, *result.curve_edges);
    // Each vertex must meet the crust's even-odd region as the L2 metric computes it (an
    // exact arrangement, independent of the triangulation): a small square around the vertex
    // overlaps the region. Its area, 4e-10, stands well above the rounding of the region's
    // area in the overlap below.
    for (const Point2& v : result.medial_axis->vertices) {
      const double h = 1e-5;
      const auto square = closed_polyline_segments(std::vector<Point2>{v + Point2{-h, -h}, v + Point2{h, -h}, v + Point2{h, h}, v + Point2{-h, h}});
      const EvenOddAreas areas = even_odd_areas(crust, square);
      const double overlap = 0.5 * (areas.first + areas.second - areas.symmetric_difference);
      EXPECT_GT(overlap, 0.0) << count << " points, seed " << seed << ": vertex (" << v.x << ", " << v.y << ") is outside";
      ++vertices_checked;
    }
    if (!result.medial_axis->vertices.empty()) {
      const double distance = *evaluate_reconstruction(input.truth, input.points, result).medial_axis_hausdorff;
      EXPECT_LT(distance, 0.5) << count << " points, seed " << seed;
    }
  }
  std::filesystem::remove(rings);
  EXPECT_GT(vertices_checked, 100);
}

TEST(LocalCrust, RefusesInputWithoutAClosedCurve) {
  const auto& local_crust = find_algorithm("local-crust");
  EXPECT_THROW(local_crust.reconstruct(std::vector<Point2>{{1, 1}, {1, 1}, {1, 1}}, {}), InputError);
  EXPECT_THROW(local_crust.reconstruct(std::vector<Point2>{{0, 0}, {0, 1}, {0, 2}}, {}), InputError);
}

}  // namespace
}  // namespace curvebench
