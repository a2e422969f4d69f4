#include "io/parameters_json.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace curvebench {

ParameterValue parameter_from_json(const nlohmann::json& value, const std::string& where) {
  if (value.is_boolean()) return value.get<bool>();
  if (value.is_number_integer()) return value.get<std::int64_t>();
  if (value.is_number()) return value.get<double>();
  if (value.is_string()) return value.get<std::string>();
  throw std::runtime_error(where + " must be a number, a boolean or a name, not " + value.dump());
}

std::map<std::string, ParameterValue> parameters_from_json(const nlohmann::json& object, const std::string& where) {
  if (!object.is_object()) throw std::runtime_error(where + " must be an object of name: value");
  std::map<std::string, ParameterValue> values;
  for (const auto& [name, value] : object.items()) values[name] = parameter_from_json(value, where + "." + name);
  return values;
}

nlohmann::ordered_json parameter_to_json(const ParameterValue& value) {
  return std::visit([](const auto& v) { return nlohmann::ordered_json(v); }, value);
}

nlohmann::ordered_json parameters_to_json(const ParameterValues& values) {
  auto json = nlohmann::ordered_json::object();
  for (const auto& [name, value] : values.all()) json[name] = parameter_to_json(value);
  return json;
}

namespace {

constexpr std::pair<Output, const char*> kOutputNames[] = {{kCurve, "curve"},
                                                          {kNewCurve, "new_curve"},
                                                          {kMovedPoints, "moved_points"},
                                                          {kMedialAxis, "medial_axis"},
                                                          {kDominantPoints, "dominant_points"}};

}  // namespace

std::vector<std::string> output_names(unsigned outputs) {
  std::vector<std::string> list;
  for (const auto& [bit, name] : kOutputNames) {
    if (outputs & bit) list.emplace_back(name);
  }
  return list;
}

unsigned outputs_from_names(const nlohmann::json& names, const std::string& where) {
  std::string known;
  for (const auto& [bit, name] : kOutputNames) known += (known.empty() ? "" : ", ") + std::string(name);
  if (!names.is_array() || names.empty()) throw std::runtime_error(where + " must be a non-empty list of: " + known);
  unsigned outputs = 0;
  for (const auto& given : names) {
    unsigned bit_of_name = 0;
    for (const auto& [bit, name] : kOutputNames) {
      if (given.is_string() && given.get<std::string>() == name) bit_of_name = bit;
    }
    if (bit_of_name == 0) throw std::runtime_error(where + ": " + given.dump() + " is not one of: " + known);
    outputs |= bit_of_name;
  }
  return outputs;
}

ParameterSpec parameter_spec_from_json(const nlohmann::json& json, const std::string& where) {
  if (!json.is_object()) throw std::runtime_error(where + " must be an object with name, type, default and description");
  auto text = [&](const char* key) {
    if (!json.contains(key) || !json.at(key).is_string() || json.at(key).get<std::string>().empty()) {
      throw std::runtime_error(where + "." + key + " must be a non-empty string");
    }
    return json.at(key).get<std::string>();
  };
  const std::string name = text("name");
  const std::string at = where + " (" + name + ")";
  const std::string type = text("type");
  const std::string description = text("description");
  if (!json.contains("default")) throw std::runtime_error(at + " has no default");
  const nlohmann::json& given_default = json.at("default");
  auto bound = [&](const char* key, double none) {
    if (!json.contains(key) || json.at(key).is_null()) return none;
    if (!json.at(key).is_number()) throw std::runtime_error(at + "." + key + " must be a number or null");
    return json.at(key).get<double>();
  };
  const double infinity = std::numeric_limits<double>::infinity();
  ParameterSpec spec;
  if (type == "real" || type == "integer") {
    if (!given_default.is_number() || (type == "integer" && !given_default.is_number_integer())) {
      throw std::runtime_error(at + ".default must be " + (type == "real" ? "a number" : "a whole number"));
    }
    const double minimum = bound("minimum", -infinity);
    const double maximum = bound("maximum", infinity);
    if (json.contains("minimum_exclusive") && !json.at("minimum_exclusive").is_boolean()) {
      throw std::runtime_error(at + ".minimum_exclusive must be true or false");
    }
    if (type == "real") {
      spec = real_parameter(name, given_default.get<double>(), minimum, maximum, description, json.value("minimum_exclusive", false));
    } else {
      spec = integer_parameter(name, given_default.get<std::int64_t>(), 0, 0, description);
      spec.minimum = minimum;  // either bound may be none (infinite), which integer_parameter's integers cannot say
      spec.maximum = maximum;
    }
  } else if (type == "boolean") {
    if (!given_default.is_boolean()) throw std::runtime_error(at + ".default must be true or false");
    spec = boolean_parameter(name, given_default.get<bool>(), description);
  } else if (type == "choice") {
    if (!json.contains("choices") || !json.at("choices").is_array() || json.at("choices").empty() ||
        !std::all_of(json.at("choices").begin(), json.at("choices").end(), [](const auto& c) { return c.is_string(); })) {
      throw std::runtime_error(at + ".choices must be a non-empty list of names");
    }
    if (!given_default.is_string()) throw std::runtime_error(at + ".default must be one of its choices");
    spec = choice_parameter(name, given_default.get<std::string>(), json.at("choices").get<std::vector<std::string>>(), description);
  } else {
    throw std::runtime_error(at + ".type '" + type + "' is not real, integer, boolean or choice");
  }
  try {  // the default must be a value the parameter allows
    resolve_parameters(name, {spec}, {{spec.name, spec.default_value}});
  } catch (const InputError&) {
    throw std::runtime_error(at + ": the default " + value_text(spec.default_value) + " is not " + allowed_values(spec));
  }
  return spec;
}

nlohmann::ordered_json algorithm_catalogue(std::span<const Algorithm* const> algorithms) {
  auto catalogue = nlohmann::ordered_json::array();
  for (const Algorithm* algorithm : algorithms) {
    const AlgorithmInfo& info = algorithm->info();
    nlohmann::ordered_json entry;
    entry["name"] = info.name;
    entry["citation"] = info.citation;
    entry["outputs"] = output_names(info.outputs);
    entry["collinear_input"] = info.collinear == CollinearInput::kReconstructed ? "reconstructed" : "refused";
    entry["parameters"] = nlohmann::ordered_json::array();
    for (const ParameterSpec& spec : info.parameters) {
      nlohmann::ordered_json p;
      p["name"] = spec.name;
      p["type"] = type_name(spec.type);
      p["default"] = parameter_to_json(spec.default_value);
      if (spec.type == ParameterType::kReal || spec.type == ParameterType::kInteger) {
        p["minimum"] = spec.minimum;
        p["minimum_exclusive"] = spec.minimum_exclusive;
        p["maximum"] = std::isfinite(spec.maximum) ? nlohmann::ordered_json(spec.maximum) : nlohmann::ordered_json(nullptr);
      }
      if (spec.type == ParameterType::kChoice) p["choices"] = spec.choices;
      p["allowed"] = allowed_values(spec);
      p["description"] = spec.description;
      entry["parameters"].push_back(std::move(p));
    }
    catalogue.push_back(std::move(entry));
  }
  return catalogue;
}

}  // namespace curvebench
