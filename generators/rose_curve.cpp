#include "generators/rose_curve.h"

#include <cmath>

namespace curvebench {

Point2 rose_point(double a, double b, int k, double t) {
  const double r = a + b * std::cos(k * t);
  return {r * std::cos(t), r * std::sin(t)};
}

Point2 rose_unit_normal(double a, double b, int k, double t) {
  const double r = a + b * std::cos(k * t), dr = -b * k * std::sin(k * t);
  const double tx = dr * std::cos(t) - r * std::sin(t), ty = dr * std::sin(t) + r * std::cos(t);
  const double length = std::hypot(tx, ty);
  return {ty / length, -tx / length};
}

}  // namespace curvebench
