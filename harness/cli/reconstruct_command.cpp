#include <iostream>
#include <map>
#include <memory>
#include <stdexcept>

#include "cli/commands.h"
#include "core/registry.h"
#include "io/points_file.h"
#include "io/reconstruction_json.h"
#include "io/svg.h"

namespace curvebench {
namespace {

struct ReconstructOptions {
  std::string algorithm;
  std::string input;
  std::string output;
  std::string svg;
  std::vector<std::string> params;
  std::vector<std::string> external;
};

// name=value assignments; each value is converted to its parameter's type when resolved.
std::map<std::string, ParameterValue> parse_parameters(const std::vector<std::string>& assignments) {
  std::map<std::string, ParameterValue> params;
  for (const auto& assignment : assignments) {
    const size_t eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) throw std::runtime_error("--param '" + assignment + "' is not name=value");
    params[assignment.substr(0, eq)] = assignment.substr(eq + 1);
  }
  return params;
}

void run(const ReconstructOptions& options) {
  try {
    register_external_files(options.external);
    const Algorithm& algorithm = find_algorithm(options.algorithm);
    const auto given = parse_parameters(options.params);
    const ParameterValues resolved = resolve_parameters(algorithm.name(), algorithm.info().parameters, given);
    const std::vector<Point2> points = read_points_file(options.input);
    Reconstruction result;
    try {
      result = algorithm.reconstruct(points, given);
    } catch (const InputError& e) {
      throw std::runtime_error(options.input + ": " + e.what());
    }
    const auto json = reconstruction_to_json(algorithm.name(), resolved,
                                             {options.input, static_cast<int>(points.size())}, result);
    if (!options.svg.empty()) {
      write_file_atomically(options.svg, reconstruction_svg(points, result, algorithm.name() + ": " + options.input));
    }
    if (options.output.empty()) {
      std::cout << json.dump(2) << "\n";
    } else {
      write_file_atomically(options.output, json.dump(2) + "\n");
    }
  } catch (const std::exception& e) {
    if (!options.output.empty()) {
      try {
        write_file_atomically(options.output, error_to_json(options.algorithm, options.input, e.what()).dump(2) + "\n");
      } catch (const std::exception&) {
        // The original error is the one worth reporting.
      }
    }
    throw;
  }
}

}  // namespace

void add_reconstruct_command(CLI::App& app) {
  auto options = std::make_shared<ReconstructOptions>();
  auto* cmd = app.add_subcommand("reconstruct", "Reconstruct a curve (and medial axis, dominant points) from a points file");
  cmd->add_option("--algorithm,-a", options->algorithm, "Algorithm name (see `curvebench list`)")->default_val("labeling");
  cmd->add_option("--input,-i", options->input, "Points file: one 'x y' per line")->required();
  cmd->add_option("--output,-o", options->output, "Reconstruction JSON to write (default: print to stdout)");
  cmd->add_option("--svg", options->svg, "SVG picture of points, curve, medial axis and dominant points");
  cmd->add_option("--param,-p", options->params, "Algorithm parameter as name=value (repeatable)");
  add_external_option(*cmd, options->external);
  cmd->callback([options] { run(*options); });
}

}  // namespace curvebench
