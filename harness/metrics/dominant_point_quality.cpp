#include "metrics/dominant_point_quality.h"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace curvebench {
namespace {

// The integral square error of one curve: `order` lists its samples along the curve.
std::optional<double> curve_square_error(std::span<const Point2> samples, const std::vector<int>& order,
                                         const std::set<int>& dominant) {
  std::vector<size_t> corners;  // positions in `order` of the dominant points
  for (size_t k = 0; k < order.size(); ++k) {
    if (dominant.contains(order[k])) corners.push_back(k);
  }
  if (corners.empty()) return std::nullopt;
  double error = 0.0;
  for (size_t c = 0; c < corners.size(); ++c) {
    const Point2 from = samples[order[corners[c]]];
    const size_t next = corners[(c + 1) % corners.size()];
    const Point2 to = samples[order[next]];
    // The samples strictly after this corner and before the next one, wrapping around.
    for (size_t k = (corners[c] + 1) % order.size(); k != next; k = (k + 1) % order.size()) {
      const Point2 offset = samples[order[k]] - closest_point_on_segment(samples[order[k]], from, to);
      error += dot(offset, offset);
    }
  }
  return error;
}

}  // namespace

DominantPointQuality dominant_point_quality(std::span<const Point2> samples, std::span<const int> curve_of_sample,
                                            std::span<const double> parameter_of_sample,
                                            std::span<const int> dominant_points) {
  if (curve_of_sample.size() != samples.size() || parameter_of_sample.size() != samples.size()) {
    throw std::invalid_argument("dominant point quality: one curve and one parameter per sample are needed");
  }
  const std::set<int> dominant(dominant_points.begin(), dominant_points.end());
  for (int index : dominant) {
    if (index < 0 || index >= static_cast<int>(samples.size())) {
      throw std::invalid_argument("dominant point " + std::to_string(index) + " is not a sample index");
    }
  }
  DominantPointQuality quality;
  quality.count = static_cast<int>(dominant.size());
  if (quality.count == 0) return quality;
  quality.compression_ratio = static_cast<double>(samples.size()) / quality.count;

  std::map<int, std::vector<int>> samples_by_curve;
  for (int i = 0; i < static_cast<int>(samples.size()); ++i) {
    if (curve_of_sample[i] >= 0) samples_by_curve[curve_of_sample[i]].push_back(i);
  }
  double error = 0.0;
  for (auto& [curve, order] : samples_by_curve) {
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return parameter_of_sample[a] < parameter_of_sample[b]; });
    const std::optional<double> curve_error = curve_square_error(samples, order, dominant);
    if (!curve_error) return quality;
    error += *curve_error;
  }
  quality.integral_square_error = error;
  if (error > 0.0) quality.figure_of_merit = *quality.compression_ratio / error;
  return quality;
}

}  // namespace curvebench
