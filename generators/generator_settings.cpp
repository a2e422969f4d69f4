#include "generators/generator_settings.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace curvebench {
namespace {

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

// A JSON value as the command line would spell it: text as it is, a number as written.
std::string option_text(const nlohmann::ordered_json& value) { return value.is_string() ? value.get<std::string>() : value.dump(); }

}  // namespace

void set_generator_setting(GeneratorSettings& settings, const std::string& name, const std::string& text) {
  std::string option = "--" + name;
  std::replace(option.begin(), option.end(), '_', '-');
  if (name == "family") settings.family = text;
  else if (name == "shape") {
    const size_t eq = text.find('=');
    if (eq == std::string::npos) throw std::runtime_error("--shape '" + text + "': not name=value");
    settings.shape[text.substr(0, eq)] = parse_number("--shape " + text.substr(0, eq), text.substr(eq + 1));
  } else if (name == "sampler") settings.sampler = text;
  else if (name == "epsilon") settings.epsilon = parse_number(option, text);
  else if (name == "min_step_fraction") settings.min_step_fraction = parse_number(option, text);
  else if (name == "count") settings.count = static_cast<int>(parse_integer(option, text, 3, 1 << 28));
  else if (name == "noise") settings.noise = parse_number(option, text);
  else if (name == "noise_scale") settings.noise_scale = text;
  else if (name == "noise_model") settings.noise_model = text;
  else if (name == "outliers") settings.outliers = parse_number(option, text);
  else if (name == "seed") settings.seed = static_cast<std::uint64_t>(parse_integer(option, text, 0, 1LL << 53));
  else if (name == "dense") settings.dense = static_cast<int>(parse_integer(option, text, 16, 1 << 24));
  else if (name == "input") settings.input = text;
  else if (name == "input_format") settings.input_format = text;
  else {
    throw std::runtime_error("unknown generator setting '" + name + "' (known: family, shape, sampler, epsilon, min_step_fraction, "
                             "count, noise, noise_scale, noise_model, outliers, seed, dense, input, input_format)");
  }
}

GeneratorSettings generator_settings_from_json(const nlohmann::ordered_json& json) {
  GeneratorSettings settings;
  for (const auto& [key, value] : json.items()) {
    if (key == "shape" && value.is_object()) {
      for (const auto& [name, v] : value.items()) set_generator_setting(settings, "shape", name + "=" + option_text(v));
    } else {
      set_generator_setting(settings, key, option_text(value));
    }
  }
  return settings;
}

nlohmann::ordered_json generator_settings_to_json(const GeneratorSettings& settings) {
  const bool outline = settings.family == "outline";
  static const CurveFamily outline_family{"outline", "", {}, false, nullptr, nullptr};  // its shape is the file's
  const CurveFamily& family = outline ? outline_family : find_curve_family(settings.family);
  const ShapeValues shape = resolve_shape(family, settings.shape);
  nlohmann::ordered_json record;
  record["family"] = family.name;
  record["shape"] = nlohmann::ordered_json::object();
  for (const auto& p : family.parameters) {
    if (p.integer) record["shape"][p.name] = static_cast<long long>(shape.at(p.name));
    else record["shape"][p.name] = shape.at(p.name);
  }
  if (outline) {
    record["input"] = settings.input;
    record["input_format"] = settings.input_format;
  }
  record["dense"] = settings.dense;
  record["sampler"] = settings.sampler;
  if (settings.sampler == "epsilon") {
    record["epsilon"] = settings.epsilon;
    record["min_step_fraction"] = settings.min_step_fraction;
  } else {
    record["count"] = settings.count;
  }
  record["noise"] = settings.noise;
  record["noise_scale"] = settings.noise_scale;
  if (settings.noise_model != GeneratorSettings{}.noise_model) record["noise_model"] = settings.noise_model;
  record["outliers"] = settings.outliers;
  record["seed"] = settings.seed;
  return record;
}

}  // namespace curvebench
