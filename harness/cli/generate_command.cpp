// `curvebench generate`: a curve family (or an imported outline), a sampler, noise and
// outliers, all from one seed -> a points file and the ground-truth JSON.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "cli/commands.h"
#include "generators/closed_curves.h"
#include "generators/dominant_points.h"
#include "generators/medial_axis.h"
#include "generators/outline_import.h"
#include "generators/random.h"
#include "generators/samplers.h"
#include "io/ground_truth_json.h"
#include "io/points_file.h"

namespace curvebench {
namespace {

using ShapeParameters = std::map<std::string, double>;

struct ShapeParameter {
  std::string name;
  double default_value;
  bool integer;
};

struct Family {
  std::string name;
  std::string description;
  std::vector<ShapeParameter> parameters;
  bool seeded;  // the shape itself depends on --seed
  std::function<Scene(const ShapeParameters&, std::uint64_t seed, int dense)> build;
  std::function<MedialAxis(const ShapeParameters&)> exact_medial_axis;  // empty if none is known
};

const std::vector<Family>& families() {
  static const std::vector<Family> all = {
      {"circle", "circle of the given radius", {{"radius", 1, false}}, false,
       [](const ShapeParameters& p, std::uint64_t, int dense) { return circle_scene(p.at("radius"), dense); },
       [](const ShapeParameters& p) { return circle_medial_axis({0, 0}, p.at("radius")); }},
      {"ellipse", "ellipse with semi-axes a, b", {{"a", 2, false}, {"b", 1, false}}, false,
       [](const ShapeParameters& p, std::uint64_t, int dense) { return ellipse_scene(p.at("a"), p.at("b"), dense); },
       [](const ShapeParameters& p) { return ellipse_medial_axis(p.at("a"), p.at("b")); }},
      {"superellipse", "|x/a|^exponent + |y/b|^exponent = 1 (a rounded square for exponent > 2)",
       {{"a", 1, false}, {"b", 1, false}, {"exponent", 4, false}}, false,
       [](const ShapeParameters& p, std::uint64_t, int dense) { return superellipse_scene(p.at("a"), p.at("b"), p.at("exponent"), dense); },
       nullptr},
      {"rose", "r = a + b cos(k t)", {{"a", 1, false}, {"b", 0.3, false}, {"k", 5, true}}, false,
       [](const ShapeParameters& p, std::uint64_t, int dense) {
         return rose_scene(p.at("a"), p.at("b"), static_cast<int>(p.at("k")), dense);
       },
       nullptr},
      {"random", "random smooth curve r(t) = 1 + random decaying harmonics", {}, true,
       [](const ShapeParameters&, std::uint64_t seed, int dense) { return random_fourier_scene(seed, dense); }, nullptr},
      {"dumbbell", "two lobes joined by a thin neck of the given half-width (Cassini oval)", {{"neck", 0.2, false}}, false,
       [](const ShapeParameters& p, std::uint64_t, int dense) { return dumbbell_scene(p.at("neck"), dense); }, nullptr},
      {"concavities", "unit circle with `count` deep narrow slots", {{"count", 5, true}, {"depth", 0.7, false}, {"width", 0.08, false}},
       false,
       [](const ShapeParameters& p, std::uint64_t, int dense) {
         return concavities_scene(static_cast<int>(p.at("count")), p.at("depth"), p.at("width"), dense);
       },
       nullptr},
      {"disjoint", "2-5 disjoint random smooth curves", {{"count", 3, true}}, true,
       [](const ShapeParameters& p, std::uint64_t seed, int dense) {
         return disjoint_curves_scene(static_cast<int>(p.at("count")), seed, dense);
       },
       nullptr},
      {"nested", "a random smooth curve with a smaller one inside it", {}, true,
       [](const ShapeParameters&, std::uint64_t seed, int dense) { return nested_curves_scene(seed, dense); }, nullptr},
      {"star", "star polygon with `points` tips, inner radius = inner_ratio", {{"points", 5, true}, {"inner_ratio", 0.45, false}}, false,
       [](const ShapeParameters& p, std::uint64_t, int dense) {
         return star_scene(static_cast<int>(p.at("points")), p.at("inner_ratio"), dense);
       },
       nullptr},
      {"square", "square of the given side", {{"side", 2, false}}, false,
       [](const ShapeParameters& p, std::uint64_t, int dense) { return square_scene(p.at("side"), dense); }, nullptr},
      {"l-shape", "L in the 2x2 square with arms of the given width", {{"arm_width", 0.6, false}}, false,
       [](const ShapeParameters& p, std::uint64_t, int dense) { return l_shape_scene(p.at("arm_width"), dense); }, nullptr},
      {"horned", "crescent: unit disc minus a disc (inner_radius, centre (offset, 0)); two horn tips",
       {{"inner_radius", 0.8, false}, {"offset", 0.5, false}}, false,
       [](const ShapeParameters& p, std::uint64_t, int dense) { return horned_scene(p.at("inner_radius"), p.at("offset"), dense); },
       nullptr},
  };
  return all;
}

struct GenerateOptions {
  std::string family = "random";
  std::vector<std::string> shape;  // name=value
  std::string sampler = "epsilon";
  std::string epsilon = "0.2";
  std::string min_step_fraction = "0.5";
  std::string count = "200";
  std::string noise = "0";
  std::string noise_scale = "lfs";
  std::string outliers = "0";
  std::string seed = "1";
  std::string dense = "8192";
  std::string input;
  std::string input_format = "auto";
  std::string points;
  std::string truth;
};

double parse_number(const std::string& option, const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(value)) {
    throw std::runtime_error(option + ": '" + text + "' is not a number");
  }
  return value;
}

long long parse_integer(const std::string& option, const std::string& text, long long low, long long high) {
  const double value = parse_number(option, text);
  if (value != std::floor(value) || value < low || value > high) {
    throw std::runtime_error(option + ": '" + text + "' is not an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
  }
  return static_cast<long long>(value);
}

const Family& find_family(const std::string& name) {
  for (const auto& family : families()) {
    if (family.name == name) return family;
  }
  std::string known;
  for (const auto& family : families()) known += (known.empty() ? "" : ", ") + family.name;
  throw std::runtime_error("--family: unknown family '" + name + "' (known: " + known + ", outline)");
}

ShapeParameters resolve_shape(const Family& family, const std::vector<std::string>& assignments) {
  ShapeParameters values;
  for (const auto& p : family.parameters) values[p.name] = p.default_value;
  for (const auto& assignment : assignments) {
    const size_t eq = assignment.find('=');
    const std::string name = assignment.substr(0, eq);
    const auto known = std::find_if(family.parameters.begin(), family.parameters.end(), [&](const auto& p) { return p.name == name; });
    if (eq == std::string::npos || known == family.parameters.end()) {
      std::string names;
      for (const auto& p : family.parameters) names += (names.empty() ? "" : ", ") + p.name;
      throw std::runtime_error("--shape '" + assignment + "': family " + family.name + " takes " + (names.empty() ? "no shape parameters" : "name=value with name one of: " + names));
    }
    const std::string option = "--shape " + name;
    values[name] = known->integer ? static_cast<double>(parse_integer(option, assignment.substr(eq + 1), 1, 1 << 20))
                                  : parse_number(option, assignment.substr(eq + 1));
  }
  return values;
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

// The outline family: closed polygons read from --input, densified with corners kept.
Scene outline_scene(const GenerateOptions& o, int dense) {
  if (o.input.empty()) throw std::runtime_error("--family outline needs --input FILE (rings text, GeoJSON or SVG)");
  std::string format = o.input_format;
  if (format == "auto") {
    format = has_extension(o.input, {".geojson", ".json"}) ? "geojson" : has_extension(o.input, {".svg", ".path"}) ? "svg" : "rings";
  }
  const std::string text = read_text_file(o.input);
  Rings rings;
  if (format == "rings") rings = parse_rings_text(text, o.input);
  else if (format == "geojson") rings = parse_geojson(text, o.input);
  else if (format == "svg") rings = parse_svg_paths(text, o.input);
  else throw std::runtime_error("--input-format: must be auto, rings, geojson or svg");
  return polygon_scene(o.input, rings, dense);
}

GroundTruth make_ground_truth(const Scene& scene, const SampledScene& samples, const MedialAxis& medial_axis,
                              nlohmann::ordered_json generator) {
  GroundTruth truth;
  truth.generator = std::move(generator);
  for (const auto& curve : scene.curves) truth.curves.push_back({curve.points, curve.lfs});
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

void run(const GenerateOptions& o) {
  if (o.points.empty()) throw std::runtime_error("--points: a points file to write is required");
  const bool outline = o.family == "outline";
  static const Family outline_family{"outline", "", {}, false, nullptr, nullptr};
  const Family& family = outline ? outline_family : find_family(o.family);
  const ShapeParameters shape = resolve_shape(family, o.shape);
  const auto seed = static_cast<std::uint64_t>(parse_integer("--seed", o.seed, 0, (1LL << 53)));
  const int dense = static_cast<int>(parse_integer("--dense", o.dense, 16, 1 << 24));
  const double noise = parse_number("--noise", o.noise);
  const double outliers = parse_number("--outliers", o.outliers);
  if (noise < 0) throw std::runtime_error("--noise: must be >= 0");
  if (outliers < 0) throw std::runtime_error("--outliers: must be >= 0 (a fraction of the curve samples)");
  if (o.noise_scale != "lfs" && o.noise_scale != "diagonal") throw std::runtime_error("--noise-scale: must be 'lfs' or 'diagonal'");

  nlohmann::ordered_json generator;
  generator["family"] = family.name;
  generator["shape"] = nlohmann::ordered_json::object();
  for (const auto& p : family.parameters) {
    if (p.integer) generator["shape"][p.name] = static_cast<long long>(shape.at(p.name));
    else generator["shape"][p.name] = shape.at(p.name);
  }
  if (outline) {
    generator["input"] = o.input;
    generator["input_format"] = o.input_format;
  }
  generator["dense"] = dense;
  generator["sampler"] = o.sampler;
  double epsilon = 0, min_step_fraction = 0;
  int count = 0;
  if (o.sampler == "epsilon") {
    epsilon = parse_number("--epsilon", o.epsilon);
    min_step_fraction = parse_number("--min-step-fraction", o.min_step_fraction);
    if (epsilon <= 0) throw std::runtime_error("--epsilon: must be > 0");
    if (min_step_fraction <= 0 || min_step_fraction > 1) throw std::runtime_error("--min-step-fraction: must be in (0, 1]");
    generator["epsilon"] = epsilon;
    generator["min_step_fraction"] = min_step_fraction;
  } else if (o.sampler == "uniform" || o.sampler == "random") {
    count = static_cast<int>(parse_integer("--count", o.count, 3, 1 << 28));
    generator["count"] = count;
  } else {
    throw std::runtime_error("--sampler: must be 'epsilon', 'uniform' or 'random'");
  }
  generator["noise"] = noise;
  generator["noise_scale"] = o.noise_scale;
  generator["outliers"] = outliers;
  generator["seed"] = seed;

  const Scene scene = outline ? outline_scene(o, dense) : family.build(shape, seed, dense);
  // One seed drives everything; each stage draws from its own derived stream.
  SampledScene samples = o.sampler == "epsilon" ? epsilon_sample(scene, epsilon, derive_seed(seed, 1), min_step_fraction)
                                                : arc_length_sample(scene, count, o.sampler == "random", derive_seed(seed, 1));
  if (noise > 0) {
    add_normal_noise(scene, samples, noise, o.noise_scale == "lfs" ? NoiseScale::local_feature_size : NoiseScale::bounding_box_diagonal,
                     derive_seed(seed, 2));
  }
  if (outliers > 0) add_outliers(scene, samples, outliers, derive_seed(seed, 3));
  // Everything is computed before anything is written, so a bad setting leaves no file.
  std::string truth_text;
  if (!o.truth.empty()) {
    const MedialAxis medial_axis = family.exact_medial_axis ? family.exact_medial_axis(shape) : interior_medial_axis(scene);
    truth_text = ground_truth_to_json(make_ground_truth(scene, samples, medial_axis, generator)).dump() + "\n";
  }
  write_points_file(o.points, samples.points, "curvebench generate " + generator.dump());
  if (!o.truth.empty()) write_file_atomically(o.truth, truth_text);
  const auto outlier_count = std::count(samples.curve.begin(), samples.curve.end(), -1);
  std::cout << "wrote " << samples.points.size() << " points (" << outlier_count << " outliers) of " << scene.curves.size()
            << " curve(s) to " << o.points << (o.truth.empty() ? "" : " and the ground truth to " + o.truth) << "\n";
}

std::string family_help() {
  std::ostringstream help;
  help << "Curve family. Families and their --shape parameters (defaults):";
  for (const auto& family : families()) {
    help << "\n  " << family.name << ": " << family.description;
    for (const auto& p : family.parameters) help << "; " << p.name << "=" << p.default_value;
    if (family.seeded) help << " (shape from --seed)";
  }
  help << "\n  outline: closed polygons read from --input (holes kept, corners where they turn > 10 degrees)";
  return help.str();
}

}  // namespace

void add_generate_command(CLI::App& app) {
  auto o = std::make_shared<GenerateOptions>();
  auto* cmd = app.add_subcommand("generate", "Generate a sampled curve: points file and ground-truth JSON");
  cmd->add_option("--family,-f", o->family, family_help())->capture_default_str();
  cmd->add_option("--shape", o->shape, "Shape parameter of the family as name=value (repeatable)");
  cmd->add_option("--sampler", o->sampler, "epsilon (Definition 4, random steps), uniform or random (--count points along arc length)")
      ->capture_default_str();
  cmd->add_option("--epsilon,-e", o->epsilon, "epsilon of the epsilon-sampler")->capture_default_str();
  cmd->add_option("--min-step-fraction", o->min_step_fraction, "each epsilon step is a random fraction in [this, 1] of the largest")
      ->capture_default_str();
  cmd->add_option("--count,-n", o->count, "number of samples for the uniform and random samplers")->capture_default_str();
  cmd->add_option("--noise", o->noise, "Gaussian noise along the normal: standard deviation as a multiple of --noise-scale")
      ->capture_default_str();
  cmd->add_option("--noise-scale", o->noise_scale, "lfs (local feature size at the sample) or diagonal (of the bounding box)")
      ->capture_default_str();
  cmd->add_option("--outliers", o->outliers, "outliers as a fraction of the curve samples, uniform in the box around the shape")
      ->capture_default_str();
  cmd->add_option("--seed,-s", o->seed, "seed of the shape (random families), the sampler, noise and outliers")->capture_default_str();
  cmd->add_option("--dense", o->dense, "dense vertices per curve of the true polyline")->capture_default_str();
  cmd->add_option("--input,-i", o->input, "outline file for --family outline: rings text (x y per line, blank line between rings), "
                                         "GeoJSON (Polygon/MultiPolygon) or SVG (path data or <path d=...>)");
  cmd->add_option("--input-format", o->input_format, "auto (from the extension: .geojson/.json, .svg/.path, else rings), "
                                                     "rings, geojson or svg")->capture_default_str();
  cmd->add_option("--points,-o", o->points, "points file to write")->required();
  cmd->add_option("--truth,-t", o->truth, "ground-truth JSON to write");
  cmd->callback([o] { run(*o); });
}

}  // namespace curvebench
