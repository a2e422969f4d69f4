// What is known about a generated input besides its points: the settings it was made with,
// the true curves, where every sample came from, the correct adjacency, the true interior
// medial axis and the dominant points (io/ground_truth_json.h is its file format).
#pragma once

#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/point.h"

namespace curvebench {

struct GroundTruthCurve {
  std::vector<Point2> vertices;  // closed: the last joins the first; open: from one end to the other
  std::vector<double> lfs;       // one per vertex
  bool closed = true;
};

inline bool has_open_curve(const std::vector<GroundTruthCurve>& curves) {
  for (const auto& curve : curves) {
    if (!curve.closed) return true;
  }
  return false;
}

struct GroundTruthSample {
  int curve = -1;  // index into curves, -1 for an outlier
  double parameter = std::numeric_limits<double>::quiet_NaN();
  double lfs = std::numeric_limits<double>::quiet_NaN();
  bool is_outlier() const { return curve < 0; }
};

struct GroundTruthMedialAxis {
  std::vector<Point2> vertices;
  std::vector<Edge> edges;
};

struct GroundTruth {
  nlohmann::ordered_json generator = nlohmann::ordered_json::object();  // settings, incl. "seed"
  std::vector<GroundTruthCurve> curves;
  std::vector<GroundTruthSample> samples;  // one per point of the points file
  std::vector<Edge> edges;
  GroundTruthMedialAxis medial_axis;
  std::vector<Point2> dominant_points;
};

}  // namespace curvebench
