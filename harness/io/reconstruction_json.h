// The reconstruction JSON (harness/README.md, "Data flow and file formats"): what
// `curvebench reconstruct --output` writes and `curvebench evaluate` reads.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/algorithm.h"

namespace curvebench {

struct ReconstructionInput {
  std::string path;
  int points = 0;
};

nlohmann::ordered_json reconstruction_to_json(const std::string& algorithm, const ParameterValues& parameters,
                                              const ReconstructionInput& input, const Reconstruction& result);

// The record written instead when reconstruction failed.
nlohmann::ordered_json error_to_json(const std::string& algorithm, const std::string& input_path,
                                     const std::string& message);

// Parses a reconstruction JSON back; throws std::runtime_error naming `name` if malformed
// or if its status is not "ok".
Reconstruction reconstruction_from_json(const nlohmann::json& json, const std::string& name);

// A reconstruction JSON file as read: the document (its algorithm, parameters and input path)
// and the reconstruction in it. Throws std::runtime_error naming the path if the file cannot
// be read, is not JSON or is not a usable reconstruction.
struct ReconstructionFile {
  nlohmann::json json;
  Reconstruction reconstruction;
};
ReconstructionFile read_reconstruction_file(const std::string& path);

}  // namespace curvebench
