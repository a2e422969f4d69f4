// The radius of the random smooth curves: r(t) = 1 + sum over k = 2..6 of
// (a_k cos kt + b_k sin kt), coefficients uniform in +-0.25/k: smooth, often with
// concavities, always star-shaped about the origin.
//
// random_fourier_radius: in a seed, out its radius, coefficients redrawn until the radius
// stays clear of zero (r > 0.2, so no pinch) and the closed curve is simple, both checked on
// a 4096-vertex polyline (independent of any density, so the same seed gives the same curve
// at any density).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

namespace curvebench {

struct FourierRadius {
  static constexpr int kFirst = 2, kLast = 6;
  std::array<double, kLast + 1> cosine{}, sine{};

  double operator()(double t) const {
    // cos kt and sin kt by the angle-addition recurrence: one sin/cos pair per evaluation.
    const double c1 = std::cos(t), s1 = std::sin(t);
    double ck = c1, sk = s1, r = 1.0;
    for (int k = 2; k <= kLast; ++k) {
      const double next_c = ck * c1 - sk * s1;
      sk = sk * c1 + ck * s1;
      ck = next_c;
      r += cosine[k] * ck + sine[k] * sk;
    }
    return r;
  }
};

FourierRadius random_fourier_radius(std::uint64_t seed);

}  // namespace curvebench
