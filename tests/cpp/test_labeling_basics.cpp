// The labeling algorithm on hand-made inputs: degenerate circles, sharp corners, dominant
// points, input it must refuse, and the invariants of its labels.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <numbers>
#include <random>
#include <utility>

#include "core/registry.h"
#include "labeling/extract_shapes.h"
#include "labeling/label_voronoi_vertices.h"
#include "labeling/side_of_tangent_line.h"
#include "test_support.h"

namespace curvebench {
namespace {

using testing::cycle_edges;
using testing::cyclic_distance;
using testing::lattice_circle;
using testing::random_order;
using testing::rose_in_curve_order;
using testing::sample_polygon_evenly;
using testing::star_polygon;
using testing::uniform_circle;
using testing::voronoi_cell;

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
  const auto dominant = extract_curve_and_dominant_points(dv, labels).dominant_points;
  ASSERT_FALSE(dominant.empty());
  for (int site : dominant) {
    const auto cell = voronoi_cell(dv, site);
    int inner = 0;
    for (int t : cell) inner += labels.inner[t];
    const int outer = static_cast<int>(cell.size()) - inner + (dv.on_hull[site] ? 1 : 0);
    EXPECT_TRUE(inner >= 1 && outer >= 1) << "a pattern needs both labels in the cell of " << site;
  }
}

// Section 3.4 read literally: walk each cell cyclically (the infinite vertex closing an
// unbounded one, its direction the outward normal of the hull edge next to it), look for a
// vertex whose label differs from both neighbours, and apply the filter to its terminals.
std::vector<int> dominant_points_cell_by_cell(const DelaunayVoronoi& dv, const VoronoiLabels& labels) {
  const int hull_size = static_cast<int>(dv.hull.size());
  std::vector<int> dominant;
  for (int site = 0; site < dv.site_count(); ++site) {
    const auto cell = voronoi_cell(dv, site);
    const int m = static_cast<int>(cell.size());
    const int cycle = m + (dv.on_hull[site] ? 1 : 0);  // position m is the infinite vertex
    auto is_inner = [&](int pos) { return pos < m && labels.inner[cell[pos]]; };
    const Point2 p = dv.sites[site];
    // The hull edge to the counter-clockwise next hull site precedes cell[0]; the edge from the
    // previous one follows cell[m - 1].
    auto hull_normal = [&](bool at_end) {
      const int h = static_cast<int>(std::find(dv.hull.begin(), dv.hull.end(), site) - dv.hull.begin());
      const Point2 from = at_end ? dv.sites[dv.hull[(h + hull_size - 1) % hull_size]] : p;
      const Point2 to = at_end ? p : dv.sites[dv.hull[(h + 1) % hull_size]];
      return Point2{to.y - from.y, from.x - to.x};
    };
    bool found = false;
    for (int pos = 0; pos < m && !found; ++pos) {
      const int before = (pos + cycle - 1) % cycle, after = (pos + 1) % cycle;
      const bool centre = is_inner(pos);
      if (is_inner(before) == centre || is_inner(after) == centre) continue;
      const int c = cell[pos];
      auto across = [&](int terminal, bool at_end) {
        if (terminal == m) return dot(hull_normal(at_end), dv.circumcenters[c] - p) < 0;
        return side_of_tangent_line(dv, site, c, cell[terminal]) < 0;
      };
      found = across(before, false) && across(after, true);
    }
    if (found) dominant.push_back(site);
  }
  return dominant;
}

TEST(Labeling, DominantPointsFromLocalLabelChangesEqualTheCellByCellReading) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Point2> cloud(400);  // random labels everywhere, and hull samples with patterns
  for (auto& p : cloud) p = {unit(rng), unit(rng)};
  std::vector<Point2> noisy_circle;
  for (int k = 0; k < 300; ++k) {
    const double t = 2 * std::numbers::pi * unit(rng), r = 1 + 0.05 * (unit(rng) - 0.5);
    noisy_circle.push_back({r * std::cos(t), r * std::sin(t)});
  }
  const std::vector<std::vector<Point2>> inputs{sample_polygon_evenly(star_polygon(0.6), 200),
                                               sample_polygon_evenly({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 200),
                                               cloud, noisy_circle, uniform_circle(12), lattice_circle(5525)};
  int dominant_total = 0, on_hull = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const auto dv = build_delaunay_voronoi(inputs[i]);
    const auto labels = label_voronoi_vertices(dv);
    const auto reference = dominant_points_cell_by_cell(dv, labels);
    EXPECT_EQ(extract_curve_and_dominant_points(dv, labels).dominant_points, reference) << "input " << i;
    dominant_total += static_cast<int>(reference.size());
    for (int site : reference) on_hull += dv.on_hull[site];
  }
  EXPECT_GT(dominant_total, 20) << "the inputs must show patterns";
  EXPECT_GT(on_hull, 0) << "and some on hull samples, where the infinite vertex is a terminal";
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
  for (const auto& e : extract_curve_and_dominant_points(dv, labels).curve_edges) ++degree[e[0]], ++degree[e[1]];
  for (int s = 0; s < dv.site_count(); ++s) EXPECT_EQ(degree[s], 2) << "sample " << s;
}

// Points in curve order and the same points shuffled are numbered differently by the Voronoi
// layer (sites in input order, and in Z order). On an epsilon-sample the labels are fixed by
// the geometry, so every output must be the same, read back in the first file's indices.
TEST(Labeling, OutputOfAnEpsilonSampleDoesNotDependOnThePointOrder) {
  const int n = 3000;
  const auto along = rose_in_curve_order(n, 9);
  const auto order = random_order(n, 10);  // shuffled[i] = along[order[i]]
  std::vector<Point2> shuffled;
  for (int i : order) shuffled.push_back(along[i]);
  const auto a = run_labeling(along), b = run_labeling(shuffled);

  EXPECT_EQ(testing::sorted(*a.curve_edges), cycle_edges(n));
  std::vector<Edge> b_curve;
  for (const auto& e : *b.curve_edges) b_curve.push_back(make_edge(order[e[0]], order[e[1]]));
  EXPECT_EQ(testing::sorted(b_curve), cycle_edges(n));

  auto in_along_indices = [&](std::vector<int> dominant, bool from_shuffled) {
    if (from_shuffled) {
      for (int& i : dominant) i = order[i];
    }
    std::sort(dominant.begin(), dominant.end());
    return dominant;
  };
  EXPECT_EQ(in_along_indices(*a.dominant_points, false), in_along_indices(*b.dominant_points, true));

  // The medial axis as geometry, its vertices with radii and its edges as pairs of vertices,
  // equal up to rounding: CGAL may list a triangle's corners in another rotation, and the
  // computed circumcentre depends on which corner comes first (by up to 7e-12 here; the
  // Voronoi layer keeps the relative error of a centre below about 1e-8).
  auto geometry = [](const MedialAxis& axis) {
    std::vector<std::array<double, 3>> disks;
    for (std::size_t i = 0; i < axis.vertices.size(); ++i) disks.push_back({axis.vertices[i].x, axis.vertices[i].y, axis.radii[i]});
    std::vector<std::array<double, 4>> edges;
    for (const auto& e : axis.edges) {
      const auto [p, q] = std::minmax(disks[e[0]], disks[e[1]]);
      edges.push_back({p[0], p[1], q[0], q[1]});
    }
    std::sort(disks.begin(), disks.end());
    std::sort(edges.begin(), edges.end());
    return std::pair(disks, edges);
  };
  auto expect_near = [](const auto& a, const auto& b, const char* what) {
    ASSERT_EQ(a.size(), b.size()) << what;
    int far = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      for (std::size_t k = 0; k < a[i].size(); ++k) far += !(std::abs(a[i][k] - b[i][k]) <= 1e-9);
    }
    EXPECT_EQ(far, 0) << what;
  };
  const auto [a_disks, a_edges] = geometry(*a.medial_axis);
  const auto [b_disks, b_edges] = geometry(*b.medial_axis);
  ASSERT_GT(a_disks.size(), 1000u);
  expect_near(a_disks, b_disks, "medial-axis vertices");
  expect_near(a_edges, b_edges, "medial-axis edges");
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
