// The labeling algorithm on hand-made inputs: degenerate circles, sharp corners, dominant
// points, input it must refuse, and the invariants of its labels.
#include <gtest/gtest.h>

#include <map>

#include "core/registry.h"
#include "labeling/dominant_points.h"
#include "labeling/extract_shapes.h"
#include "labeling/label_voronoi_vertices.h"
#include "test_support.h"

namespace curvebench {
namespace {

using testing::cycle_edges;
using testing::cyclic_distance;
using testing::lattice_circle;
using testing::sample_polygon_evenly;
using testing::star_polygon;
using testing::uniform_circle;

Reconstruction run_labeling(const std::vector<Point2>& points) {
  return find_algorithm("labeling").reconstruct(points, {});
}

TEST(Labeling, UniformCircleIsTheRegularPolygon) {
  for (int n : {3, 4, 6, 12, 50, 1000}) {
    const auto result = run_labeling(uniform_circle(n));
    EXPECT_EQ(testing::sorted(*result.curve_edges), cycle_edges(n)) << n << " points";
  }
}

TEST(Labeling, ExactlyCocircularCircleIsThePolygonAndItsCentreIsTheMedialAxis) {
  const auto points = lattice_circle(5525);  // 180 points, one Voronoi vertex of degree 180
  const auto result = run_labeling(points);
  EXPECT_EQ(testing::sorted(*result.curve_edges), cycle_edges(180));
  ASSERT_EQ(result.medial_axis->vertices.size(), 1u) << "the 178 coinciding vertices merge";
  EXPECT_NEAR(norm(result.medial_axis->vertices[0]), 0.0, 1e-6);
  EXPECT_NEAR(result.medial_axis->radii[0], 5525.0, 1e-6);
  EXPECT_TRUE(result.medial_axis->edges.empty());
}

TEST(Labeling, SquareSampledEvenlyIsExactWithDominantPointsAtTheCorners) {
  const std::vector<Point2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const auto points = sample_polygon_evenly(square, 200);
  const auto result = run_labeling(points);
  EXPECT_EQ(testing::sorted(*result.curve_edges), cycle_edges(200));
  for (int corner : {0, 50, 100, 150}) {
    EXPECT_TRUE(std::any_of(result.dominant_points->begin(), result.dominant_points->end(),
                            [&](int dp) { return cyclic_distance(dp, corner, 200) <= 2; }))
        << "no dominant point near corner sample " << corner;
  }
}

TEST(Labeling, StarSampledEvenlyIsExactWithDominantPointsAtAllTenCorners) {
  const auto points = sample_polygon_evenly(star_polygon(0.6), 200);
  const auto result = run_labeling(points);
  EXPECT_EQ(testing::sorted(*result.curve_edges), cycle_edges(200));
  for (int corner = 0; corner < 200; corner += 20) {  // tips at even multiples of 20, inner corners between
    EXPECT_TRUE(std::any_of(result.dominant_points->begin(), result.dominant_points->end(),
                            [&](int dp) { return cyclic_distance(dp, corner, 200) <= 2; }))
        << "no dominant point near corner sample " << corner;
  }
}

TEST(Labeling, EveryDominantPointShowsALabelPatternOnItsCell) {
  const auto points = sample_polygon_evenly(star_polygon(0.6), 200);
  const auto dv = build_delaunay_voronoi(points);
  const auto labels = label_voronoi_vertices(dv);
  const auto dominant = detect_dominant_points(dv, labels, extract_curve_edges(dv, labels));
  ASSERT_FALSE(dominant.empty());
  std::vector<int> cell;
  for (int site : dominant) {
    voronoi_cell(dv, site, cell);
    int inner = 0;
    for (int t : cell) inner += labels.inner[t];
    const int outer = static_cast<int>(cell.size()) - inner + (dv.on_hull[site] ? 1 : 0);
    EXPECT_TRUE(inner >= 1 && outer >= 1) << "a pattern needs both labels in the cell of " << site;
  }
}

TEST(Labeling, LabelsAreConsistentWithEveryOutput) {
  const auto points = sample_polygon_evenly(star_polygon(0.5), 150);
  const auto dv = build_delaunay_voronoi(points);
  const auto labels = label_voronoi_vertices(dv);
  EXPECT_GT(labels.queued_vertices, 0) << "a star has pseudo-concavities: walks must start";
  // Each sample of the curve is paired with a source vertex that is outer (or infinite).
  for (int s = 0; s < dv.site_count(); ++s) {
    const int source = labels.source_vertex[s];
    ASSERT_NE(source, kUnpaired) << "sample " << s;
    if (source != kInfinite) {
      EXPECT_FALSE(labels.inner[source]);
    }
  }
  // The medial axis is exactly the inner vertices (before merging none coincide here).
  const auto axis = extract_interior_medial_axis(dv, labels);
  EXPECT_EQ(axis.vertices.size(), static_cast<size_t>(std::count(labels.inner.begin(), labels.inner.end(), 1)));
  // Curve degree 2 everywhere: every sample has exactly two curve edges.
  std::map<int, int> degree;
  for (const auto& e : extract_curve_edges(dv, labels)) ++degree[e[0]], ++degree[e[1]];
  for (int s = 0; s < dv.site_count(); ++s) EXPECT_EQ(degree[s], 2) << "sample " << s;
}

TEST(Labeling, DuplicatesAreReportedAtTheirFirstOccurrence) {
  const auto circle = uniform_circle(8);
  // Input: c0 c1 c5 c2 c3 c4 c5 c6 c7 c3 -> c5 first occurs at index 2, c3 at index 4.
  const std::vector<Point2> points{circle[0], circle[1], circle[5], circle[2], circle[3],
                                   circle[4], circle[5], circle[6], circle[7], circle[3]};
  const auto result = run_labeling(points);
  EXPECT_EQ(result.distinct_points, 8);
  const std::vector<Edge> expected = testing::sorted({make_edge(0, 1), make_edge(1, 3), make_edge(3, 4), make_edge(4, 5),
                                                      make_edge(5, 2), make_edge(2, 7), make_edge(7, 8), make_edge(8, 0)});
  EXPECT_EQ(testing::sorted(*result.curve_edges), expected);
}

TEST(Labeling, RefusesInputWithoutAClosedCurve) {
  EXPECT_THROW(run_labeling({}), InputError);
  EXPECT_THROW(run_labeling({{0, 0}}), InputError);
  EXPECT_THROW(run_labeling({{0, 0}, {1, 1}, {0, 0}}), InputError);
  try {
    run_labeling({{0, 0}, {1, 1}, {2, 2}, {3, 3}});
    FAIL() << "collinear input must be refused";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "labeling: all 4 distinct points are collinear, so they bound no closed curve");
  }
  EXPECT_THROW(find_algorithm("labeling").reconstruct(uniform_circle(5), {{"no_such_parameter", 1.0}}), InputError);
}

TEST(Labeling, ThreePointsAreATriangle) {
  const auto result = run_labeling({{0, 0}, {1, 0}, {0.3, 0.8}});
  EXPECT_EQ(testing::sorted(*result.curve_edges), cycle_edges(3));
}

TEST(Labeling, TimingsNameEveryPhase) {
  const auto result = run_labeling(uniform_circle(20));
  ASSERT_EQ(result.timing_ms.size(), 4u);
  EXPECT_EQ(result.timing_ms[0].first, "delaunay");
  EXPECT_EQ(result.timing_ms[1].first, "labeling");
  EXPECT_EQ(result.timing_ms[2].first, "extract");
  EXPECT_EQ(result.timing_ms[3].first, "total");
}

}  // namespace
}  // namespace curvebench
