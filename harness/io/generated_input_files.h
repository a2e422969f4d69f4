// Writes a generated input (generators/generate.h) as `curvebench generate` does: the points
// file, headed by a comment holding the settings record, and the ground-truth JSON.
//
// In:  the generated input, the points path and the ground-truth path (empty: no truth file).
// Out: the files, each written through a temporary file and a rename; nothing is written
//      before everything is ready, so a failure leaves no file.
#pragma once

#include <string>

#include "generators/generate.h"

namespace curvebench {

void write_generated_input_files(const GeneratedInput& input, const std::string& points_path, const std::string& truth_path);

}  // namespace curvebench
