// The generator library: the family table, settings from text and JSON, their record, and
// generate() composing family, sampler, noise and outliers from one seed.
#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>

#include "generators/families.h"
#include "generators/generate.h"
#include "generators/random.h"
#include "generators/samplers.h"

namespace curvebench {
namespace {

std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(FamilyTable, EveryFamilyBuildsWithItsDefaults) {
  for (const CurveFamily& family : curve_families()) {
    const Scene scene = family.build(resolve_shape(family, {}), 3, 256);
    EXPECT_FALSE(scene.curves.empty()) << family.name;
    EXPECT_EQ(&find_curve_family(family.name), &family);
  }
}

TEST(FamilyTable, ShapeValuesResolveAgainstDefaults) {
  const ShapeValues rose = resolve_shape(find_curve_family("rose"), {{"k", 7}});
  EXPECT_EQ(rose, (ShapeValues{{"a", 1}, {"b", 0.3}, {"k", 7}}));
  EXPECT_EQ(curve_family_scene("rose", {}, 0, 512).curves[0].points, rose_scene(1, 0.3, 5, 512).curves[0].points);
  EXPECT_NE(error_of([] { resolve_shape(find_curve_family("rose"), {{"q", 1}}); }).find("one of: a, b, k"), std::string::npos);
  EXPECT_NE(error_of([] { resolve_shape(find_curve_family("rose"), {{"k", 2.5}}); }).find("'2.5' is not an integer"), std::string::npos);
  EXPECT_NE(error_of([] { find_curve_family("blob"); }).find("known: circle, ellipse"), std::string::npos);
}

TEST(GeneratorSettings, JsonKeysAreTheFieldNames) {
  const GeneratorSettings s = generator_settings_from_json(
      nlohmann::ordered_json::parse(R"({"family": "star", "shape": {"points": 4}, "sampler": "random", "count": 50,
                                        "noise": 0.1, "noise_scale": "diagonal", "outliers": 0.2, "dense": 1024, "seed": 7})"));
  EXPECT_EQ(s.family, "star");
  EXPECT_EQ(s.shape, (ShapeValues{{"points", 4}}));
  EXPECT_EQ(s.sampler, "random");
  EXPECT_EQ(s.count, 50);
  EXPECT_EQ(s.noise, 0.1);
  EXPECT_EQ(s.noise_scale, "diagonal");
  EXPECT_EQ(s.outliers, 0.2);
  EXPECT_EQ(s.dense, 1024);
  EXPECT_EQ(s.seed, 7u);
  EXPECT_NE(error_of([] { generator_settings_from_json({{"colour", 1}}); }).find("unknown generator setting 'colour'"), std::string::npos);
  EXPECT_EQ(error_of([] { generator_settings_from_json({{"dense", 8}}); }), "--dense: '8' is not an integer in [16, 16777216]");
}

TEST(GeneratorSettings, RecordResolvesTheShapeAndKeepsTheSamplersOwnSettings) {
  GeneratorSettings s;
  s.family = "rose";
  const auto record = generator_settings_to_json(s);
  EXPECT_EQ(record.dump(),
            R"({"family":"rose","shape":{"a":1.0,"b":0.3,"k":5},"dense":8192,"sampler":"epsilon","epsilon":0.2,)"
            R"("min_step_fraction":0.5,"noise":0.0,"noise_scale":"lfs","outliers":0.0,"seed":1})");
  s.noise_model = "uniform";  // recorded only when not the default, after noise_scale
  EXPECT_NE(generator_settings_to_json(s).dump().find(R"("noise_scale":"lfs","noise_model":"uniform","outliers")"), std::string::npos);
  s.sampler = "uniform";
  EXPECT_FALSE(generator_settings_to_json(s).contains("epsilon"));
  EXPECT_EQ(generator_settings_to_json(s)["count"], 200);
}

TEST(Generate, ComposesFamilySamplerNoiseAndOutliersFromOneSeed) {
  GeneratorSettings s;
  s.family = "ellipse";
  s.epsilon = 0.3;
  s.dense = 1024;
  s.seed = 4;
  s.outliers = 0.25;
  const GeneratedInput input = generate(s);
  const Scene scene = ellipse_scene(2, 1, 1024);
  SampledScene expected = epsilon_sample(scene, 0.3, derive_seed(4, 1));
  add_outliers(scene, expected, 0.25, derive_seed(4, 3));
  EXPECT_EQ(input.points, expected.points);
  EXPECT_EQ(input.truth.edges, expected.true_edges);
  ASSERT_EQ(input.truth.samples.size(), input.points.size());
  EXPECT_TRUE(input.truth.samples.back().is_outlier());
  EXPECT_EQ(input.truth.generator, generator_settings_to_json(s));
  EXPECT_FALSE(input.truth.medial_axis.edges.empty());  // the ellipse's exact axis
  EXPECT_EQ(generate(s).points, input.points);
}

TEST(Generate, RejectsSettingsOutOfRange) {
  GeneratorSettings s;
  s.sampler = "grid";
  EXPECT_EQ(error_of([&] { generate(s); }), "--sampler: must be 'epsilon', 'uniform' or 'random'");
  s = {};
  s.noise = -1;
  EXPECT_EQ(error_of([&] { generate(s); }), "--noise: must be >= 0");
  s = {};
  s.noise_model = "laplace";
  EXPECT_EQ(error_of([&] { generate(s); }), "--noise-model: must be 'gaussian' or 'uniform'");
  s = {};
  s.family = "outline";
  EXPECT_NE(error_of([&] { generate(s); }).find("needs --input"), std::string::npos);
}

}  // namespace
}  // namespace curvebench
