#include <algorithm>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <thread>

#include "cli/commands.h"
#include "core/registry.h"
#include "external/register_external_algorithms.h"
#include "generators/generate.h"
#include "io/generated_input_files.h"
#include "io/points_file.h"
#include "process/child_process.h"
#include "sweep/merge_shards.h"
#include "sweep/run_in_child_processes.h"
#include "sweep/run_sweep.h"

namespace curvebench {
namespace {

using Json = nlohmann::ordered_json;

struct SweepCommandOptions {
  std::string config;
  std::string output;
  std::string inputs;
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  bool resume = false;
  std::string shard = "0/1";
  double timeout = 0;
  long memory_limit_mb = 8192;
  bool quiet = false;
  std::vector<std::string> external;
};

// Generates the input with these settings (a sweep configuration's keys are the settings'
// field names) and writes its files.
void generate_input_files(const Json& settings, const std::string& points_path, const std::string& truth_path) {
  write_generated_input_files(generate(generator_settings_from_json(settings)), points_path, truth_path);
}

// A configuration read and expanded into its plan, with its external algorithms (its
// "external_algorithms", relative to its directory, and those of --external) registered.
struct LoadedConfiguration {
  SweepPlan plan;
  Json external_declarations = Json::array();  // what a fresh process needs to register them again
};

LoadedConfiguration load_configuration(const std::string& path, const std::vector<std::string>& external_files) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open for reading");
  Json config;
  try {
    config = Json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + ": not JSON: " + e.what());
  }
  std::vector<const ExternalAlgorithm*> external = read_external_algorithms_file(path);  // the configuration's own
  for (const std::string& file : external_files) {
    const auto from_file = read_external_algorithms_file(file);
    external.insert(external.end(), from_file.begin(), from_file.end());
  }
  LoadedConfiguration loaded;
  for (const ExternalAlgorithm* algorithm : external) loaded.external_declarations.push_back(algorithm->declaration());
  try {
    loaded.plan = plan_sweep(config, all_algorithms());
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  return loaded;
}

void parse_shard(const std::string& text, SweepOptions& options) {
  const size_t slash = text.find('/');
  try {
    size_t used = 0;
    options.shard_index = std::stoi(text.substr(0, slash), &used);
    if (slash == std::string::npos || used != slash) throw std::invalid_argument(text);
    options.shard_count = std::stoi(text.substr(slash + 1), &used);
    if (used != text.size() - slash - 1) throw std::invalid_argument(text);
  } catch (const std::logic_error&) {
    throw std::runtime_error("--shard '" + text + "' is not i/n");
  }
}

void run(const SweepCommandOptions& o) {
  const LoadedConfiguration loaded = load_configuration(o.config, o.external);
  SweepEnvironment environment;
  environment.algorithms = all_algorithms();
  environment.generate_input = generate_input_files;
  // Each run is this executable's hidden `sweep-run` subcommand, told the external algorithms.
  environment.start_fresh_process = [external = loaded.external_declarations.dump()](const std::string& spec) {
    exec_this_executable({"sweep-run", spec, "--external-declarations", external});
  };
  SweepOptions options;
  options.results_path = o.output;
  options.inputs_directory = o.inputs.empty() ? o.output + ".inputs" : o.inputs;
  options.parallel_jobs = o.jobs;
  options.resume = o.resume;
  options.timeout_seconds = o.timeout;
  options.memory_limit_mb = o.memory_limit_mb;
  options.show_progress = !o.quiet;
  parse_shard(o.shard, options);
  const SweepSummary s = run_sweep(loaded.plan, options, environment);
  std::cerr << "sweep: " << s.written_rows << " rows written to " << o.output << " (" << s.ok << " ok, " << s.errors << " error, "
            << s.timeouts << " timeout, " << s.crashes << " crash), " << s.skipped_runs << " of " << s.planned_runs
            << " runs already there, in " << s.seconds << " s\n";
}

struct MergeCommandOptions {
  std::string config;
  std::vector<std::string> shards;
  std::string output;
  std::vector<std::string> external;
};

void merge(const MergeCommandOptions& o) {
  const LoadedConfiguration loaded = load_configuration(o.config, o.external);
  write_file_atomically(o.output, merge_shards(loaded.plan, o.shards));
  std::cerr << "merge: " << loaded.plan.runs.size() << " rows from " << o.shards.size() << " shard file(s) written to " << o.output << "\n";
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepCommandOptions>();
  auto* cmd = app.add_subcommand("sweep", "Run a grid of algorithms x inputs x parameters x seeds, one JSON line per run");
  cmd->add_option("config", o->config, "Sweep configuration JSON (see harness/configs/)")->required();
  cmd->add_option("--out,-o", o->output, "Results file (JSON lines), appended to")->required();
  cmd->add_option("--jobs,-j", o->jobs, "Runs at once, each in its own process")->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_flag("--resume", o->resume, "Skip runs that already have a row in the results file");
  cmd->add_option("--shard", o->shard, "Run only slice i of n (0 <= i < n): the runs whose index is i modulo n")->capture_default_str();
  cmd->add_option("--memory-limit-mb", o->memory_limit_mb, "Resident memory per run before it is killed and recorded as a crash (0: no limit)")
      ->default_val(8192);
  cmd->add_option("--timeout", o->timeout, "Seconds per run before it is killed (default: the config's timeout_seconds)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--inputs", o->inputs, "Directory for the generated inputs (default: <out>.inputs)");
  cmd->add_flag("--quiet,-q", o->quiet, "No progress on stderr");
  add_external_option(*cmd, o->external);
  cmd->callback([o] { run(*o); });

  auto m = std::make_shared<MergeCommandOptions>();
  auto* merge_command = app.add_subcommand(
      "merge", "Merge the results files of a sweep's shards in plan order, checking every planned run is there exactly once");
  merge_command->add_option("config", m->config, "The sweep configuration the shards ran")->required();
  merge_command->add_option("shards", m->shards, "The shards' results files")->required();
  merge_command->add_option("--out,-o", m->output, "Merged results file to write")->required();
  add_external_option(*merge_command, m->external);
  merge_command->callback([m] { merge(*m); });

  // One run of a sweep, in a fresh process: what `sweep` starts for every run. Hidden from help.
  auto spec = std::make_shared<std::string>();
  auto declarations = std::make_shared<std::string>("[]");
  auto* one = app.add_subcommand("sweep-run", "One run of a sweep (started by sweep)")->group("");
  one->add_option("spec", *spec, "The run, as JSON")->required();
  one->add_option("--external-declarations", *declarations, "The sweep's external algorithms, as a JSON list of declarations");
  one->callback([spec, declarations] {
    report_child_result([&] {
      register_external_algorithms(Json::parse(*declarations), ".", "sweep-run --external-declarations");
      return perform_sweep_run(*spec, all_algorithms());
    });
  });
}

}  // namespace curvebench
