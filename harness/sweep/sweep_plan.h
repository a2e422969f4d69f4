// A sweep configuration expanded into the list of runs it asks for.
//
// In:  the configuration JSON and the algorithms that may be named in it:
//   {"description": "what the sweep shows",            // optional
//    "timeout_seconds": 60,                             // per run, optional (default 60)
//    "seeds": [1, 2, 3],                                // every input is made once per seed
//    "algorithms": "all",                               // or a list of names and objects:
//       ["labeling", {"name": "alpha-shape", "parameters": {"alpha": [1, 2]}}],
//    "inputs": [{"family": ["circle", "rose"], "epsilon": [0.1, 0.2], "noise": 0},
//               {"algorithms": [...], "family": "star", ...}, ...]}
//   Each object under "inputs" is a grid of `curvebench generate` settings (option names
//   without the dashes, `_` for `-`, "shape" an object of --shape name=value): a value that
//   is a list is an axis, and the grid is the cartesian product of its axes, also inside
//   nested objects, in the order written. Algorithm parameters expand the same way. An
//   "algorithms" key inside an inputs object replaces the top-level list for that grid
//   only (parameter grids on a subset of the inputs).
// Out: the distinct inputs (settings plus "seed") and the runs, input by input, each input
//      with every algorithm and parameter combination in the order written. An input, or a
//      run (input, algorithm, parameters), that several grids produce is planned once, where
//      it first appears. Parameters are resolved against the algorithm's defaults, so a run
//      states every value it used.
// Throws std::runtime_error naming the offending part for a malformed configuration, an
// unknown algorithm or parameter.
#pragma once

#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "core/algorithm.h"

namespace curvebench {

struct SweepRun {
  int input = 0;                      // index into SweepPlan::inputs
  std::string algorithm;
  nlohmann::ordered_json parameters;  // every parameter of the algorithm, resolved
};

struct SweepPlan {
  std::string description;
  double timeout_seconds = 60;
  std::vector<nlohmann::ordered_json> inputs;  // generator settings, "seed" last
  std::vector<SweepRun> runs;
};

SweepPlan plan_sweep(const nlohmann::ordered_json& config, std::span<const Algorithm* const> algorithms);

}  // namespace curvebench
