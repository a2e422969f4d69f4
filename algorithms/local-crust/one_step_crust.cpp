#include "local-crust/one_step_crust.h"

#include <CGAL/Exact_rational.h>

#include <cmath>
#include <limits>

namespace curvebench {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// Below this the relative error bounds no longer hold (subnormal products): decide exactly.
constexpr double kTinyBound = 1e-280;

// dot(p - r, q - r) and cross(p - r, q - r): |pr| |qr| times cos and sin of the angle at r.
struct Angle {
  double dot, cross;
  double magnitude;  // |ux wx| + |uy wy| + |ux wy| + |uy wx|, bounds both and their errors
};

Angle angle_at(Point2 r, Point2 p, Point2 q) {
  const Point2 u = p - r, w = q - r;
  return {dot(u, w), cross(u, w),
          std::abs(u.x * w.x) + std::abs(u.y * w.y) + std::abs(u.x * w.y) + std::abs(u.y * w.x)};
}

using Q = CGAL::Exact_rational;

void exact_angle_at(Point2 r, Point2 p, Point2 q, Q& dot_value, Q& cross_value) {
  const Q ux = Q(p.x) - Q(r.x), uy = Q(p.y) - Q(r.y);
  const Q wx = Q(q.x) - Q(r.x), wy = Q(q.y) - Q(r.y);
  dot_value = ux * wx + uy * wy;
  cross_value = ux * wy - uy * wx;
}

// Angle at r is acute: the circumcentre of hull triangle (r, p, q) lies on r's side of pq.
bool acute(Point2 r, Point2 p, Point2 q) {
  const Angle a = angle_at(r, p, q);
  // Each of the two products carries at most 3 roundings (two differences, one product), the
  // sum one more: |error| <= 4 u magnitude with u = eps / 2; 4 eps leaves a factor 2 margin.
  const double bound = 4.0 * kEps * a.magnitude;
  if (std::isfinite(a.dot) && bound > kTinyBound && std::abs(a.dot) > bound) return a.dot > 0.0;
  Q d, c;
  exact_angle_at(r, p, q, d, c);
  return CGAL::sign(d) == CGAL::POSITIVE;
}

// angle(p r q) + angle(p s q) < 90 degrees, for r and s on opposite sides of pq:
// cos(sum) * |pr||qr||ps||qs| = dot_r dot_s - |cross_r| |cross_s| > 0, where the two crosses
// have opposite signs (r and s lie on opposite sides of pq).
bool angle_sum_acute(Point2 r, Point2 s, Point2 p, Point2 q) {
  const Angle a = angle_at(r, p, q), b = angle_at(s, p, q);
  const double value = a.dot * b.dot + a.cross * b.cross;
  // dot and cross each err by at most 4 u magnitude (u = eps / 2), so each product by 9 u ma mb
  // and the sum by 20 u ma mb in all: 16 eps = 32 u leaves a margin.
  const double bound = 16.0 * kEps * a.magnitude * b.magnitude;
  if (std::isfinite(value) && std::isfinite(bound) && bound > kTinyBound && std::abs(value) > bound) {
    return value > 0.0;
  }
  Q dr, cr, ds, cs;
  exact_angle_at(r, p, q, dr, cr);
  exact_angle_at(s, p, q, ds, cs);
  return CGAL::sign(dr * ds + cr * cs) == CGAL::POSITIVE;
}

}  // namespace

bool is_one_step_crust_edge(const DelaunayVoronoi& dv, int t, int k) {
  const auto& tri = dv.triangles[t];
  const Point2 r = dv.sites[tri[k]], p = dv.sites[tri[(k + 1) % 3]], q = dv.sites[tri[(k + 2) % 3]];
  const int other = dv.neighbors[t][k];
  if (other == kInfinite) return acute(r, p, q);
  const int j = dv.neighbors[other][0] == t ? 0 : (dv.neighbors[other][1] == t ? 1 : 2);
  return angle_sum_acute(r, dv.sites[dv.triangles[other][j]], p, q);
}

OneStepCrust one_step_crust(const DelaunayVoronoi& dv) {
  const int triangles = dv.triangle_count();
  OneStepCrust result;
  result.is_crust.assign(triangles, {0, 0, 0});
  for (int t = 0; t < triangles; ++t) {
    const auto& tri = dv.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int other = dv.neighbors[t][k];
      if (other != kInfinite && other < t) continue;  // decided from the other side
      const bool crust = is_one_step_crust_edge(dv, t, k);
      result.is_crust[t][k] = crust;
      if (other != kInfinite) {
        const int j = dv.neighbors[other][0] == t ? 0 : (dv.neighbors[other][1] == t ? 1 : 2);
        result.is_crust[other][j] = crust;
      }
      if (crust) result.curve.push_back(make_edge(tri[(k + 1) % 3], tri[(k + 2) % 3]));
    }
  }
  return result;
}

}  // namespace curvebench
