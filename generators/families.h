// The curve families: one table that `curvebench generate`, the sweep, the benchmark, the
// exactness table and the tests all build their shapes from.
//
// A family has a name, a one-line description, named shape parameters with defaults (some
// integer), whether its shape depends on the seed, a builder (shape values, seed, dense
// vertices per curve -> Scene) and, where one is known in closed form, its exact interior
// medial axis (open families have none: they bound no region). Imported outlines
// ("outline") are not in the table: they come from a file (generate.h).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "generators/closed_curves.h"
#include "generators/medial_axis.h"

namespace curvebench {

using ShapeValues = std::map<std::string, double>;  // shape parameter name -> value

struct ShapeParameter {
  std::string name;
  double default_value;
  bool integer;
};

struct CurveFamily {
  std::string name;
  std::string description;
  std::vector<ShapeParameter> parameters;
  bool seeded;  // the shape itself depends on the seed
  std::function<Scene(const ShapeValues&, std::uint64_t seed, int dense)> build;
  std::function<MedialAxis(const ShapeValues&)> exact_medial_axis;  // empty if none is known
};

// Every family, in the order `curvebench generate --help` lists them.
const std::vector<CurveFamily>& curve_families();

// The family named `name`; throws std::runtime_error listing the known names (and
// "outline") if there is none.
const CurveFamily& find_curve_family(const std::string& name);

// In:  a family and values for some of its shape parameters.
// Out: every shape parameter of the family, the given value or the default.
// Throws std::runtime_error naming the parameter if it is not the family's, or not an
// integer in [1, 2^20] where the family wants an integer.
ShapeValues resolve_shape(const CurveFamily& family, const ShapeValues& given);

// The scene of family `name` with the `given` shape values (the rest default), built for
// `seed` (seeded families only) with `dense` vertices per curve.
Scene curve_family_scene(const std::string& name, const ShapeValues& given, std::uint64_t seed, int dense);

}  // namespace curvebench
