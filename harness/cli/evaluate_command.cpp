#include <iostream>
#include <memory>
#include <stdexcept>

#include "cli/commands.h"
#include "io/evaluation_json.h"
#include "io/ground_truth_json.h"
#include "io/points_file.h"
#include "io/reconstruction_json.h"

namespace curvebench {
namespace {

struct EvaluateOptions {
  std::string truth;
  std::string result;
  std::string points;
  std::string output;
};

void run(const EvaluateOptions& options) {
  const GroundTruth truth = read_ground_truth_file(options.truth);
  const ReconstructionFile result_file = read_reconstruction_file(options.result);
  const nlohmann::json& result_json = result_file.json;
  std::string points_path = options.points;
  if (points_path.empty()) {
    if (!result_json.contains("input") || !result_json["input"].value("path", "").size()) {
      throw std::runtime_error(options.result + ": names no input points file; give --points");
    }
    points_path = result_json["input"]["path"].get<std::string>();
  }
  const std::vector<Point2> points = read_points_file(points_path);
  nlohmann::ordered_json scores;
  try {
    scores = evaluation_to_json(truth, points, result_file.reconstruction);
  } catch (const std::exception& e) {
    throw std::runtime_error(options.result + " against " + options.truth + ": " + e.what());
  }
  nlohmann::ordered_json json;
  json["truth"] = options.truth;
  json["result"] = options.result;
  json["points"] = points_path;
  json["algorithm"] = result_json.value("algorithm", "");
  json.update(scores);
  const std::string text = json.dump(2) + "\n";
  std::cout << text;
  if (!options.output.empty()) write_file_atomically(options.output, text);
}

}  // namespace

void add_evaluate_command(CLI::App& app) {
  auto options = std::make_shared<EvaluateOptions>();
  auto* cmd = app.add_subcommand("evaluate", "Score a reconstruction against its ground truth (metrics: README.md, \"Metrics\")");
  cmd->add_option("--truth,-t", options->truth, "Ground-truth JSON from `curvebench generate`")->required();
  cmd->add_option("--result,-r", options->result, "Reconstruction JSON from `curvebench reconstruct`")->required();
  cmd->add_option("--points", options->points, "Points file the reconstruction indexes (default: its input path)");
  cmd->add_option("--output,-o", options->output, "Metrics JSON to write (also printed)");
  cmd->callback([options] { run(*options); });
}

}  // namespace curvebench
