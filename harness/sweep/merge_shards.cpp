#include "sweep/merge_shards.h"

#include <fstream>
#include <map>
#include <stdexcept>

#include "sweep/run_sweep.h"

namespace curvebench {
namespace {

using Json = nlohmann::ordered_json;

// How many runs a message names before it only counts the rest.
constexpr size_t kRunsNamed = 5;

std::string describe(const std::string& algorithm, const Json& parameters, const Json& input) {
  return algorithm + (parameters.empty() ? "" : " " + parameters.dump()) + " on " + input.dump();
}

// "3 runs of the plan have no row: #4 (labeling on {...}); ...", or "" when `runs` is empty.
std::string problem(const std::vector<std::string>& runs, const std::string& what_one_does, const std::string& what_several_do) {
  if (runs.empty()) return "";
  std::string text = std::to_string(runs.size()) + (runs.size() == 1 ? " run " + what_one_does : " runs " + what_several_do) + ": ";
  for (size_t i = 0; i < runs.size() && i < kRunsNamed; ++i) text += (i ? "; " : "") + runs[i];
  if (runs.size() > kRunsNamed) text += "; and " + std::to_string(runs.size() - kRunsNamed) + " more";
  return text;
}

}  // namespace

std::string merge_shards(const SweepPlan& plan, const std::vector<std::string>& shard_paths) {
  std::map<std::string, size_t> index_of_key;
  for (size_t r = 0; r < plan.runs.size(); ++r) {
    const SweepRun& run = plan.runs[r];
    index_of_key.emplace(run_key(run.algorithm, run.parameters, plan.inputs[run.input]), r);
  }
  std::vector<std::string> row_of_run(plan.runs.size());
  std::vector<std::string> where_of_run(plan.runs.size());  // file:line of the row found
  std::vector<std::string> duplicated, unplanned;
  for (const std::string& path : shard_paths) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open for reading");
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      if (line.empty()) continue;
      const std::string where = path + ":" + std::to_string(number);
      const Json row = Json::parse(line, nullptr, false);
      if (row.is_discarded() || !row.is_object() || !row.contains("algorithm") || !row["algorithm"].is_string() ||
          !row.contains("parameters") || !row.contains("input")) {
        throw std::runtime_error(where + ": not a sweep row (an interrupted shard? run it again with --resume)");
      }
      const std::string algorithm = row["algorithm"].get<std::string>();
      const auto found = index_of_key.find(run_key(algorithm, row["parameters"], row["input"]));
      if (found == index_of_key.end()) {
        unplanned.push_back(where + " (" + describe(algorithm, row["parameters"], row["input"]) + ")");
      } else if (!row_of_run[found->second].empty()) {
        duplicated.push_back("#" + std::to_string(found->second) + " (" + describe(algorithm, row["parameters"], row["input"]) + ") in " +
                             where_of_run[found->second] + " and " + where);
      } else {
        row_of_run[found->second] = line;
        where_of_run[found->second] = where;
      }
    }
  }
  std::vector<std::string> missing;
  for (size_t r = 0; r < plan.runs.size(); ++r) {
    if (row_of_run[r].empty()) missing.push_back("#" + std::to_string(r) + " (" + describe(plan.runs[r].algorithm, plan.runs[r].parameters, plan.inputs[plan.runs[r].input]) + ")");
  }
  std::string problems;
  for (const std::string& part : {problem(missing, "of the plan has no row", "of the plan have no row"),
                                  problem(duplicated, "has more than one row", "have more than one row"),
                                  problem(unplanned, "is not in the plan", "are not in the plan")}) {
    if (!part.empty()) problems += (problems.empty() ? "" : "; ") + part;
  }
  if (!problems.empty()) throw std::runtime_error("merge: " + problems);
  std::string merged;
  for (const std::string& row : row_of_run) merged += row + "\n";
  return merged;
}

}  // namespace curvebench
