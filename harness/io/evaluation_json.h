// The scores of one reconstruction as `curvebench evaluate` prints them, without the file
// names: {"oracle_l2_error": ..., "metrics": {...}} (metrics_json.h holds the metrics).
//
// In:  the ground truth, the input points it describes (file order) and a reconstruction of
//      those points.
// Out: the oracle L2 error of the points (oracle_l2_error.h; null when undefined) and every
//      metric of the reconstruction (evaluate_reconstruction.h). The command line and the
//      Python package both call this, so their figures are the same.
// Throws what oracle_l2_error and evaluate_reconstruction throw.
#pragma once

#include <nlohmann/json.hpp>
#include <span>

#include "core/reconstruction.h"
#include "generators/ground_truth.h"

namespace curvebench {

nlohmann::ordered_json evaluation_to_json(const GroundTruth& truth, std::span<const Point2> points,
                                          const Reconstruction& reconstruction);

}  // namespace curvebench
