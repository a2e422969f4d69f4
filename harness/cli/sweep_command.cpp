#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <thread>

#include "cli/commands.h"
#include "core/registry.h"
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
};

std::string option_value(const Json& value) { return value.is_string() ? value.get<std::string>() : value.dump(); }

// `curvebench generate` options for generator settings: {"noise_scale": "lfs"} is
// --noise-scale lfs, {"shape": {"k": 5}} is --shape k=5.
std::vector<std::string> generate_arguments(const Json& settings, const std::string& points_path, const std::string& truth_path) {
  std::vector<std::string> arguments{"curvebench", "generate"};
  for (const auto& [key, value] : settings.items()) {
    if (key == "shape" && value.is_object()) {
      for (const auto& [name, v] : value.items()) arguments.insert(arguments.end(), {"--shape", name + "=" + option_value(v)});
      continue;
    }
    std::string option = "--" + key;
    std::replace(option.begin(), option.end(), '_', '-');
    arguments.insert(arguments.end(), {option, option_value(value)});
  }
  arguments.insert(arguments.end(), {"--points", points_path, "--truth", truth_path});
  return arguments;
}

// Runs this executable's `generate` subcommand; throws with its last line on stderr if it fails.
void generate_with_this_executable(const Json& settings, const std::string& points_path, const std::string& truth_path) {
  const std::vector<std::string> arguments = generate_arguments(settings, points_path, truth_path);
  int error_pipe[2];
  if (::pipe2(error_pipe, O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    const int null_device = ::open("/dev/null", O_WRONLY);
    ::dup2(null_device, 1);
    ::dup2(error_pipe[1], 2);
    std::vector<char*> argv;
    for (const auto& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv("/proc/self/exe", argv.data());
    ::_exit(127);
  }
  ::close(error_pipe[1]);
  std::string errors;
  char buffer[4096];
  for (ssize_t n; (n = ::read(error_pipe[0], buffer, sizeof buffer)) != 0;) {
    if (n > 0) errors.append(buffer, static_cast<size_t>(n));
    else if (errno != EINTR) break;
  }
  ::close(error_pipe[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
  while (!errors.empty() && errors.back() == '\n') errors.pop_back();
  std::string message = errors.substr(errors.rfind('\n') == std::string::npos ? 0 : errors.rfind('\n') + 1);
  const std::string prefix = "curvebench: error: ";
  if (message.starts_with(prefix)) message.erase(0, prefix.size());
  throw std::runtime_error(message.empty() ? "curvebench generate failed" : message);
}

// Replaces this process with this executable's hidden `sweep-run` subcommand for one run.
void exec_sweep_run(const std::string& spec) {
  const char* argv[] = {"curvebench", "sweep-run", spec.c_str(), nullptr};
  ::execv("/proc/self/exe", const_cast<char* const*>(argv));
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
  std::ifstream in(o.config, std::ios::binary);
  if (!in) throw std::runtime_error(o.config + ": cannot open for reading");
  Json config;
  try {
    config = Json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(o.config + ": not JSON: " + e.what());
  }
  SweepEnvironment environment;
  environment.algorithms = all_algorithms();
  environment.generate_input = generate_with_this_executable;
  environment.start_fresh_process = exec_sweep_run;
  SweepPlan plan;
  try {
    plan = plan_sweep(config, environment.algorithms);
  } catch (const std::exception& e) {
    throw std::runtime_error(o.config + ": " + e.what());
  }
  SweepOptions options;
  options.results_path = o.output;
  options.inputs_directory = o.inputs.empty() ? o.output + ".inputs" : o.inputs;
  options.parallel_jobs = o.jobs;
  options.resume = o.resume;
  options.timeout_seconds = o.timeout;
  options.memory_limit_mb = o.memory_limit_mb;
  options.show_progress = !o.quiet;
  parse_shard(o.shard, options);
  const SweepSummary s = run_sweep(plan, options, environment);
  std::cerr << "sweep: " << s.written_rows << " rows written to " << o.output << " (" << s.ok << " ok, " << s.errors << " error, "
            << s.timeouts << " timeout, " << s.crashes << " crash), " << s.skipped_runs << " of " << s.planned_runs
            << " runs already there, in " << s.seconds << " s\n";
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
  cmd->callback([o] { run(*o); });

  // One run of a sweep, in a fresh process: what `sweep` starts for every run. Hidden from help.
  auto spec = std::make_shared<std::string>();
  auto* one = app.add_subcommand("sweep-run", "One run of a sweep (started by sweep)")->group("");
  one->add_option("spec", *spec, "The run, as JSON")->required();
  one->callback([spec] { report_child_result([&] { return perform_sweep_run(*spec, all_algorithms()); }); });
}

}  // namespace curvebench
