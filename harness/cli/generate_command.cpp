// `curvebench generate`: the generator library (generators/generate.h) on the command line:
// its settings as options -> a points file and the ground-truth JSON.
#include <algorithm>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cli/commands.h"
#include "generators/generate.h"
#include "generators/number_text.h"
#include "io/generated_input_files.h"

namespace curvebench {
namespace {

struct GenerateOptions {
  std::vector<std::pair<std::string, CLI::Option*>> settings;  // setting name and its option, in the order of --help
  std::map<std::string, std::string> text;                     // setting name -> the option's value
  std::vector<std::string> shape;                              // name=value
  std::string points;
  std::string truth;
};

void run(const GenerateOptions& o) {
  if (o.points.empty()) throw std::runtime_error("--points: a points file to write is required");
  GeneratorSettings settings;
  for (const auto& [name, option] : o.settings) {
    if (option->count() > 0) set_generator_setting(settings, name, o.text.at(name));
  }
  for (const auto& assignment : o.shape) set_generator_setting(settings, "shape", assignment);
  const GeneratedInput input = generate(settings);
  write_generated_input_files(input, o.points, o.truth);
  const auto outliers = std::count_if(input.truth.samples.begin(), input.truth.samples.end(), [](const auto& s) { return s.is_outlier(); });
  std::cout << "wrote " << input.points.size() << " points (" << outliers << " outliers) of " << input.truth.curves.size()
            << " curve(s) to " << o.points << (o.truth.empty() ? "" : " and the ground truth to " + o.truth) << "\n";
}

std::string family_help() {
  std::ostringstream help;
  help << "Curve family. Families and their --shape parameters (defaults):";
  for (const auto& family : curve_families()) {
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
  const GeneratorSettings defaults;
  // A setting's option; `default_text` is shown in --help (none if empty).
  auto setting = [&](const std::string& name, const std::string& flags, const std::string& help, const std::string& default_text) {
    CLI::Option* option = cmd->add_option(flags, o->text[name], help);
    if (!default_text.empty()) option->default_str(default_text);
    o->settings.emplace_back(name, option);
  };
  setting("family", "--family,-f", family_help(), defaults.family);
  cmd->add_option("--shape", o->shape, "Shape parameter of the family as name=value (repeatable)");
  setting("sampler", "--sampler", "epsilon (Definition 4, random steps), uniform or random (--count points along arc length)",
          defaults.sampler);
  setting("epsilon", "--epsilon,-e", "epsilon of the epsilon-sampler", number_text(defaults.epsilon));
  setting("min_step_fraction", "--min-step-fraction", "each epsilon step is a random fraction in [this, 1] of the largest",
          number_text(defaults.min_step_fraction));
  setting("count", "--count,-n", "number of samples for the uniform and random samplers", number_text(defaults.count));
  setting("noise", "--noise", "noise along the normal, as a multiple of --noise-scale: the standard deviation (gaussian) or the "
                              "half-width w of the band [-w, w] (uniform)",
          number_text(defaults.noise));
  setting("noise_scale", "--noise-scale", "lfs (local feature size at the sample) or diagonal (of the bounding box)", defaults.noise_scale);
  setting("noise_model", "--noise-model", "gaussian or uniform (in the band [-w, w] along the normal, w = noise x scale)",
          defaults.noise_model);
  setting("outliers", "--outliers", "outliers as a fraction of the curve samples, uniform in the box around the shape",
          number_text(defaults.outliers));
  setting("seed", "--seed,-s", "seed of the shape (random families), the sampler, noise and outliers",
          number_text(static_cast<double>(defaults.seed)));
  setting("dense", "--dense", "dense vertices per curve of the true polyline", number_text(defaults.dense));
  setting("input", "--input,-i", "outline file for --family outline: rings text (x y per line, blank line between rings), "
                                 "GeoJSON (Polygon/MultiPolygon) or SVG (path data or <path d=...>)", "");
  setting("input_format", "--input-format", "auto (from the extension: .geojson/.json, .svg/.path, else rings), rings, geojson or svg",
          defaults.input_format);
  cmd->add_option("--points,-o", o->points, "points file to write")->required();
  cmd->add_option("--truth,-t", o->truth, "ground-truth JSON to write");
  cmd->callback([o] { run(*o); });
}

}  // namespace curvebench
