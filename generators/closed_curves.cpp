#include "generators/closed_curves.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

#include "generators/fourier_radius.h"
#include "generators/polylines_are_simple.h"
#include "generators/random.h"
#include "generators/rose_curve.h"
#include "generators/scene_builder.h"

namespace curvebench {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

void require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument(message);
}

std::vector<Point2> polar_polyline(const std::function<double(double)>& radius, int dense) {
  return closed_parametric_polyline([&](double t) { return radius(t) * Point2{std::cos(t), std::sin(t)}; }, dense);
}

std::vector<Point2> random_fourier_polyline(std::uint64_t seed, int dense) {
  return polar_polyline(random_fourier_radius(seed), dense);
}

}  // namespace

FourierRadius random_fourier_radius(std::uint64_t seed) {
  Random random(seed);
  for (;;) {
    FourierRadius radius;
    for (int k = FourierRadius::kFirst; k <= FourierRadius::kLast; ++k) {
      radius.cosine[k] = random.uniform(-0.25, 0.25) / k;
      radius.sine[k] = random.uniform(-0.25, 0.25) / k;
    }
    const auto polyline = polar_polyline(radius, 4096);
    const bool clear_of_zero = std::all_of(polyline.begin(), polyline.end(), [](Point2 p) { return norm(p) > 0.2; });
    if (clear_of_zero && find_polyline_crossing({polyline}).empty()) return radius;
  }
}

Scene circle_scene(double radius, int dense) {
  require(radius > 0 && std::isfinite(radius), "circle: radius must be a positive number");
  require(dense >= 3, "circle: dense must be at least 3");
  std::vector<Point2> points(dense);
  for (int i = 0; i < dense; ++i) points[i] = radius * Point2{std::cos(kTwoPi * i / dense), std::sin(kTwoPi * i / dense)};
  return make_scene("circle", {smooth_curve(std::move(points))}, [radius](Point2) { return radius; });
}

Scene ellipse_scene(double a, double b, int dense) {
  require(a > 0 && b > 0 && std::isfinite(a) && std::isfinite(b), "ellipse: semi-axes must be positive numbers");
  auto points = closed_parametric_polyline([a, b](double t) { return Point2{a * std::cos(t), b * std::sin(t)}; }, dense);
  // The medial axis of an ellipse is the segment between the centres of curvature at the
  // ends of the major axis; lfs is the distance to that segment (outside it is empty).
  const double half_axis = a >= b ? (a * a - b * b) / a : (b * b - a * a) / b;
  auto exact_lfs = [a, b, half_axis](Point2 p) {
    return a >= b ? std::hypot(p.x - std::clamp(p.x, -half_axis, half_axis), p.y)
                  : std::hypot(p.x, p.y - std::clamp(p.y, -half_axis, half_axis));
  };
  return make_scene("ellipse", {smooth_curve(std::move(points))}, exact_lfs);
}

Scene rose_scene(double a, double b, int k, int dense) {
  require(std::isfinite(a) && std::isfinite(b) && a > std::abs(b), "rose: need a > |b| so that r = a + b cos(k t) > 0");
  require(k >= 1, "rose: k must be at least 1");
  auto points = closed_parametric_polyline([a, b, k](double t) { return rose_point(a, b, k, t); }, dense);
  return make_scene("rose", {smooth_curve(std::move(points))});
}

Scene random_fourier_scene(std::uint64_t seed, int dense) {
  require(dense >= 3, "random curve: dense must be at least 3");
  return make_scene("random_fourier", {smooth_curve(random_fourier_polyline(seed, dense))});
}

Scene disjoint_curves_scene(int count, std::uint64_t seed, int dense) {
  require(count >= 1 && count <= 16, "disjoint curves: count must be between 1 and 16");
  require(dense >= 3, "disjoint curves: dense must be at least 3");
  Random random(seed);
  std::vector<DenseCurve> curves;
  std::vector<Point2> centers;
  std::vector<double> reaches;  // radius of a disc around the centre holding the curve
  double half_width = 1.5 * std::sqrt(static_cast<double>(count));
  for (int c = 0; c < count; ++c) {
    auto curve = random_fourier_polyline(derive_seed(seed, c), dense);
    const double scale = random.uniform(0.4, 1.0);
    const double angle = random.uniform(0.0, kTwoPi);
    double reach = 0.0;
    for (Point2& p : curve) {
      p = scale * Point2{p.x * std::cos(angle) - p.y * std::sin(angle), p.x * std::sin(angle) + p.y * std::cos(angle)};
      reach = std::max(reach, norm(p));
    }
    // Random centres, rejected while the discs come closer than a gap; the box grows when
    // it is crowded, so placement always ends.
    for (int attempt = 1;; ++attempt) {
      const Point2 center{random.uniform(-half_width, half_width), random.uniform(-half_width, half_width)};
      bool clear = true;
      for (size_t j = 0; j < centers.size() && clear; ++j) clear = distance(center, centers[j]) > reach + reaches[j] + 0.1;
      if (clear) {
        for (Point2& p : curve) p = p + center;
        centers.push_back(center);
        reaches.push_back(reach);
        break;
      }
      if (attempt % 100 == 0) half_width *= 1.2;
    }
    curves.push_back(smooth_curve(std::move(curve)));
  }
  return make_scene("disjoint_curves", std::move(curves));
}

Scene superellipse_scene(double a, double b, double exponent, int dense) {
  require(a > 0 && b > 0 && std::isfinite(a) && std::isfinite(b), "superellipse: semi-axes must be positive numbers");
  require(exponent >= 1 && std::isfinite(exponent), "superellipse: exponent must be at least 1");
  auto signed_power = [exponent](double v) { return std::copysign(std::pow(std::abs(v), 2.0 / exponent), v); };
  auto points = closed_parametric_polyline(
      [=](double t) { return Point2{a * signed_power(std::cos(t)), b * signed_power(std::sin(t))}; }, dense);
  return make_scene("superellipse", {smooth_curve(std::move(points))});
}

Scene dumbbell_scene(double neck_half_width, int dense) {
  require(neck_half_width > 0 && neck_half_width <= 1, "dumbbell: neck half-width must be in (0, 1]");
  // Cassini oval with foci (+-1, 0): (x^2 + y^2)^2 - 2 (x^2 - y^2) = a^4 - 1. Its half-width
  // at x = 0 is sqrt(a^2 - 1); in polar form r^2 = cos 2t + sqrt(cos^2 2t + a^4 - 1).
  const double a2 = 1.0 + neck_half_width * neck_half_width;
  auto points = polar_polyline(
      [a2](double t) {
        const double c = std::cos(2 * t);
        return std::sqrt(c + std::sqrt(c * c + a2 * a2 - 1.0));
      },
      dense);
  return make_scene("dumbbell", {smooth_curve(std::move(points))});
}

Scene concavities_scene(int count, double depth, double width, int dense) {
  require(count >= 1 && count <= 64, "concavities: count must be between 1 and 64");
  require(depth > 0 && depth <= 0.9, "concavities: depth must be in (0, 0.9]");
  require(width > 0 && width * count < kTwoPi, "concavities: width must be positive and the slots must fit");
  // Slots at equally spaced angles; each bump is a Gaussian in the angular distance to it.
  auto radius = [=](double t) {
    double bumps = 0.0;
    for (int i = 0; i < count; ++i) {
      double delta = std::remainder(t - kTwoPi * (i + 0.5) / count, kTwoPi);
      bumps += std::exp(-0.5 * (delta / width) * (delta / width));
    }
    return 1.0 - depth * std::min(bumps, 1.0);
  };
  // Slots are narrow: oversample so that their bottoms get enough vertices.
  return make_scene("concavities", {smooth_curve(polar_polyline(radius, dense))});
}

Scene nested_curves_scene(std::uint64_t seed, int dense) {
  require(dense >= 3, "nested curves: dense must be at least 3");
  // Both curves are star-shaped about the origin, so the inner one lies inside the outer one
  // when its largest radius is below the outer's smallest; half of it leaves a wide gap.
  const FourierRadius outer = random_fourier_radius(derive_seed(seed, 0));
  const FourierRadius inner = random_fourier_radius(derive_seed(seed, 1));
  auto outer_points = polar_polyline(outer, dense);
  auto inner_points = polar_polyline(inner, dense);
  double outer_min = HUGE_VAL, inner_max = 0.0;
  for (const Point2 p : outer_points) outer_min = std::min(outer_min, norm(p));
  for (const Point2 p : inner_points) inner_max = std::max(inner_max, norm(p));
  const double scale = 0.5 * outer_min / inner_max;
  for (Point2& p : inner_points) p = scale * p;
  return make_scene("nested_curves", {smooth_curve(std::move(outer_points)), smooth_curve(std::move(inner_points))});
}

Scene holes_scene(int count, std::uint64_t seed, int dense) {
  require(count >= 1 && count <= 8, "holes: count must be between 1 and 8");
  require(dense >= 3, "holes: dense must be at least 3");
  const FourierRadius outer = random_fourier_radius(derive_seed(seed, 0));
  std::vector<Point2> outer_points = polar_polyline(outer, dense);
  double outer_max = 0.0;
  for (const Point2 p : outer_points) outer_max = std::max(outer_max, norm(p));
  constexpr double kGap = 0.1;
  auto clearance_to_outer = [&](Point2 center) {
    double least = HUGE_VAL;
    for (const Point2 p : outer_points) least = std::min(least, distance(center, p));
    return least;
  };
  Random random(derive_seed(seed, 1));
  std::vector<DenseCurve> curves;  // the holes, then the outer curve first
  std::vector<Point2> centers;
  std::vector<double> reaches;  // radius of a disc around the centre holding the hole
  for (int h = 0; h < count; ++h) {
    auto hole = random_fourier_polyline(derive_seed(seed, 2 + h), dense);
    double unit_reach = 0.0;
    for (const Point2 p : hole) unit_reach = std::max(unit_reach, norm(p));
    double reach = random.uniform(0.15, 0.3);
    const double angle = random.uniform(0.0, kTwoPi);
    // Centres inside the outer curve (star-shaped about the origin), rejected while the hole's
    // disc comes within the gap of the outer curve or of another hole's disc; the hole
    // shrinks when it does not fit, so placement always ends (the outer curve keeps 0.2 from
    // the origin).
    for (int attempt = 1;; ++attempt) {
      const Point2 center{random.uniform(-outer_max, outer_max), random.uniform(-outer_max, outer_max)};
      bool clear = norm(center) < outer(std::atan2(center.y, center.x)) && clearance_to_outer(center) > reach + kGap;
      for (size_t j = 0; j < centers.size() && clear; ++j) clear = distance(center, centers[j]) > reach + reaches[j] + kGap;
      if (clear) {
        const double scale = reach / unit_reach;
        for (Point2& p : hole) {
          p = center + scale * Point2{p.x * std::cos(angle) - p.y * std::sin(angle), p.x * std::sin(angle) + p.y * std::cos(angle)};
        }
        centers.push_back(center);
        reaches.push_back(reach);
        break;
      }
      if (attempt % 100 == 0) reach *= 0.9;
    }
    curves.push_back(smooth_curve(std::move(hole)));
  }
  curves.insert(curves.begin(), smooth_curve(std::move(outer_points)));
  return make_scene("holes", std::move(curves));
}

}  // namespace curvebench
