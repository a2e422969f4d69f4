#include "core/algorithm.h"

namespace curvebench {

Parameters resolve_parameters(const std::vector<ParameterSpec>& specs, const Parameters& given,
                              const std::string& algorithm_name) {
  Parameters resolved;
  for (const auto& spec : specs) resolved[spec.name] = spec.default_value;
  for (const auto& [name, value] : given) {
    if (!resolved.contains(name)) {
      throw InputError("algorithm '" + algorithm_name + "' has no parameter '" + name + "'");
    }
    resolved[name] = value;
  }
  return resolved;
}

}  // namespace curvebench
