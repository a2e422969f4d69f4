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
    // Discrete curvature: turning angle over the mean length of the two edges.
    std::vector<double> curvature(n);
    double mean = 0.0;
    for (int i = 0; i < n; ++i) {
      const Point2 in = p[i] - p[(i + n - 1) % n], out_edge = p[(i + 1) % n] - p[i];
      curvature[i] = std::abs(std::atan2(cross(in, out_edge), dot(in, out_edge))) / (0.5 * (norm(in) + norm(out_edge)));
      mean += curvature[i] / n;
    }
    const int reach = std::min(std::max(window, n / 512), (n - 1) / 2);
    for (int i = 0; i < n; ++i) {
      // 0.1% above the mean, so that rounding on a circle makes no peak.
      bool peak = curvature[i] > 1.001 * mean;
      for (int d = 1; d <= reach && peak; ++d) {
        peak = curvature[i] > curvature[(i + d) % n] && curvature[i] > curvature[(i + n - d) % n];
      }
      if (peak) out.push_back(p[i]);
    }
  }
  return out;
}

}  // namespace curvebench
