#include "io/generated_input_files.h"

#include "io/ground_truth_json.h"
#include "io/points_file.h"

namespace curvebench {

void write_generated_input_files(const GeneratedInput& input, const std::string& points_path, const std::string& truth_path) {
  const std::string truth_text = truth_path.empty() ? "" : ground_truth_to_json(input.truth).dump() + "\n";
  write_points_file(points_path, input.points, "curvebench generate " + input.truth.generator.dump());
  if (!truth_path.empty()) write_file_atomically(truth_path, truth_text);
}

}  // namespace curvebench
