#include "io/evaluation_json.h"

#include <cmath>

#include "io/metrics_json.h"
#include "metrics/evaluate_reconstruction.h"
#include "metrics/oracle_l2_error.h"

namespace curvebench {

nlohmann::ordered_json evaluation_to_json(const GroundTruth& truth, std::span<const Point2> points,
                                          const Reconstruction& reconstruction) {
  const double oracle = oracle_l2_error(truth, points);
  const ReconstructionMetrics metrics = evaluate_reconstruction(truth, points, reconstruction);
  nlohmann::ordered_json json;
  json["oracle_l2_error"] = std::isnan(oracle) ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(oracle);
  json["metrics"] = metrics_to_json(metrics);
  return json;
}

}  // namespace curvebench
