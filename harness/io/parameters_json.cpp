#include "io/parameters_json.h"

#include <cmath>
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

std::vector<std::string> output_names(unsigned outputs) {
  static const std::pair<Output, const char*> names[] = {{kCurve, "curve"},
                                                         {kNewCurve, "new_curve"},
                                                         {kMovedPoints, "moved_points"},
                                                         {kMedialAxis, "medial_axis"},
                                                         {kDominantPoints, "dominant_points"}};
  std::vector<std::string> list;
  for (const auto& [bit, name] : names) {
    if (outputs & bit) list.emplace_back(name);
  }
  return list;
}

nlohmann::ordered_json algorithm_catalogue(std::span<const Algorithm* const> algorithms) {
  auto catalogue = nlohmann::ordered_json::array();
  for (const Algorithm* algorithm : algorithms) {
    const AlgorithmInfo& info = algorithm->info();
    nlohmann::ordered_json entry;
    entry["name"] = info.name;
    entry["citation"] = info.citation;
    entry["outputs"] = output_names(info.outputs);
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
