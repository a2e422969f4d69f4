#include "generators/dominant_points.h"

#include <cmath>

namespace curvebench {

std::vector<Point2> true_dominant_points(const Scene& scene, int window) {
  std::vector<Point2> out;
  for (const auto& curve : scene.curves) {
    const auto& p = curve.points;
    const int n = static_cast<int>(p.size());
    if (!curve.corners.empty()) {
      for (const int corner : curve.corners) out.push_back(p[corner]);
      continue;
    }
    // Discrete curvature: turning angle over the mean length of the two edges. An open
    // curve has none at its ends, and a peak needs its whole window inside the curve.
    const int first = curve.closed ? 0 : 1, last = curve.closed ? n - 1 : n - 2;
    std::vector<double> curvature(n, 0.0);
    double mean = 0.0;
    for (int i = first; i <= last; ++i) {
      const Point2 in = p[i] - p[(i + n - 1) % n], out_edge = p[(i + 1) % n] - p[i];
      curvature[i] = std::abs(std::atan2(cross(in, out_edge), dot(in, out_edge))) / (0.5 * (norm(in) + norm(out_edge)));
      mean += curvature[i] / (last - first + 1);
    }
    const int reach = std::min(std::max(window, n / 512), (n - 1) / 2);
    if (!curve.closed) out.push_back(p.front());
    for (int i = first; i <= last; ++i) {
      if (!curve.closed && (i - reach < first || i + reach > last)) continue;
      // 0.1% above the mean, so that rounding on a circle makes no peak.
      bool peak = curvature[i] > 1.001 * mean;
      for (int d = 1; d <= reach && peak; ++d) {
        peak = curvature[i] > curvature[(i + d) % n] && curvature[i] > curvature[(i + n - d) % n];
      }
      if (peak) out.push_back(p[i]);
    }
    if (!curve.closed) out.push_back(p.back());
  }
  return out;
}

}  // namespace curvebench
