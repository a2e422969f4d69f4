// The metrics of one reconstruction as a flat JSON object: what `curvebench evaluate` writes
// and what each sweep row holds under "metrics". Keys of an output the reconstruction lacks
// are absent; a value that is undefined for it (an infinite distance; the edge comparison of
// a curve on vertices of its own, whose edges join no samples) is null.
//
// {"true_curves": 1,
//  "l2_error": 0.006, "hausdorff": 0.01, "curve_recall": 1.0,
//  "curve_recall_tolerance": 0.01, "manifold": true, "components": 1,
//  "closed_components": 1, "dangling_vertices": 0, "branching_vertices": 0,
//  "exact": true, "edge_precision": 1.0, "edge_recall": 1.0, "edge_f1": 1.0,  // null unless on samples
//  "medial_axis_hausdorff": 0.02,
//  "dominant_points": 12, "compression_ratio": 9.4, "integral_square_error": 0.03,
//  "figure_of_merit": 313.3}
#pragma once

#include <nlohmann/json.hpp>

#include "metrics/evaluate_reconstruction.h"

namespace curvebench {

nlohmann::ordered_json metrics_to_json(const ReconstructionMetrics& metrics);

}  // namespace curvebench
