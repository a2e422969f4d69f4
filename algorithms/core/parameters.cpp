#include "core/parameters.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <utility>

#include "core/algorithm.h"

namespace curvebench {
namespace {

std::string number_text(double value) {
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

// A number written as text, or nullopt-like failure reported by returning false.
bool parse_number(const std::string& text, double& value) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return *end == '\0' && errno != ERANGE && std::isfinite(value);
}

bool in_range(const ParameterSpec& spec, double value) {
  const bool above = spec.minimum_exclusive ? value > spec.minimum : value >= spec.minimum;
  return above && value <= spec.maximum;
}

// `given` as the spec's type, or throws with `why` describing what is allowed.
ParameterValue convert(const ParameterSpec& spec, const ParameterValue& given, const std::string& algorithm) {
  auto reject = [&] {
    throw InputError("algorithm '" + algorithm + "': parameter '" + spec.name + "' must be " + allowed_values(spec) +
                     " (got " + value_text(given) + ")");
  };
  double number = 0.0;
  bool is_number = false;
  if (const auto* d = std::get_if<double>(&given)) number = *d, is_number = true;
  if (const auto* i = std::get_if<std::int64_t>(&given)) number = static_cast<double>(*i), is_number = true;
  if (const auto* s = std::get_if<std::string>(&given); s && spec.type != ParameterType::kChoice) {
    if (*s == "true" || *s == "false") {
      if (spec.type != ParameterType::kBoolean) reject();
      return *s == "true";
    }
    is_number = parse_number(*s, number);
    if (!is_number) reject();
  }
  switch (spec.type) {
    case ParameterType::kReal:
      if (!is_number || !std::isfinite(number) || !in_range(spec, number)) reject();
      return number;
    case ParameterType::kInteger:
      if (!is_number || number != std::floor(number) || !in_range(spec, number)) reject();
      return static_cast<std::int64_t>(number);
    case ParameterType::kBoolean:
      if (const auto* b = std::get_if<bool>(&given)) return *b;
      if (!is_number || (number != 0.0 && number != 1.0)) reject();
      return number == 1.0;
    case ParameterType::kChoice:
      if (const auto* s = std::get_if<std::string>(&given)) {
        for (const auto& choice : spec.choices) {
          if (choice == *s) return *s;
        }
      }
      reject();
  }
  reject();
  return {};
}

}  // namespace

ParameterSpec real_parameter(std::string name, double default_value, double minimum, double maximum,
                             std::string description, bool minimum_exclusive) {
  return {std::move(name), ParameterType::kReal, default_value, minimum, maximum, minimum_exclusive, {},
          std::move(description)};
}

ParameterSpec integer_parameter(std::string name, std::int64_t default_value, std::int64_t minimum,
                                std::int64_t maximum, std::string description) {
  return {std::move(name), ParameterType::kInteger, default_value, static_cast<double>(minimum),
          static_cast<double>(maximum), false, {}, std::move(description)};
}

ParameterSpec boolean_parameter(std::string name, bool default_value, std::string description) {
  return {std::move(name), ParameterType::kBoolean, default_value, 0, 1, false, {}, std::move(description)};
}

ParameterSpec choice_parameter(std::string name, std::string default_value, std::vector<std::string> choices,
                               std::string description) {
  return {std::move(name), ParameterType::kChoice, std::move(default_value), 0, 0, false, std::move(choices),
          std::move(description)};
}

std::string type_name(ParameterType type) {
  switch (type) {
    case ParameterType::kReal: return "real";
    case ParameterType::kInteger: return "integer";
    case ParameterType::kBoolean: return "boolean";
    case ParameterType::kChoice: return "choice";
  }
  return "unknown";
}

std::string allowed_values(const ParameterSpec& spec) {
  auto bound = [](double v) { return std::isinf(v) ? std::string(v > 0 ? "inf" : "-inf") : number_text(v); };
  switch (spec.type) {
    case ParameterType::kReal:
    case ParameterType::kInteger: {
      std::string text = spec.type == ParameterType::kReal ? "a real number " : "a whole number ";
      text += (spec.minimum_exclusive ? "> " : ">= ") + bound(spec.minimum);
      if (std::isfinite(spec.maximum)) text += " and <= " + bound(spec.maximum);
      return text;
    }
    case ParameterType::kBoolean: return "true or false (1 or 0)";
    case ParameterType::kChoice: {
      std::string text = "one of: ";
      for (std::size_t i = 0; i < spec.choices.size(); ++i) text += (i ? ", " : "") + spec.choices[i];
      return text;
    }
  }
  return "";
}

std::string value_text(const ParameterValue& value) {
  if (const auto* d = std::get_if<double>(&value)) return number_text(*d);
  if (const auto* i = std::get_if<std::int64_t>(&value)) return std::to_string(*i);
  if (const auto* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  return std::get<std::string>(value);
}

const ParameterValue& ParameterValues::at(const std::string& name) const {
  const auto found = values_.find(name);
  if (found == values_.end()) throw std::logic_error("no parameter '" + name + "' was declared");
  return found->second;
}

double ParameterValues::real(const std::string& name) const { return std::get<double>(at(name)); }
std::int64_t ParameterValues::integer(const std::string& name) const { return std::get<std::int64_t>(at(name)); }
bool ParameterValues::boolean(const std::string& name) const { return std::get<bool>(at(name)); }
const std::string& ParameterValues::choice(const std::string& name) const { return std::get<std::string>(at(name)); }

ParameterValues resolve_parameters(const std::string& algorithm, const std::vector<ParameterSpec>& specs,
                                   const ParameterAssignments& given) {
  ParameterValues resolved;
  for (const auto& [name, value] : given) {
    const ParameterSpec* spec = nullptr;
    for (const auto& candidate : specs) {
      if (candidate.name == name) spec = &candidate;
    }
    if (!spec) {
      std::string known;
      for (const auto& candidate : specs) known += (known.empty() ? "" : ", ") + candidate.name;
      throw InputError("algorithm '" + algorithm + "' has no parameter '" + name + "' (" +
                       (known.empty() ? std::string("it takes none") : "it takes: " + known) + ")");
    }
    resolved.values_[name] = convert(*spec, value, algorithm);
  }
  for (const auto& spec : specs) resolved.values_.try_emplace(spec.name, spec.default_value);
  return resolved;
}

}  // namespace curvebench
