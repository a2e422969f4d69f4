// The ground-truth JSON (harness/README.md, "Data flow and file formats"): what
// `curvebench generate --truth` writes beside the points file and `curvebench evaluate` reads.
//
// {"format": "curvebench-ground-truth/1",
//  "generator": {"family": "rose", "epsilon": 0.2, "seed": 3, ...every setting},
//  "points": N,                                   // samples in the points file, file order
//  "curves": [{"vertices": [[x, y], ...], "lfs": [...]}],   // dense closed counter-clockwise polylines;
//                                                 // an open one (end to end) also has "closed": false
//  "samples": [{"curve": 0, "parameter": 0.25, "lfs": 0.1}, {"curve": "outlier"}, ...],
//  "edges": [[i, j], ...],                        // correct adjacency between samples, i < j, sorted
//  "medial_axis": {"vertices": [[x, y], ...], "edges": [[a, b], ...]},  // true interior medial axis
//  "dominant_points": [[x, y], ...]}              // corners and curvature extrema on the curves
//
// "parameter" is the arc-length fraction in [0, 1) along the curve's dense polyline from its
// first vertex ([0, 1] on an open curve, 1 at its last vertex); "lfs" the local feature size
// there (before any noise moved the sample). A curve without "closed" is closed (files
// written before open curves existed), so closed curves are written without it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "generators/ground_truth.h"

namespace curvebench {

inline constexpr const char* kGroundTruthFormat = "curvebench-ground-truth/1";

nlohmann::ordered_json ground_truth_to_json(const GroundTruth& truth);

// Parses and checks a ground-truth JSON (format tag, sample count, indices in range);
// throws std::runtime_error "<name>: <what>" if it is malformed.
GroundTruth ground_truth_from_json(const nlohmann::ordered_json& json, const std::string& name);

// Reads and parses a ground-truth file; errors name the path.
GroundTruth read_ground_truth_file(const std::string& path);

}  // namespace curvebench
