#include "io/reconstruction_json.h"

#include <fstream>
#include <stdexcept>

#include "io/parameters_json.h"

namespace curvebench {
namespace {

nlohmann::ordered_json edges_json(const std::vector<Edge>& edges) {
  auto array = nlohmann::ordered_json::array();
  for (const auto& e : edges) array.push_back({e[0], e[1]});
  return array;
}

nlohmann::ordered_json points_json(const std::vector<Point2>& points) {
  auto array = nlohmann::ordered_json::array();
  for (const auto& p : points) array.push_back({p.x, p.y});
  return array;
}

}  // namespace

nlohmann::ordered_json reconstruction_to_json(const std::string& algorithm, const ParameterValues& parameters,
                                              const ReconstructionInput& input, const Reconstruction& result) {
  nlohmann::ordered_json json;
  json["algorithm"] = algorithm;
  json["parameters"] = parameters_to_json(parameters);
  json["input"] = {{"path", input.path}, {"points", input.points}, {"distinct_points", result.distinct_points}};
  // "curve" holds edges between input points, with "positions" (one per input point) for a
  // denoising method; or, for a method with vertices of its own, "vertices" and edges between them.
  if (result.curve_edges) {
    json["curve"] = {{"edges", edges_json(*result.curve_edges)}};
    if (result.moved_points) json["curve"]["positions"] = points_json(*result.moved_points);
  } else if (result.new_curve) {
    json["curve"] = {{"vertices", points_json(result.new_curve->vertices)}, {"edges", edges_json(result.new_curve->edges)}};
  }
  if (result.medial_axis) {
    json["medial_axis"] = {{"vertices", points_json(result.medial_axis->vertices)},
                           {"radii", result.medial_axis->radii},
                           {"edges", edges_json(result.medial_axis->edges)}};
  }
  if (result.dominant_points) json["dominant_points"] = *result.dominant_points;
  json["timing_ms"] = nlohmann::ordered_json::object();
  for (const auto& [phase, ms] : result.timing_ms) json["timing_ms"][phase] = ms;
  json["status"] = "ok";
  return json;
}

nlohmann::ordered_json error_to_json(const std::string& algorithm, const std::string& input_path,
                                     const std::string& message) {
  nlohmann::ordered_json json;
  json["algorithm"] = algorithm;
  json["input"] = {{"path", input_path}};
  json["status"] = "error";
  json["message"] = message;
  return json;
}

Reconstruction reconstruction_from_json(const nlohmann::json& json, const std::string& name) {
  try {
    if (json.value("status", "") != "ok") {
      throw std::runtime_error("status is '" + json.value("status", "missing") + "', not 'ok'");
    }
    Reconstruction result;
    result.distinct_points = json.at("input").value("distinct_points", 0);
    auto read_edges = [](const nlohmann::json& array) {
      std::vector<Edge> edges;
      for (const auto& e : array) edges.push_back(make_edge(e.at(0).get<int>(), e.at(1).get<int>()));
      return edges;
    };
    auto read_points = [](const nlohmann::json& array) {
      std::vector<Point2> points;
      for (const auto& p : array) points.push_back({p.at(0).get<double>(), p.at(1).get<double>()});
      return points;
    };
    if (json.contains("curve")) {
      const auto& curve = json["curve"];
      if (curve.contains("vertices")) {
        result.new_curve = PolylineGraph{read_points(curve["vertices"]), read_edges(curve.at("edges"))};
      } else {
        result.curve_edges = read_edges(curve.at("edges"));
        if (curve.contains("positions")) result.moved_points = read_points(curve["positions"]);
      }
    }
    if (json.contains("medial_axis")) {
      const auto& axis = json["medial_axis"];
      result.medial_axis = MedialAxis{read_points(axis.at("vertices")), axis.at("radii").get<std::vector<double>>(),
                                      read_edges(axis.at("edges"))};
    }
    if (json.contains("dominant_points")) result.dominant_points = json["dominant_points"].get<std::vector<int>>();
    if (json.contains("timing_ms")) {
      for (const auto& [phase, ms] : json["timing_ms"].items()) result.timing_ms.emplace_back(phase, ms.get<double>());
    }
    return result;
  } catch (const std::exception& e) {
    throw std::runtime_error(name + ": not a usable reconstruction: " + e.what());
  }
}

ReconstructionFile read_reconstruction_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open for reading");
  ReconstructionFile file;
  try {
    file.json = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + ": not JSON: " + e.what());
  }
  file.reconstruction = reconstruction_from_json(file.json, path);
  return file;
}

}  // namespace curvebench
