// The ground-truth JSON: round trip, outliers, and one-line errors for malformed files.
#include <gtest/gtest.h>

#include <cmath>

#include "io/ground_truth_json.h"

namespace curvebench {
namespace {

GroundTruth small_truth() {
  GroundTruth truth;
  truth.generator = {{"family", "circle"}, {"epsilon", 0.5}, {"seed", 3}};
  truth.curves.push_back({{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}, {1, 1, 1, 1}});
  truth.samples = {{0, 0.0, 1.0}, {0, 0.3, 1.0}, {0, 0.7, 1.0}, {}};
  truth.edges = {{0, 1}, {0, 2}, {1, 2}};
  truth.medial_axis.vertices = {{0, 0}};
  truth.dominant_points = {{1, 0}};
  return truth;
}

std::string error_of(const nlohmann::ordered_json& json) {
  try {
    ground_truth_from_json(json, "t.json");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(GroundTruthJson, RoundTripKeepsEverything) {
  const GroundTruth truth = small_truth();
  const auto json = ground_truth_to_json(truth);
  EXPECT_EQ(json["format"], "curvebench-ground-truth/1");
  EXPECT_EQ(json["points"], 4);
  EXPECT_EQ(json["samples"][3]["curve"], "outlier");
  EXPECT_EQ(json["generator"]["seed"], 3);
  const GroundTruth back = ground_truth_from_json(nlohmann::ordered_json::parse(json.dump()), "t.json");
  EXPECT_EQ(back.curves[0].vertices, truth.curves[0].vertices);
  EXPECT_EQ(back.curves[0].lfs, truth.curves[0].lfs);
  ASSERT_EQ(back.samples.size(), 4u);
  EXPECT_EQ(back.samples[1].curve, 0);
  EXPECT_EQ(back.samples[1].parameter, 0.3);
  EXPECT_TRUE(back.samples[3].is_outlier());
  EXPECT_TRUE(std::isnan(back.samples[3].parameter));
  EXPECT_EQ(back.edges, truth.edges);
  EXPECT_EQ(back.medial_axis.vertices, truth.medial_axis.vertices);
  EXPECT_EQ(back.dominant_points, truth.dominant_points);
  EXPECT_EQ(back.generator["family"], "circle");
  EXPECT_EQ(ground_truth_to_json(back).dump(), json.dump());
}

TEST(GroundTruthJson, MalformedFilesGiveOneLineErrors) {
  auto json = ground_truth_to_json(small_truth());
  auto wrong_format = json;
  wrong_format["format"] = "something-else";
  EXPECT_NE(error_of(wrong_format).find("not a ground-truth file"), std::string::npos);
  auto bad_edge = json;
  bad_edge["edges"].push_back({0, 9});
  EXPECT_EQ(error_of(bad_edge), "t.json: \"edges\" holds edge [0, 9] out of range");
  auto bad_count = json;
  bad_count["points"] = 5;
  EXPECT_EQ(error_of(bad_count), "t.json: \"points\" does not match the number of samples");
  auto bad_curve = json;
  bad_curve["samples"][0]["curve"] = 4;
  EXPECT_EQ(error_of(bad_curve), "t.json: sample 0: \"curve\" is neither a curve index nor \"outlier\"");
}

}  // namespace
}  // namespace curvebench
