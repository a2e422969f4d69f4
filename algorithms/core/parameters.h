// Typed algorithm parameters: what an algorithm declares (ParameterSpec), what a caller gives
// (ParameterValue by name), and the checked, complete set an algorithm runs with
// (ParameterValues). Validation happens once, in resolve_parameters; algorithms never check
// their own parameters.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace curvebench {

enum class ParameterType { kReal, kInteger, kBoolean, kChoice };

// A value as given or resolved: a real, an integer, a boolean or a choice's name.
using ParameterValue = std::variant<double, std::int64_t, bool, std::string>;
// Values given by name (text from a command line is converted when resolved).
using ParameterAssignments = std::map<std::string, ParameterValue>;

struct ParameterSpec {
  std::string name;
  ParameterType type = ParameterType::kReal;
  ParameterValue default_value;
  // Inclusive bounds of a real or integer parameter; `minimum_exclusive` makes the lower one strict.
  double minimum = 0.0;
  double maximum = 0.0;
  bool minimum_exclusive = false;
  std::vector<std::string> choices;  // the names a choice parameter accepts
  std::string description;           // one line
};

ParameterSpec real_parameter(std::string name, double default_value, double minimum, double maximum,
                             std::string description, bool minimum_exclusive = false);
ParameterSpec integer_parameter(std::string name, std::int64_t default_value, std::int64_t minimum,
                                std::int64_t maximum, std::string description);
ParameterSpec boolean_parameter(std::string name, bool default_value, std::string description);
ParameterSpec choice_parameter(std::string name, std::string default_value, std::vector<std::string> choices,
                               std::string description);

// "real", "integer", "boolean" or "choice".
std::string type_name(ParameterType type);
// What a spec allows, in words: "a real number > 0 and <= 100", "one of: a, b", ...
std::string allowed_values(const ParameterSpec& spec);
// The value as text ("0.5", "15", "true", "auto"), as the command line takes it.
std::string value_text(const ParameterValue& value);

// Every parameter of an algorithm, checked and with defaults filled in.
class ParameterValues {
 public:
  double real(const std::string& name) const;
  std::int64_t integer(const std::string& name) const;
  bool boolean(const std::string& name) const;
  const std::string& choice(const std::string& name) const;
  const std::map<std::string, ParameterValue>& all() const { return values_; }

 private:
  friend ParameterValues resolve_parameters(const std::string&, const std::vector<ParameterSpec>&,
                                            const ParameterAssignments&);
  const ParameterValue& at(const std::string& name) const;
  std::map<std::string, ParameterValue> values_;
};

// Defaults from `specs`, overridden by `given`, each converted to its declared type and
// checked against its range. A real accepts any number, an integer a whole number, a boolean
// true/false or 0/1, a choice one of its names; text (from a command line) is parsed first.
// Throws InputError with one line naming the algorithm, the parameter and what is allowed.
ParameterValues resolve_parameters(const std::string& algorithm, const std::vector<ParameterSpec>& specs,
                                   const ParameterAssignments& given);

}  // namespace curvebench
