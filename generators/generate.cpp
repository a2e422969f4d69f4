#include "generators/generate.h"

#include <algorithm>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "generators/dominant_points.h"
#include "generators/medial_axis.h"
#include "generators/outline_import.h"
#include "generators/random.h"
#include "generators/samplers.h"

namespace curvebench {
namespace {

void check_settings(const GeneratorSettings& s) {
  if (s.noise < 0) throw std::runtime_error("--noise: must be >= 0");
  if (s.outliers < 0) throw std::runtime_error("--outliers: must be >= 0 (a fraction of the curve samples)");
  if (s.noise_scale != "lfs" && s.noise_scale != "diagonal") throw std::runtime_error("--noise-scale: must be 'lfs' or 'diagonal'");
  if (s.noise_model != "gaussian" && s.noise_model != "uniform") throw std::runtime_error("--noise-model: must be 'gaussian' or 'uniform'");
  if (s.sampler == "epsilon") {
    if (s.epsilon <= 0) throw std::runtime_error("--epsilon: must be > 0");
    if (s.min_step_fraction <= 0 || s.min_step_fraction > 1) throw std::runtime_error("--min-step-fraction: must be in (0, 1]");
  } else if (s.sampler != "uniform" && s.sampler != "random") {
    throw std::runtime_error("--sampler: must be 'epsilon', 'uniform' or 'random'");
  }
}

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

bool has_extension(const std::string& path, std::initializer_list<std::string_view> extensions) {
  return std::any_of(extensions.begin(), extensions.end(), [&](std::string_view e) { return path.ends_with(e); });
}

// The outline family: closed polygons read from the input file, densified with corners kept.
Scene outline_scene(const GeneratorSettings& s) {
  if (s.input.empty()) throw std::runtime_error("--family outline needs --input FILE (rings text, GeoJSON or SVG)");
  std::string format = s.input_format;
  if (format == "auto") {
    format = has_extension(s.input, {".geojson", ".json"}) ? "geojson" : has_extension(s.input, {".svg", ".path"}) ? "svg" : "rings";
  }
  const std::string text = read_text_file(s.input);
  Rings rings;
  if (format == "rings") rings = parse_rings_text(text, s.input);
  else if (format == "geojson") rings = parse_geojson(text, s.input);
  else if (format == "svg") rings = parse_svg_paths(text, s.input);
  else throw std::runtime_error("--input-format: must be auto, rings, geojson or svg");
  return polygon_scene(s.input, rings, s.dense);
}

GroundTruth ground_truth_of(const Scene& scene, const SampledScene& samples, const MedialAxis& medial_axis,
                            nlohmann::ordered_json record) {
  GroundTruth truth;
  truth.generator = std::move(record);
  for (const auto& curve : scene.curves) truth.curves.push_back({curve.points, curve.lfs, curve.closed});
  for (size_t i = 0; i < samples.points.size(); ++i) {
    GroundTruthSample sample;
    if (samples.curve[i] >= 0) sample = {samples.curve[i], samples.parameter[i], samples.lfs[i]};
    truth.samples.push_back(sample);
  }
  truth.edges = samples.true_edges;
  truth.medial_axis = {medial_axis.vertices, medial_axis.edges};
  truth.dominant_points = true_dominant_points(scene);
  return truth;
}

}  // namespace

GeneratedInput generate(const GeneratorSettings& settings) {
  nlohmann::ordered_json record = generator_settings_to_json(settings);
  check_settings(settings);
  const bool outline = settings.family == "outline";
  const CurveFamily* family = outline ? nullptr : &find_curve_family(settings.family);
  const ShapeValues shape = outline ? ShapeValues{} : resolve_shape(*family, settings.shape);
  const Scene scene = outline ? outline_scene(settings) : family->build(shape, settings.seed, settings.dense);
  // One seed drives everything; each stage draws from its own derived stream.
  const std::uint64_t seed = settings.seed;
  SampledScene samples = settings.sampler == "epsilon"
                             ? epsilon_sample(scene, settings.epsilon, derive_seed(seed, 1), settings.min_step_fraction)
                             : arc_length_sample(scene, settings.count, settings.sampler == "random", derive_seed(seed, 1));
  if (settings.noise > 0) {
    const NoiseScale scale = settings.noise_scale == "lfs" ? NoiseScale::local_feature_size : NoiseScale::bounding_box_diagonal;
    const NoiseModel model = settings.noise_model == "gaussian" ? NoiseModel::gaussian : NoiseModel::uniform;
    add_normal_noise(scene, samples, settings.noise, scale, derive_seed(seed, 2), model);
  }
  if (settings.outliers > 0) add_outliers(scene, samples, settings.outliers, derive_seed(seed, 3));
  const bool open = std::any_of(scene.curves.begin(), scene.curves.end(), [](const DenseCurve& c) { return !c.closed; });
  // Open curves bound no region, so there is no interior medial axis.
  const MedialAxis medial_axis = open ? MedialAxis{}
                                 : family && family->exact_medial_axis ? family->exact_medial_axis(shape)
                                                                       : interior_medial_axis(scene);
  return {samples.points, ground_truth_of(scene, samples, medial_axis, std::move(record))};
}

}  // namespace curvebench
