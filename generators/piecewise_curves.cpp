// Piecewise-smooth families (star, square, L-shape, crescent) and imported polygons: the
// closed_curves.h families whose curves have sharp corners.
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "generators/closed_curves.h"
#include "generators/scene_builder.h"

namespace curvebench {
namespace {

constexpr double kPi = std::numbers::pi;

void require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument(message);
}

}  // namespace

Scene polygon_scene(std::string name, const std::vector<std::vector<Point2>>& rings, int dense) {
  require(!rings.empty(), name + ": no polygon");
  std::vector<std::vector<Point2>> cleaned;
  for (const auto& ring : rings) {
    // Drop repeated vertices (GeoJSON and SVG close rings by repeating the first).
    std::vector<Point2> distinct;
    for (const Point2 p : ring) {
      require(std::isfinite(p.x) && std::isfinite(p.y), name + ": a vertex is not a finite number");
      if (distinct.empty() || !(distinct.back() == p)) distinct.push_back(p);
    }
    while (distinct.size() > 1 && distinct.front() == distinct.back()) distinct.pop_back();
    require(distinct.size() >= 3, name + ": a ring has fewer than 3 distinct vertices");
    cleaned.push_back(std::move(distinct));
  }
  return make_scene(std::move(name), densify_polygons(cleaned, dense));
}

Scene star_scene(int points, double inner_ratio, int dense) {
  require(points >= 2, "star: needs at least 2 points");
  require(inner_ratio > 0 && inner_ratio < 1, "star: inner radius ratio must be in (0, 1)");
  std::vector<Point2> ring;
  for (int i = 0; i < 2 * points; ++i) {
    const double angle = kPi * i / points + kPi / 2;
    ring.push_back((i % 2 == 0 ? 1.0 : inner_ratio) * Point2{std::cos(angle), std::sin(angle)});
  }
  return polygon_scene("star", {ring}, dense);
}

Scene square_scene(double side, int dense) {
  require(side > 0 && std::isfinite(side), "square: side must be a positive number");
  const double h = side / 2;
  return polygon_scene("square", {{{-h, -h}, {h, -h}, {h, h}, {-h, h}}}, dense);
}

Scene l_shape_scene(double arm_width, int dense) {
  require(arm_width > 0 && arm_width < 2, "L-shape: arm width must be in (0, 2)");
  const double w = arm_width;
  return polygon_scene("l_shape", {{{0, 0}, {2, 0}, {2, w}, {w, w}, {w, 2}, {0, 2}}}, dense);
}

Scene horned_scene(double inner_radius, double offset, int dense) {
  require(inner_radius > 0 && offset > 0 && std::isfinite(inner_radius) && std::isfinite(offset),
          "horned: radius and offset must be positive numbers");
  // The circles |p| = 1 and |p - (offset, 0)| = inner_radius must cross for two horn tips,
  // and the inner disc must not contain the origin's side entirely.
  require(std::abs(1 - inner_radius) < offset && offset < 1 + inner_radius, "horned: the two circles must cross");
  const double tip_x = (1 + offset * offset - inner_radius * inner_radius) / (2 * offset);
  const double tip_angle = std::acos(tip_x);                                  // on the unit circle
  const double inner_tip_angle = std::atan2(std::sqrt(1 - tip_x * tip_x), tip_x - offset);  // on the inner circle
  // Outer arc from the upper tip counter-clockwise round to the lower tip, then the inner arc
  // clockwise back (it bounds the crescent from the inside of the bite).
  const double outer_span = 2 * (kPi - tip_angle), inner_span = 2 * (kPi - inner_tip_angle);
  const double outer_length = outer_span, inner_length = inner_radius * inner_span;
  const int outer_count = std::max(3, static_cast<int>(dense * outer_length / (outer_length + inner_length)));
  const int inner_count = std::max(3, dense - outer_count);
  DenseCurve curve;
  curve.corners = {0, outer_count};
  for (int i = 0; i < outer_count; ++i) {
    const double angle = tip_angle + outer_span * i / outer_count;
    curve.points.push_back({std::cos(angle), std::sin(angle)});
  }
  for (int i = 0; i < inner_count; ++i) {
    const double angle = -inner_tip_angle - inner_span * i / inner_count;
    curve.points.push_back(Point2{offset, 0} + inner_radius * Point2{std::cos(angle), std::sin(angle)});
  }
  return make_scene("horned", {std::move(curve)});
}

}  // namespace curvebench
