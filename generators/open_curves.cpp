#include "generators/open_curves.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "generators/fourier_radius.h"
#include "generators/random.h"
#include "generators/scene_builder.h"

namespace curvebench {
namespace {

void require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument(message);
}

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

void require_arc_angle(double angle_degrees, const std::string& family) {
  require(angle_degrees > 0 && angle_degrees < 360, family + ": angle must be in (0, 360) degrees");
}

}  // namespace

Scene circular_arc_scene(double radius, double angle_degrees, int dense) {
  require(radius > 0 && std::isfinite(radius), "arc: radius must be a positive number");
  require_arc_angle(angle_degrees, "arc");
  const double half = radians(angle_degrees) / 2;
  auto points = open_parametric_polyline(
      [=](double s) { return radius * Point2{std::cos(-half + 2 * half * s), std::sin(-half + 2 * half * s)}; }, dense);
  return make_scene("arc", {smooth_curve(std::move(points), false)});
}

Scene elliptic_arc_scene(double a, double b, double angle_degrees, int dense) {
  require(a > 0 && b > 0 && std::isfinite(a) && std::isfinite(b), "ellipse-arc: semi-axes must be positive numbers");
  require_arc_angle(angle_degrees, "ellipse-arc");
  const double half = radians(angle_degrees) / 2;
  auto points = open_parametric_polyline(
      [=](double s) { return Point2{a * std::cos(-half + 2 * half * s), b * std::sin(-half + 2 * half * s)}; }, dense);
  return make_scene("ellipse_arc", {smooth_curve(std::move(points), false)});
}

Scene spiral_scene(double turns, double gap, int dense) {
  require(turns > 0 && turns <= 64, "spiral: turns must be in (0, 64]");
  require(gap > 0 && std::isfinite(gap), "spiral: gap must be a positive number");
  const double end = 2 * std::numbers::pi * turns;
  auto points = open_parametric_polyline(
      [=](double s) {
        const double phi = end * s;
        return gap * (1 + phi / (2 * std::numbers::pi)) * Point2{std::cos(phi), std::sin(phi)};
      },
      dense);
  return make_scene("spiral", {smooth_curve(std::move(points), false)});
}

Scene open_random_scene(std::uint64_t seed, int dense) {
  const FourierRadius radius = random_fourier_radius(derive_seed(seed, 0));
  Random random(derive_seed(seed, 1));
  const double start = random.uniform(0.0, 2 * std::numbers::pi);
  const double span = radians(random.uniform(180.0, 300.0));
  auto points = open_parametric_polyline(
      [&](double s) {
        const double t = start + span * s;
        return radius(t) * Point2{std::cos(t), std::sin(t)};
      },
      dense);
  return make_scene("open_random", {smooth_curve(std::move(points), false)});
}

}  // namespace curvebench
