// The settings of one generated input: everything `curvebench generate` takes apart from
// the files to write. The field names are the sweep configurations' keys and, with `-` for
// `_`, the command line's options.
//
// set_generator_setting: in a field name and its value as text (shape as "name=value", one
//   parameter at a time), out the settings with that field set; throws std::runtime_error
//   "--option: why" for a value that is not a number (an integer in range where one is
//   wanted) or an unknown name.
// generator_settings_from_json: in a JSON object of field names (a sweep input: numbers or
//   text, "shape" an object of name: value), out the settings; the same errors.
// generator_settings_to_json: in settings, out the record that the ground truth and the
//   points file carry: every shape parameter of the family resolved, only the sampler's own
//   settings, "noise_model" only when it is not the default (so records made before it
//   existed stay the same), "seed" last. Throws as resolve_shape (families.h) does.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "generators/families.h"

namespace curvebench {

struct GeneratorSettings {
  std::string family = "random";    // a family of families.h, or "outline" (read from `input`)
  ShapeValues shape;                // shape parameters given; the others take the family's defaults
  std::string sampler = "epsilon";  // epsilon, uniform or random
  double epsilon = 0.2;             // epsilon sampler
  double min_step_fraction = 0.5;   // epsilon sampler: each step is a random fraction in [this, 1] of the largest
  int count = 200;                  // uniform and random samplers
  double noise = 0;                 // noise along the normal, in units of noise_scale
  std::string noise_scale = "lfs";  // lfs or diagonal
  std::string noise_model = "gaussian";  // gaussian (noise is the standard deviation) or uniform (the half-width)
  double outliers = 0;              // a fraction of the curve samples
  std::uint64_t seed = 1;           // the shape (seeded families), the sampler, noise and outliers
  int dense = 8192;                 // dense vertices per curve of the true polyline
  std::string input;                // outline file (rings text, GeoJSON or SVG)
  std::string input_format = "auto";  // auto, rings, geojson or svg
};

void set_generator_setting(GeneratorSettings& settings, const std::string& name, const std::string& text);

GeneratorSettings generator_settings_from_json(const nlohmann::ordered_json& json);

nlohmann::ordered_json generator_settings_to_json(const GeneratorSettings& settings);

}  // namespace curvebench
