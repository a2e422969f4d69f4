#include "external/external_algorithm.h"

#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "io/edges_file.h"
#include "io/parameters_json.h"
#include "io/points_file.h"
#include "io/reconstruction_json.h"
#include "process/child_process.h"

namespace curvebench {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// What a child whose exec failed prints before exiting with status 127.
constexpr char kCannotRun[] = "cannot run ";

const std::set<std::string> kFilePlaceholders = {"points", "output", "vertices"};

// `text` with every {key} replaced by value_of(key), which returns nullopt for a key that is
// not a placeholder; that throws, naming `where`.
std::string fill_placeholders(const std::string& text, const std::function<std::optional<std::string>(const std::string&)>& value_of,
                              const std::string& where) {
  std::string filled;
  size_t pos = 0;
  while (pos < text.size()) {
    const size_t open = text.find('{', pos);
    if (open == std::string::npos) break;
    const size_t close = text.find('}', open);
    if (close == std::string::npos) throw std::runtime_error(where + ": '" + text + "' opens a placeholder with '{' it does not close");
    const std::string key = text.substr(open + 1, close - open - 1);
    const std::optional<std::string> value = value_of(key);
    if (!value) {
      throw std::runtime_error(where + ": '" + text + "' names {" + key +
                               "}, which is none of {points}, {output}, {vertices}, {dir} or a declared parameter");
    }
    filled += text.substr(pos, open - pos) + *value;
    pos = close + 1;
  }
  return filled + text.substr(std::min(pos, text.size()));
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// The last line of the program's output that is not blank, shortened: what a failure message quotes.
std::string last_output_line(const std::string& output) {
  size_t end = output.find_last_not_of(" \t\r\n");
  if (end == std::string::npos) return "";
  const size_t start = output.find_last_of("\r\n", end);
  std::string line = output.substr(start == std::string::npos ? 0 : start + 1, end - (start == std::string::npos ? 0 : start + 1) + 1);
  if (line.size() > 200) line = line.substr(0, 200) + "...";
  return line;
}

// A fresh directory for one run's files, removed with everything in it when the run ends.
class TemporaryDirectory {
 public:
  explicit TemporaryDirectory(const std::string& algorithm) {
    std::string pattern = (fs::temp_directory_path() / ("curvebench-" + algorithm + "-XXXXXX")).string();
    if (::mkdtemp(pattern.data()) == nullptr) {
      throw std::runtime_error(algorithm + ": cannot make a temporary directory: " + std::strerror(errno));
    }
    path_ = pattern;
  }
  ~TemporaryDirectory() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// Runs `arguments` (no shell) with standard output and error collected; throws
// ExternalProgramFailed unless it exits with status 0.
void run_program(const std::vector<std::string>& arguments, const std::string& algorithm) {
  const auto exec_program = [&] {
    ::dup2(STDOUT_FILENO, STDERR_FILENO);
    std::vector<char*> argv;
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execvp(argv[0], argv.data());
    const std::string why = kCannotRun + ("'" + arguments[0] + "': ") + std::strerror(errno) + "\n";
    [[maybe_unused]] const ssize_t ignored = ::write(STDOUT_FILENO, why.data(), why.size());
    ::_exit(127);
  };
  const ChildExit end = run_child(start_child(exec_program), ChildLimits{});  // the sweep's limits cover it from outside
  const std::string last_line = last_output_line(end.output);
  const std::string quoted = last_line.empty() ? "" : "; its last output: " + last_line;
  if (WIFSIGNALED(end.wait_status)) {
    const int signal = WTERMSIG(end.wait_status);
    throw ExternalProgramFailed(algorithm + ": the program was killed by signal " + std::to_string(signal) + " (" +
                                ::strsignal(signal) + ")" + quoted);
  }
  const int status = WEXITSTATUS(end.wait_status);
  if (status == 127 && end.output.starts_with(kCannotRun)) throw std::runtime_error(algorithm + ": " + last_line);
  if (status != 0) throw ExternalProgramFailed(algorithm + ": the program exited with status " + std::to_string(status) + quoted);
}

void require_edges_within(const std::vector<Edge>& edges, std::size_t count, const std::string& where, const std::string& of) {
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Edge& e = edges[i];
    if (e[0] < 0 || static_cast<std::size_t>(e[1]) >= count || e[0] == e[1]) {
      throw std::runtime_error(where + "[" + std::to_string(i) + "] is [" + std::to_string(e[0]) + ", " + std::to_string(e[1]) +
                               "]: not two different indices of the " + std::to_string(count) + " " + of);
    }
  }
}

// The reconstruction JSON the program wrote, checked against the declaration and the
// number of points it was given.
SiteResult site_result_from_json(const std::string& text, std::size_t points, const AlgorithmInfo& info) {
  const std::string file = info.name + ": {output}";
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error(file + ": not JSON: " + e.what());
  }
  if (!json.is_object()) throw std::runtime_error(file + ": not a JSON object");
  if (json.value("status", "ok") == "error") {
    throw std::runtime_error(info.name + ": " + json.value("message", std::string("the program reported an error")));
  }
  if (!json.contains("status")) json["status"] = "ok";  // the program need not say it
  if (!json.contains("input")) json["input"] = nlohmann::json::object();
  Reconstruction read = reconstruction_from_json(json, file);
  auto require = [&](bool present, unsigned output, const std::string& what) {
    const bool declared = (info.outputs & output) != 0;
    if (present != declared) {
      throw std::runtime_error(file + (present ? ": has " : ": has no ") + what + ", which " + info.name + " does " +
                               (present ? "not declare" : "declare"));
    }
  };
  require(read.curve_edges.has_value(), kCurve, "curve.edges");
  require(read.moved_points.has_value(), kMovedPoints, "curve.positions");
  require(read.new_curve.has_value(), kNewCurve, "curve.vertices");
  require(read.medial_axis.has_value(), kMedialAxis, "medial_axis");
  require(read.dominant_points.has_value(), kDominantPoints, "dominant_points");
  SiteResult result;
  if (read.curve_edges) require_edges_within(*read.curve_edges, points, file + ": curve.edges", "points");
  if (read.moved_points && read.moved_points->size() != points) {
    throw std::runtime_error(file + ": curve.positions has " + std::to_string(read.moved_points->size()) + " positions, not one for each of the " +
                             std::to_string(points) + " points");
  }
  if (read.new_curve) require_edges_within(read.new_curve->edges, read.new_curve->vertices.size(), file + ": curve.edges", "curve.vertices");
  if (read.medial_axis) {
    const MedialAxis& axis = *read.medial_axis;
    require_edges_within(axis.edges, axis.vertices.size(), file + ": medial_axis.edges", "medial_axis.vertices");
    if (axis.radii.size() != axis.vertices.size()) {
      throw std::runtime_error(file + ": medial_axis.radii has " + std::to_string(axis.radii.size()) + " radii for " +
                               std::to_string(axis.vertices.size()) + " vertices");
    }
  }
  if (read.dominant_points) {
    for (std::size_t i = 0; i < read.dominant_points->size(); ++i) {
      const int point = (*read.dominant_points)[i];
      if (point < 0 || static_cast<std::size_t>(point) >= points) {
        throw std::runtime_error(file + ": dominant_points[" + std::to_string(i) + "] is " + std::to_string(point) +
                                 ": not an index of the " + std::to_string(points) + " points");
      }
    }
  }
  result.curve_edges = std::move(read.curve_edges);
  result.moved_points = std::move(read.moved_points);
  result.new_curve = std::move(read.new_curve);
  result.medial_axis = std::move(read.medial_axis);
  result.dominant_points = std::move(read.dominant_points);
  return result;
}

}  // namespace

ExternalAlgorithm::ExternalAlgorithm(AlgorithmInfo info, std::vector<std::string> command, ExternalOutputFormat format,
                                     nlohmann::ordered_json declaration)
    : info_(std::move(info)), command_(std::move(command)), format_(format), declaration_(std::move(declaration)) {}

SiteResult ExternalAlgorithm::run(const Sites& sites, const ParameterValues& parameters, PhaseTimer& timer) const {
  const TemporaryDirectory work(info_.name);
  std::map<std::string, std::string> values;
  for (const auto& [name, value] : parameters.all()) values[name] = value_text(value);
  values["points"] = (work.path() / "points.xy").string();
  values["output"] = (work.path() / (format_ == ExternalOutputFormat::kEdges ? "output.edges" : "output.json")).string();
  values["vertices"] = (work.path() / "vertices.xy").string();
  std::vector<std::string> arguments;
  for (const std::string& argument : command_) {
    arguments.push_back(fill_placeholders(argument, [&](const std::string& key) -> std::optional<std::string> {
      const auto found = values.find(key);
      return found == values.end() ? std::nullopt : std::optional<std::string>(found->second);
    }, info_.name + ": command"));
  }
  write_points_file(values["points"], std::vector<Point2>(sites.points.begin(), sites.points.end()));
  timer.lap("write_input");

  run_program(arguments, info_.name);
  timer.lap("program");

  if (!fs::exists(values["output"])) throw std::runtime_error(info_.name + ": the program exited normally but wrote nothing to {output}");
  const std::string text = read_text(values["output"]);
  if (text.empty()) {
    throw std::runtime_error(info_.name + ": {output} is empty (a program that finds no edge writes a comment line, '# no edges')");
  }
  SiteResult result;
  if (format_ == ExternalOutputFormat::kReconstructionJson) {
    result = site_result_from_json(text, sites.points.size(), info_);
  } else if (info_.outputs & kNewCurve) {
    if (!fs::exists(values["vertices"])) throw std::runtime_error(info_.name + ": the program wrote no {vertices} file");
    PolylineGraph curve;
    curve.vertices = parse_points(read_text(values["vertices"]), info_.name + ": {vertices}");
    curve.edges = parse_edges(text, info_.name + ": {output}", curve.vertices.size());
    result.new_curve = std::move(curve);
  } else {
    result.curve_edges = parse_edges(text, info_.name + ": {output}", sites.points.size());
  }
  timer.lap("read_output");
  return result;
}

std::unique_ptr<ExternalAlgorithm> external_algorithm_from_json(const nlohmann::ordered_json& declaration,
                                                                const fs::path& directory, const std::string& where) {
  if (!declaration.is_object()) throw std::runtime_error(where + " must be an object declaring an external algorithm");
  auto text = [&](const char* key) {
    if (!declaration.contains(key) || !declaration.at(key).is_string() || declaration.at(key).get<std::string>().empty()) {
      throw std::runtime_error(where + "." + key + " must be a non-empty string");
    }
    return declaration.at(key).get<std::string>();
  };
  AlgorithmInfo info;
  info.name = text("name");
  const std::string at = where + " (" + info.name + ")";
  info.citation = text("citation");
  info.input = SiteInput::kDistinctPoints;
  info.outputs = outputs_from_names(declaration.contains("outputs") ? declaration.at("outputs") : Json(), at + ".outputs");
  const std::string format_name = text("output_format");
  if (format_name != "edges" && format_name != "reconstruction-json") {
    throw std::runtime_error(at + ".output_format must be \"edges\" or \"reconstruction-json\", not \"" + format_name + "\"");
  }
  const ExternalOutputFormat format = format_name == "edges" ? ExternalOutputFormat::kEdges : ExternalOutputFormat::kReconstructionJson;
  const bool curve = (info.outputs & kCurve) != 0;
  const bool new_curve = (info.outputs & kNewCurve) != 0;
  if (curve == new_curve) throw std::runtime_error(at + ".outputs must hold exactly one of \"curve\" and \"new_curve\"");
  if ((info.outputs & kMovedPoints) && !curve) throw std::runtime_error(at + ".outputs: \"moved_points\" comes with \"curve\"");
  if (format == ExternalOutputFormat::kEdges && (info.outputs & ~(kCurve | kNewCurve))) {
    throw std::runtime_error(at + ".outputs: the edges format holds only a curve; other outputs need \"reconstruction-json\"");
  }
  if (declaration.contains("collinear_input")) {
    const Json& collinear = declaration.at("collinear_input");
    if (collinear != "refused" && collinear != "reconstructed") {
      throw std::runtime_error(at + ".collinear_input must be \"refused\" or \"reconstructed\"");
    }
    info.collinear = collinear == "reconstructed" ? CollinearInput::kReconstructed : CollinearInput::kRefused;
  }
  if (declaration.contains("parameters")) {
    const Json& parameters = declaration.at("parameters");
    if (!parameters.is_array()) throw std::runtime_error(at + ".parameters must be a list");
    for (size_t i = 0; i < parameters.size(); ++i) {
      ParameterSpec spec = parameter_spec_from_json(parameters[i], at + ".parameters[" + std::to_string(i) + "]");
      if (kFilePlaceholders.contains(spec.name) || spec.name == "dir") {
        throw std::runtime_error(at + ": parameter '" + spec.name + "' has the name of a placeholder");
      }
      for (const ParameterSpec& earlier : info.parameters) {
        if (earlier.name == spec.name) throw std::runtime_error(at + ": two parameters are named '" + spec.name + "'");
      }
      info.parameters.push_back(std::move(spec));
    }
  }

  if (!declaration.contains("command") || !declaration.at("command").is_array() || declaration.at("command").empty() ||
      !std::all_of(declaration.at("command").begin(), declaration.at("command").end(), [](const Json& a) { return a.is_string(); })) {
    throw std::runtime_error(at + ".command must be a non-empty list of strings: the program and its arguments");
  }
  // {dir} is filled in now; the other placeholders are checked and kept for each run.
  std::set<std::string> used;
  std::vector<std::string> command;
  for (const Json& argument : declaration.at("command")) {
    command.push_back(fill_placeholders(argument.get<std::string>(), [&](const std::string& key) -> std::optional<std::string> {
      if (key == "dir") return (directory.empty() ? fs::current_path() : fs::absolute(directory)).lexically_normal().string();
      const bool parameter = std::any_of(info.parameters.begin(), info.parameters.end(), [&](const auto& p) { return p.name == key; });
      if (!parameter && !kFilePlaceholders.contains(key)) return std::nullopt;
      used.insert(key);
      return "{" + key + "}";
    }, at + ".command"));
  }
  for (const char* required : {"points", "output"}) {
    if (!used.contains(required)) throw std::runtime_error(at + ".command has no {" + std::string(required) + "}");
  }
  const bool needs_vertices = new_curve && format == ExternalOutputFormat::kEdges;
  if (used.contains("vertices") != needs_vertices) {
    throw std::runtime_error(at + ".command: {vertices} is for, and needed by, a \"new_curve\" in the edges format");
  }
  Json resolved = declaration;
  resolved["command"] = command;
  return std::make_unique<ExternalAlgorithm>(std::move(info), std::move(command), format, std::move(resolved));
}

}  // namespace curvebench
