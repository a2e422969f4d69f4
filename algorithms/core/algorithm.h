// The one interface every reconstruction algorithm implements. An algorithm states its
// name, what it produces and its parameters (with defaults), and maps points to a
// Reconstruction. It throws InputError with a one-line message for input it cannot handle.
#pragma once

#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/point.h"
#include "core/reconstruction.h"

namespace curvebench {

// Input an algorithm cannot reconstruct from (too few points, all collinear, bad parameter).
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum Output : unsigned {
  kCurve = 1u << 0,
  kMedialAxis = 1u << 1,
  kDominantPoints = 1u << 2,
};

struct ParameterSpec {
  std::string name;
  double default_value;
  std::string description;
};

using Parameters = std::map<std::string, double>;

class Algorithm {
 public:
  virtual ~Algorithm() = default;
  virtual std::string name() const = 0;
  virtual std::string description() const = 0;
  virtual unsigned outputs() const = 0;  // a bitwise or of Output values
  virtual std::vector<ParameterSpec> parameters() const { return {}; }
  // `params` holds only names from parameters(); missing ones take their defaults.
  virtual Reconstruction reconstruct(std::span<const Point2> points, const Parameters& params) const = 0;
};

// Defaults from `specs`, overridden by `given`; throws InputError on an unknown name.
Parameters resolve_parameters(const std::vector<ParameterSpec>& specs, const Parameters& given,
                              const std::string& algorithm_name);

}  // namespace curvebench
