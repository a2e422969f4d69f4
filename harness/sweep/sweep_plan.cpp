#include "sweep/sweep_plan.h"

#include <map>
#include <set>
#include <stdexcept>

#include "io/parameters_json.h"

namespace curvebench {
namespace {

using Json = nlohmann::ordered_json;

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error("sweep configuration: " + what); }

// Every combination of the values of `grid`: arrays are axes, objects expand recursively.
std::vector<Json> expand_grid(const Json& grid, const std::string& where) {
  if (!grid.is_object()) fail(where + " must be an object");
  std::vector<Json> combinations{Json::object()};
  for (const auto& [key, value] : grid.items()) {
    std::vector<Json> alternatives;
    if (value.is_array()) {
      if (value.empty()) fail(where + "." + key + " is an empty list");
      for (const Json& v : value) {
        if (v.is_object()) {
          for (Json& expanded : expand_grid(v, where + "." + key)) alternatives.push_back(std::move(expanded));
        } else {
          alternatives.push_back(v);
        }
      }
    } else if (value.is_object()) {
      alternatives = expand_grid(value, where + "." + key);
    } else {
      alternatives.push_back(value);
    }
    std::vector<Json> next;
    for (const Json& partial : combinations) {
      for (const Json& alternative : alternatives) {
        Json extended = partial;
        extended[key] = alternative;
        next.push_back(std::move(extended));
      }
    }
    combinations = std::move(next);
  }
  return combinations;
}

const Algorithm& algorithm_named(std::span<const Algorithm* const> algorithms, const std::string& name) {
  for (const Algorithm* algorithm : algorithms) {
    if (algorithm->name() == name) return *algorithm;
  }
  fail("unknown algorithm '" + name + "'");
}

// (algorithm, resolved parameters) pairs in the order `entries` lists them ("all" or a list).
std::vector<std::pair<std::string, Json>> algorithm_settings(Json entries, const std::string& where,
                                                             std::span<const Algorithm* const> algorithms) {
  if (entries == "all") {
    entries = Json::array();
    for (const Algorithm* algorithm : algorithms) entries.push_back(algorithm->name());
  }
  if (!entries.is_array() || entries.empty()) fail(where + " must be \"all\" or a non-empty list");
  std::vector<std::pair<std::string, Json>> settings;
  for (const Json& entry : entries) {
    const Json object = entry.is_string() ? Json{{"name", entry}} : entry;
    if (!object.is_object() || !object.contains("name") || !object.at("name").is_string()) {
      fail("each algorithm must be a name or {\"name\": ..., \"parameters\": {...}}");
    }
    const Algorithm& algorithm = algorithm_named(algorithms, object.at("name").get<std::string>());
    const Json grid = object.contains("parameters") ? object.at("parameters") : Json::object();
    for (const Json& given : expand_grid(grid, algorithm.name() + ".parameters")) {
      try {
        const auto values = parameters_from_json(given, algorithm.name() + ".parameters");
        const ParameterValues resolved = resolve_parameters(algorithm.name(), algorithm.info().parameters, values);
        settings.emplace_back(algorithm.name(), parameters_to_json(resolved));
      } catch (const std::runtime_error& e) {
        fail(e.what());
      }
    }
  }
  return settings;
}

}  // namespace

SweepPlan plan_sweep(const nlohmann::ordered_json& config, std::span<const Algorithm* const> algorithms) {
  if (!config.is_object()) fail("must be a JSON object");
  SweepPlan plan;
  plan.description = config.value("description", "");
  if (config.contains("timeout_seconds")) {
    const Json& timeout = config.at("timeout_seconds");
    if (!timeout.is_number() || timeout.get<double>() <= 0) fail("\"timeout_seconds\" must be a positive number");
    plan.timeout_seconds = timeout.get<double>();
  }
  const Json seeds = config.contains("seeds") ? config.at("seeds") : Json::array({1});
  if (!seeds.is_array() || seeds.empty()) fail("\"seeds\" must be a non-empty list of integers");
  for (const Json& seed : seeds) {
    if (!seed.is_number_integer() || seed.get<long long>() < 0) fail("\"seeds\" must be a non-empty list of integers >= 0");
  }
  if (!config.contains("inputs") || !config.at("inputs").is_array() || config.at("inputs").empty()) {
    fail("\"inputs\" must be a non-empty list of generator settings");
  }
  const auto top_level = algorithm_settings(config.contains("algorithms") ? config.at("algorithms") : Json("all"),
                                            "\"algorithms\"", algorithms);
  // An input, or a run, that several grids produce is planned once, where it first appears.
  std::map<std::string, int> input_index;
  std::set<std::string> planned;
  for (size_t g = 0; g < config.at("inputs").size(); ++g) {
    const std::string where = "inputs[" + std::to_string(g) + "]";
    Json grid = config.at("inputs")[g];
    if (grid.is_object() && grid.contains("seed")) fail(where + " sets \"seed\"; use the top-level \"seeds\"");
    std::vector<std::pair<std::string, Json>> own;
    if (grid.is_object() && grid.contains("algorithms")) {
      own = algorithm_settings(grid.at("algorithms"), where + ".algorithms", algorithms);
      grid.erase("algorithms");
    }
    const auto& settings = own.empty() ? top_level : own;
    for (const Json& input : expand_grid(grid, where)) {
      for (const Json& seed : seeds) {
        Json seeded = input;
        seeded["seed"] = seed;
        const std::string key = nlohmann::json(seeded).dump();  // keys sorted: the order written does not matter
        auto [found, added] = input_index.emplace(key, static_cast<int>(plan.inputs.size()));
        if (added) plan.inputs.push_back(std::move(seeded));
        for (const auto& [algorithm, parameters] : settings) {
          if (!planned.insert(key + "\n" + algorithm + "\n" + parameters.dump()).second) continue;
          plan.runs.push_back({found->second, algorithm, parameters});
        }
      }
    }
  }
  return plan;
}

}  // namespace curvebench
