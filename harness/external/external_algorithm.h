// Any program as an algorithm: a program that reads a points file and writes edges (or a
// reconstruction JSON), declared with a name, a citation, its typed parameters and a command
// line, and run behind the same interface as the built-in algorithms.
//
// In:  a declaration (JSON; harness/README.md, "External algorithms") and the directory of the
//      file that declares it:
//   {"name": "nn-chain", "citation": "one line",
//    "command": ["python3", "{dir}/nn_chain.py", "{points}", "{output}", "--neighbours", "{neighbours}"],
//    "outputs": ["curve"],                  // or ["new_curve"]; with the JSON format also
//                                           // "moved_points", "medial_axis", "dominant_points"
//    "output_format": "edges",              // `i j` lines (io/edges_file.h) or "reconstruction-json"
//    "parameters": [{"name": "neighbours", "type": "integer", "default": 2, "minimum": 1,
//                    "description": "one line"}]}   // as `curvebench list --json` writes them
//   Placeholders, each a whole argument or part of one (the command runs without a shell):
//   {points} the points file it reads, {output} the file it writes, {vertices} the points file
//   of its new vertices (a "new_curve" in the edges format), {dir} the declaring file's
//   directory, {<parameter>} the parameter's value as `--param` takes it.
// Out: external_algorithm_from_json: the algorithm, or std::runtime_error naming `where` and
//      what is wrong. Its reconstruct() goes through the skeleton (core/algorithm.h) with the
//      distinct input points, so the program's indices are those of the points file it is
//      given, mapped back to the caller's input. run() writes that file into a fresh
//      temporary directory, runs the program (standard output and error collected, in the
//      caller's working directory) and reads what it wrote; its phases are "write_input",
//      "program" and "read_output".
// Throws ExternalProgramFailed when the program is killed by a signal or exits with a nonzero
// status (the sweep's "crash" row), and std::runtime_error when its output is missing, empty
// or malformed, naming the file by its placeholder and the line or JSON entry (an "error" row).
// The sweep's time and memory limits (run_in_child_processes.h) cover the program too: it is
// a child of the run's process, killed with it (prctl PR_SET_PDEATHSIG) and counted in its
// resident memory (process/proc_status.h, process_tree_resident_kib).
#pragma once

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/algorithm.h"

namespace curvebench {

struct ExternalProgramFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class ExternalOutputFormat { kEdges, kReconstructionJson };

class ExternalAlgorithm final : public Algorithm {
 public:
  ExternalAlgorithm(AlgorithmInfo info, std::vector<std::string> command, ExternalOutputFormat format,
                    nlohmann::ordered_json declaration);
  const AlgorithmInfo& info() const override { return info_; }
  SiteResult run(const Sites& sites, const ParameterValues& parameters, PhaseTimer& timer) const override;
  // The declaration with {dir} filled in: what a fresh process needs to declare it again.
  const nlohmann::ordered_json& declaration() const { return declaration_; }

 private:
  AlgorithmInfo info_;
  std::vector<std::string> command_;
  ExternalOutputFormat format_;
  nlohmann::ordered_json declaration_;
};

std::unique_ptr<ExternalAlgorithm> external_algorithm_from_json(const nlohmann::ordered_json& declaration,
                                                                const std::filesystem::path& directory,
                                                                const std::string& where);

}  // namespace curvebench
