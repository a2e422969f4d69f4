#include "generators/families.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "generators/number_text.h"
#include "generators/open_curves.h"

namespace curvebench {
namespace {

int integer_shape(const ShapeValues& values, const std::string& name) { return static_cast<int>(values.at(name)); }

}  // namespace

const std::vector<CurveFamily>& curve_families() {
  static const std::vector<CurveFamily> all = {
      {"circle", "circle of the given radius", {{"radius", 1, false}}, false,
       [](const ShapeValues& p, std::uint64_t, int dense) { return circle_scene(p.at("radius"), dense); },
       [](const ShapeValues& p) { return circle_medial_axis({0, 0}, p.at("radius")); }},
      {"ellipse", "ellipse with semi-axes a, b", {{"a", 2, false}, {"b", 1, false}}, false,
       [](const ShapeValues& p, std::uint64_t, int dense) { return ellipse_scene(p.at("a"), p.at("b"), dense); },
       [](const ShapeValues& p) { return ellipse_medial_axis(p.at("a"), p.at("b")); }},
      {"superellipse", "|x/a|^exponent + |y/b|^exponent = 1 (a rounded square for exponent > 2)",
       {{"a", 1, false}, {"b", 1, false}, {"exponent", 4, false}}, false,
       [](const ShapeValues& p, std::uint64_t, int dense) { return superellipse_scene(p.at("a"), p.at("b"), p.at("exponent"), dense); },
       nullptr},
      {"rose", "r = a + b cos(k t)", {{"a", 1, false}, {"b", 0.3, false}, {"k", 5, true}}, false,
       [](const ShapeValues& p, std::uint64_t, int dense) { return rose_scene(p.at("a"), p.at("b"), integer_shape(p, "k"), dense); },
       nullptr},
      {"random", "random smooth curve r(t) = 1 + random decaying harmonics", {}, true,
       [](const ShapeValues&, std::uint64_t seed, int dense) { return random_fourier_scene(seed, dense); }, nullptr},
      {"dumbbell", "two lobes joined by a thin neck of the given half-width (Cassini oval)", {{"neck", 0.2, false}}, false,
       [](const ShapeValues& p, std::uint64_t, int dense) { return dumbbell_scene(p.at("neck"), dense); }, nullptr},
      {"concavities", "unit circle with `count` deep narrow slots", {{"count", 5, true}, {"depth", 0.7, false}, {"width", 0.08, false}},
       false,
       [](const ShapeValues& p, std::uint64_t, int dense) {
         return concavities_scene(integer_shape(p, "count"), p.at("depth"), p.at("width"), dense);
       },
       nullptr},
      {"disjoint", "2-5 disjoint random smooth curves", {{"count", 3, true}}, true,
       [](const ShapeValues& p, std::uint64_t seed, int dense) { return disjoint_curves_scene(integer_shape(p, "count"), seed, dense); },
       nullptr},
      {"nested", "a random smooth curve with a smaller one inside it", {}, true,
       [](const ShapeValues&, std::uint64_t seed, int dense) { return nested_curves_scene(seed, dense); }, nullptr},
      {"holes", "a random smooth curve with `count` (1 to 8) disjoint smooth holes inside it", {{"count", 2, true}}, true,
       [](const ShapeValues& p, std::uint64_t seed, int dense) { return holes_scene(integer_shape(p, "count"), seed, dense); },
       nullptr},
      {"star", "star polygon with `points` tips, inner radius = inner_ratio", {{"points", 5, true}, {"inner_ratio", 0.45, false}}, false,
       [](const ShapeValues& p, std::uint64_t, int dense) { return star_scene(integer_shape(p, "points"), p.at("inner_ratio"), dense); },
       nullptr},
      {"square", "square of the given side", {{"side", 2, false}}, false,
       [](const ShapeValues& p, std::uint64_t, int dense) { return square_scene(p.at("side"), dense); }, nullptr},
      {"l-shape", "L in the 2x2 square with arms of the given width", {{"arm_width", 0.6, false}}, false,
       [](const ShapeValues& p, std::uint64_t, int dense) { return l_shape_scene(p.at("arm_width"), dense); }, nullptr},
      {"horned", "crescent: unit disc minus a disc (inner_radius, centre (offset, 0)); two horn tips",
       {{"inner_radius", 0.8, false}, {"offset", 0.5, false}}, false,
       [](const ShapeValues& p, std::uint64_t, int dense) { return horned_scene(p.at("inner_radius"), p.at("offset"), dense); },
       nullptr},
      {"arc", "open circular arc of the given radius over `angle` degrees (lfs = radius up to 180)",
       {{"radius", 1, false}, {"angle", 270, false}}, false,
       [](const ShapeValues& p, std::uint64_t, int dense) { return circular_arc_scene(p.at("radius"), p.at("angle"), dense); },
       nullptr},
      {"ellipse-arc", "open arc (a cos t, b sin t), t over `angle` degrees centred on (a, 0)",
       {{"a", 2, false}, {"b", 1, false}, {"angle", 270, false}}, false,
       [](const ShapeValues& p, std::uint64_t, int dense) { return elliptic_arc_scene(p.at("a"), p.at("b"), p.at("angle"), dense); },
       nullptr},
      {"spiral", "open Archimedean spiral r = gap (1 + phi / 2 pi) over `turns` turns", {{"turns", 2, false}, {"gap", 0.3, false}},
       false, [](const ShapeValues& p, std::uint64_t, int dense) { return spiral_scene(p.at("turns"), p.at("gap"), dense); },
       nullptr},
      {"open-random", "open arc of a random smooth curve over 180-300 degrees", {}, true,
       [](const ShapeValues&, std::uint64_t seed, int dense) { return open_random_scene(seed, dense); }, nullptr},
  };
  return all;
}

const CurveFamily& find_curve_family(const std::string& name) {
  for (const auto& family : curve_families()) {
    if (family.name == name) return family;
  }
  std::string known;
  for (const auto& family : curve_families()) known += (known.empty() ? "" : ", ") + family.name;
  throw std::runtime_error("--family: unknown family '" + name + "' (known: " + known + ", outline)");
}

ShapeValues resolve_shape(const CurveFamily& family, const ShapeValues& given) {
  ShapeValues values;
  for (const auto& p : family.parameters) values[p.name] = p.default_value;
  for (const auto& [name, value] : given) {
    const auto known = std::find_if(family.parameters.begin(), family.parameters.end(), [&name = name](const auto& p) { return p.name == name; });
    if (known == family.parameters.end()) {
      std::string names;
      for (const auto& p : family.parameters) names += (names.empty() ? "" : ", ") + p.name;
      throw std::runtime_error("--shape '" + name + "=" + number_text(value) + "': family " + family.name + " takes " +
                               (names.empty() ? "no shape parameters" : "name=value with name one of: " + names));
    }
    constexpr int kLargestInteger = 1 << 20;
    if (known->integer && (value != std::floor(value) || value < 1 || value > kLargestInteger)) {
      throw std::runtime_error("--shape " + name + ": '" + number_text(value) + "' is not an integer in [1, " +
                               std::to_string(kLargestInteger) + "]");
    }
    values[name] = value;
  }
  return values;
}

Scene curve_family_scene(const std::string& name, const ShapeValues& given, std::uint64_t seed, int dense) {
  const CurveFamily& family = find_curve_family(name);
  return family.build(resolve_shape(family, given), seed, dense);
}

}  // namespace curvebench
