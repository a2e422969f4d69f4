// The degenerate-input suite, run for every registered algorithm: each returns a valid
// result (every index in range) or throws InputError with a message; none crashes or hangs.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <string>

#include "core/registry.h"
#include "test_support.h"

namespace curvebench {
namespace {

struct DegenerateCase {
  std::string name;
  std::vector<Point2> points;
};

std::vector<DegenerateCase> degenerate_cases() {
  std::vector<DegenerateCase> cases;
  std::vector<Point2> grid;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) grid.push_back({double(i), double(j)});
  cases.push_back({"regular grid", grid});
  cases.push_back({"uniform circle", testing::uniform_circle(64)});
  cases.push_back({"co-circular lattice circle", testing::lattice_circle(5525)});
  std::vector<Point2> line;
  for (int i = 0; i < 50; ++i) line.push_back({0.5 * i, 0.25 * i});
  cases.push_back({"collinear", line});
  std::vector<Point2> duplicates;
  for (int copy = 0; copy < 5; ++copy)
    for (const auto& p : testing::uniform_circle(20)) duplicates.push_back(p);
  cases.push_back({"many duplicates", duplicates});
  std::vector<Point2> near;
  for (const auto& p : testing::uniform_circle(30)) near.push_back(p), near.push_back({p.x + 1e-12, p.y - 1e-12});
  cases.push_back({"near-duplicates 1e-12 apart", near});
  std::vector<Point2> huge, tiny;
  for (const auto& p : testing::uniform_circle(40)) huge.push_back({1e9 + 1e3 * p.x, 1e9 + 1e3 * p.y}), tiny.push_back(1e-9 * p);
  cases.push_back({"coordinates around 1e9", huge});
  cases.push_back({"coordinates around 1e-9", tiny});
  // Squared distances overflow to infinity; found by fuzz_reconstruct (nn-crust read sites[-1]).
  cases.push_back({"one coordinate of 1e160", {{1.02077327578e160, 1.1437001796735144}, {2.8e-16, 1.0}, {-0.101, 1.0}, {0.0, 0.0}}});
  cases.push_back({"circle of radius 1e160", testing::uniform_circle(40, 1e160)});
  cases.push_back({"circle of radius 1e307", testing::uniform_circle(40, 1e307)});
  cases.push_back({"corners near the largest double", {{-1.7e308, -1.7e308}, {1.7e308, -1.7e308}, {1.7e308, 1.7e308}, {-1.7e308, 1.7e308}, {0, 0}, {1e300, -3e307}}});
  // Squared circumradii round to zero: alpha-shape's spectrum was empty and it read before it.
  cases.push_back({"denormal coordinates", {{4e-320, 0}, {0, 4e-320}, {-4e-320, 0}, {0, -4e-320}, {1e-321, 1e-321}}});
  cases.push_back({"no point", {}});
  cases.push_back({"one point", {{1, 2}}});
  cases.push_back({"two points", {{1, 2}, {3, 4}}});
  cases.push_back({"three points", {{0, 0}, {1, 0}, {0.2, 0.7}}});
  std::vector<Point2> line_plus_one;
  for (int i = 0; i < 100000; ++i) line_plus_one.push_back({static_cast<double>(i), 0.0});
  line_plus_one.push_back({50000.5, 1.0});
  cases.push_back({"1e5 points on a line plus one off it", line_plus_one});
  return cases;
}

void expect_valid(const Reconstruction& result, size_t point_count, const std::string& where) {
  auto in_range = [](const std::vector<Edge>& edges, size_t count) {
    return std::all_of(edges.begin(), edges.end(), [&](const Edge& e) {
      return e[0] >= 0 && e[1] >= 0 && static_cast<size_t>(e[0]) < count && static_cast<size_t>(e[1]) < count && e[0] != e[1];
    });
  };
  if (const auto curve = curve_view(result, {})) {
    const size_t count = curve->on_input_points ? point_count : curve->vertices.size();
    EXPECT_TRUE(in_range({curve->edges.begin(), curve->edges.end()}, count)) << where << ": curve edge out of range";
  }
  if (result.moved_points) {
    EXPECT_EQ(result.moved_points->size(), point_count) << where << ": one position per point";
  }
  if (result.medial_axis) {
    EXPECT_EQ(result.medial_axis->vertices.size(), result.medial_axis->radii.size()) << where;
    EXPECT_TRUE(in_range(result.medial_axis->edges, result.medial_axis->vertices.size())) << where << ": medial-axis edge";
  }
  if (result.dominant_points) {
    for (int i : *result.dominant_points) EXPECT_TRUE(i >= 0 && static_cast<size_t>(i) < point_count) << where;
  }
}

// One test per registered algorithm (by name), so that ctest runs them side by side: under
// the sanitizers the whole list of cases takes minutes for some algorithms.
std::vector<std::string> algorithm_names() {
  std::vector<std::string> names;
  for (const Algorithm* algorithm : all_algorithms()) names.push_back(algorithm->name());
  return names;
}

class EveryAlgorithm : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryAlgorithm, GivesAValidResultOrAnInputErrorOnDegenerateInputs) {
  const Algorithm& algorithm = find_algorithm(GetParam());
  const ParameterAssignments defaults;
  for (const auto& c : degenerate_cases()) {
    const std::string where = algorithm.name() + " on " + c.name;
    try {
      expect_valid(algorithm.reconstruct(c.points, defaults), c.points.size(), where);
    } catch (const InputError& e) {
      EXPECT_GT(std::string(e.what()).size(), 10u) << where << ": an error needs a message";
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << where << ": one line";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(DegenerateInputs, EveryAlgorithm, ::testing::ValuesIn(algorithm_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;  // test names take no '-'
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(DegenerateInputs, AlgorithmsRefuseWhatHasNoCurveWithTheSameKindOfMessage) {
  for (const Algorithm* algorithm : all_algorithms()) {
    const ParameterAssignments defaults;
    for (const std::vector<Point2>& points : {std::vector<Point2>{}, std::vector<Point2>{{1, 1}}, std::vector<Point2>{{1, 1}, {2, 2}}}) {
      EXPECT_THROW(algorithm->reconstruct(points, defaults), InputError) << algorithm->name() << " with " << points.size() << " points";
    }
    const std::vector<Point2> line{{0, 0}, {1, 1}, {2, 2}};
    if (algorithm->info().collinear == CollinearInput::kRefused) {
      EXPECT_THROW(algorithm->reconstruct(line, defaults), InputError) << algorithm->name() << " on a line";
    } else {
      EXPECT_NO_THROW(algorithm->reconstruct(line, defaults)) << algorithm->name() << " on a line";
    }
  }
}

// The methods whose specifications say what they make of collinear samples are given them:
// Crawl's chain and HNN-crust's neighbour edges run along the line, FitConnect's fits (and
// StretchDenoise's pass 1) link evenly spaced samples along it as the authors' code does, and
// Peel has no triangle to peel. The others refuse, since the sites bound no closed curve.
TEST(DegenerateInputs, CollinearSamplesAreAnOpenCurveToTheMethodsThatDefineOne) {
  std::vector<int> order(15);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(5));
  std::vector<Point2> line(order.size());  // sample order[k] is the k-th along the line
  for (std::size_t k = 0; k < order.size(); ++k) line[order[k]] = {3.0 - 0.5 * k, 1.0 + 0.25 * k};
  std::vector<Edge> path;
  for (std::size_t k = 1; k < order.size(); ++k) path.push_back(make_edge(order[k - 1], order[k]));
  std::sort(path.begin(), path.end());
  const ParameterAssignments defaults;
  auto edges = [&](const std::string& name) {
    std::vector<Edge> e = *find_algorithm(name).reconstruct(line, defaults).curve_edges;
    std::sort(e.begin(), e.end());
    return e;
  };
  EXPECT_EQ(edges("crawl"), path);
  EXPECT_EQ(edges("hnn-crust"), path);
  EXPECT_EQ(edges("fitconnect"), path);
  EXPECT_EQ(edges("stretchdenoise"), path);
  EXPECT_TRUE(edges("peel").empty());
  // A line's fits tend to the line itself: FitConnect's blend leaves the samples on it.
  EXPECT_EQ(*find_algorithm("fitconnect").reconstruct(line, defaults).moved_points, line);
  for (const std::string name : {"labeling", "labeling-holes", "crust", "nn-crust", "shape-hull"}) {
    try {
      find_algorithm(name).reconstruct(line, defaults);
      ADD_FAILURE() << name << " reconstructed collinear samples";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), name + ": all 15 distinct points are collinear, so they bound no closed curve");
    }
  }
}

// Well-separated samples of the rose at `count` jittered parameters, in order along it.
std::vector<Point2> jittered_rose(int count) {
  std::vector<Point2> points;
  std::mt19937_64 rng(11);
  for (int k = 0; k < count; ++k) {
    points.push_back(testing::rose_point(2 * std::numbers::pi * (k + 0.3 * static_cast<double>(rng() >> 11) * 0x1.0p-53) / count));
  }
  return points;
}

// Scaling by 1e6 or 1e-6 or translating by 1e6 must not change the output edges on
// well-separated samples: no decision may rest on an absolute length.
TEST(DegenerateInputs, ScalingAndTranslationByAMillionKeepEveryAlgorithmsEdges) {
  const auto points = jittered_rose(120);
  for (const Algorithm* algorithm : all_algorithms()) {
    if (!(algorithm->info().outputs & kCurve)) continue;
    const ParameterAssignments defaults;
    const auto reference = algorithm->reconstruct(points, defaults);
    if (!reference.curve_edges) continue;  // new vertices move with the input; compared by the metrics instead
    struct Move {
      const char* name;
      double scale;
      Point2 offset;
    };
    for (const Move& move : {Move{"scaled by 1e6", 1e6, {0, 0}}, Move{"scaled by 1e-6", 1e-6, {0, 0}},
                             Move{"translated", 1, {1e6, 1e6}}}) {
      std::vector<Point2> moved;
      for (const auto& p : points) moved.push_back(move.scale * p + move.offset);
      const auto result = algorithm->reconstruct(moved, defaults);
      EXPECT_EQ(testing::sorted(*result.curve_edges), testing::sorted(*reference.curve_edges))
          << algorithm->name() << " " << move.name;
    }
  }
}

// The order of the points must not change the edges, read back in input indices: the Voronoi
// layer keeps points in curve order as they come and renumbers shuffled ones in Z order.
TEST(DegenerateInputs, ShufflingThePointsKeepsEveryAlgorithmsEdges) {
  const auto points = jittered_rose(2000);
  const auto order = testing::random_order(2000, 12);  // shuffled[i] = points[order[i]]
  std::vector<Point2> shuffled;
  for (int i : order) shuffled.push_back(points[i]);
  for (const Algorithm* algorithm : all_algorithms()) {
    if (!(algorithm->info().outputs & kCurve)) continue;
    const ParameterAssignments defaults;
    const auto reference = algorithm->reconstruct(points, defaults);
    if (!reference.curve_edges) continue;  // new vertices: compared by the metrics instead
    const auto result = algorithm->reconstruct(shuffled, defaults);
    std::vector<Edge> edges;
    for (const auto& e : *result.curve_edges) edges.push_back(make_edge(order[e[0]], order[e[1]]));
    EXPECT_EQ(testing::sorted(edges), testing::sorted(*reference.curve_edges)) << algorithm->name();
  }
}

}  // namespace
}  // namespace curvebench
