// An algorithm folder is all it takes: tests/algorithms/hull-polygon, compiled only into this
// test executable, is listed, catalogued with its typed parameter, validated, planned by a
// sweep over "all" algorithms and run through the skeleton, with no edit anywhere else.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/registry.h"
#include "io/parameters_json.h"
#include "sweep/sweep_plan.h"
#include "test_support.h"

namespace curvebench {
namespace {

TEST(Registration, ATestOnlyFolderIsListedAndCatalogued) {
  const auto algorithms = all_algorithms();
  EXPECT_TRUE(std::any_of(algorithms.begin(), algorithms.end(), [](const Algorithm* a) { return a->name() == "hull-polygon"; }));
  EXPECT_TRUE(std::is_sorted(algorithms.begin(), algorithms.end(),
                             [](const Algorithm* a, const Algorithm* b) { return a->name() < b->name(); }));
  const auto catalogue = algorithm_catalogue(algorithms);
  const auto entry = std::find_if(catalogue.begin(), catalogue.end(), [](const auto& e) { return e["name"] == "hull-polygon"; });
  ASSERT_NE(entry, catalogue.end());
  EXPECT_EQ((*entry)["outputs"], nlohmann::ordered_json::array({"curve"}));
  const auto& skip = (*entry)["parameters"].at(0);
  EXPECT_EQ(skip["name"], "skip");
  EXPECT_EQ(skip["type"], "integer");
  EXPECT_EQ(skip["default"], 0);
  EXPECT_EQ(skip["minimum"], 0);
  EXPECT_EQ(skip["maximum"], 3);
}

TEST(Registration, TheSkeletonRunsItAndMapsItsEdgesToInputIndices) {
  auto points = testing::uniform_circle(8);
  points.insert(points.begin(), points[5]);  // a duplicate first: input index 0 is site of point 6
  const auto result = find_algorithm("hull-polygon").reconstruct(points, {{"skip", std::int64_t{1}}});
  ASSERT_TRUE(result.curve_edges.has_value());
  EXPECT_EQ(result.curve_edges->size(), 7u);
  EXPECT_EQ(result.distinct_points, 8);
  for (const Edge& e : *result.curve_edges) EXPECT_FALSE(e[0] == 6 || e[1] == 6) << "index 6 is a duplicate of index 0";
  EXPECT_EQ(result.timing_ms.front().first, "delaunay");
  EXPECT_EQ(result.timing_ms.back().first, "total");
}

TEST(Registration, ParametersAreValidatedOnceWithOneLineNamingWhatIsAllowed) {
  const auto& hull = find_algorithm("hull-polygon");
  const auto circle = testing::uniform_circle(6);
  auto message = [&](const ParameterAssignments& given) {
    try {
      hull.reconstruct(circle, given);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({{"skip", std::int64_t{4}}}),
            "algorithm 'hull-polygon': parameter 'skip' must be a whole number >= 0 and <= 3 (got 4)");
  EXPECT_EQ(message({{"skip", 1.5}}),
            "algorithm 'hull-polygon': parameter 'skip' must be a whole number >= 0 and <= 3 (got 1.5)");
  EXPECT_EQ(message({{"skip", std::string("two")}}),
            "algorithm 'hull-polygon': parameter 'skip' must be a whole number >= 0 and <= 3 (got two)");
  EXPECT_EQ(message({{"skips", std::int64_t{1}}}), "algorithm 'hull-polygon' has no parameter 'skips' (it takes: skip)");
  EXPECT_EQ(message({{"skip", std::string("2")}}), "no error") << "text from a command line is converted";
}

TEST(Registration, ASweepOverAllAlgorithmsPlansItAndChecksTheConfigurationFirst) {
  const auto algorithms = all_algorithms();
  const auto plan = plan_sweep(nlohmann::ordered_json::parse(R"({"algorithms": "all", "inputs": [{"family": "circle"}]})"),
                               algorithms);
  EXPECT_TRUE(std::any_of(plan.runs.begin(), plan.runs.end(), [](const SweepRun& r) { return r.algorithm == "hull-polygon"; }));
  EXPECT_THROW(plan_sweep(nlohmann::ordered_json::parse(
                              R"({"algorithms": [{"name": "hull-polygon", "parameters": {"skip": [0, 9]}}], "inputs": [{"family": "circle"}]})"),
                          algorithms),
               std::runtime_error);
  EXPECT_THROW(plan_sweep(nlohmann::ordered_json::parse(R"({"algorithms": ["hull-polygn"], "inputs": [{"family": "circle"}]})"),
                          algorithms),
               std::runtime_error);
}

}  // namespace
}  // namespace curvebench
