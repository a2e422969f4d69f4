// Algorithm parameters and the catalogue of algorithms as JSON.
//
// parameter_from_json: a JSON number, boolean or string as a ParameterValue (integers stay
//   integers); throws std::runtime_error naming `where` for anything else.
// parameters_to_json: resolved values as a JSON object, each in its declared type.
// algorithm_catalogue: what `curvebench list --json` prints: for each algorithm its name,
//   citation, outputs and parameters (name, type, default, range or choices, description).
// parameter_spec_from_json: one parameter in the catalogue's form (name, type, default,
//   minimum, maximum, minimum_exclusive, choices, description; a missing bound is none), as
//   an external algorithm declares it; throws std::runtime_error naming `where` if malformed.
// outputs_from_names: the inverse of output_names; throws naming `where` for an unknown name.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <span>
#include <string>

#include "core/algorithm.h"

namespace curvebench {

ParameterValue parameter_from_json(const nlohmann::json& value, const std::string& where);
std::map<std::string, ParameterValue> parameters_from_json(const nlohmann::json& object, const std::string& where);
nlohmann::ordered_json parameter_to_json(const ParameterValue& value);
nlohmann::ordered_json parameters_to_json(const ParameterValues& values);
nlohmann::ordered_json algorithm_catalogue(std::span<const Algorithm* const> algorithms);
// The names of the outputs in `outputs` (a bitwise or of Output values), in a fixed order.
std::vector<std::string> output_names(unsigned outputs);
unsigned outputs_from_names(const nlohmann::json& names, const std::string& where);
ParameterSpec parameter_spec_from_json(const nlohmann::json& json, const std::string& where);

}  // namespace curvebench
