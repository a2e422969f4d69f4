#include "io/ground_truth_json.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace curvebench {
namespace {

nlohmann::ordered_json points_to_json(const std::vector<Point2>& points) {
  auto out = nlohmann::ordered_json::array();
  for (const Point2 p : points) out.push_back({p.x, p.y});
  return out;
}

nlohmann::ordered_json edges_to_json(const std::vector<Edge>& edges) {
  auto out = nlohmann::ordered_json::array();
  for (const Edge& e : edges) out.push_back({e[0], e[1]});
  return out;
}

struct Reader {
  const std::string& name;

  [[noreturn]] void fail(const std::string& what) const { throw std::runtime_error(name + ": " + what); }

  const nlohmann::ordered_json& field(const nlohmann::ordered_json& object, const char* key, const std::string& where) const {
    if (!object.is_object() || !object.contains(key)) fail(where + " has no \"" + key + "\"");
    return object.at(key);
  }

  double number(const nlohmann::ordered_json& value, const std::string& where) const {
    if (!value.is_number()) fail(where + " is not a number");
    return value.get<double>();
  }

  std::vector<Point2> points(const nlohmann::ordered_json& value, const std::string& where) const {
    if (!value.is_array()) fail(where + " is not an array");
    std::vector<Point2> out;
    for (const auto& p : value) {
      if (!p.is_array() || p.size() != 2) fail(where + " holds a point that is not [x, y]");
      out.push_back({number(p[0], where), number(p[1], where)});
    }
    return out;
  }

  std::vector<Edge> edges(const nlohmann::ordered_json& value, size_t vertex_count, const std::string& where) const {
    if (!value.is_array()) fail(where + " is not an array");
    std::vector<Edge> out;
    for (const auto& e : value) {
      if (!e.is_array() || e.size() != 2 || !e[0].is_number_integer() || !e[1].is_number_integer()) {
        fail(where + " holds an edge that is not [i, j]");
      }
      const long long a = e[0].get<long long>(), b = e[1].get<long long>();
      if (a < 0 || b < 0 || a >= static_cast<long long>(vertex_count) || b >= static_cast<long long>(vertex_count) || a == b) {
        fail(where + " holds edge [" + std::to_string(a) + ", " + std::to_string(b) + "] out of range");
      }
      out.push_back(make_edge(static_cast<int>(a), static_cast<int>(b)));
    }
    return out;
  }
};

}  // namespace

nlohmann::ordered_json ground_truth_to_json(const GroundTruth& truth) {
  nlohmann::ordered_json out;
  out["format"] = kGroundTruthFormat;
  out["generator"] = truth.generator;
  out["points"] = truth.samples.size();
  auto curves = nlohmann::ordered_json::array();
  for (const auto& curve : truth.curves) {
    nlohmann::ordered_json c;
    c["vertices"] = points_to_json(curve.vertices);
    c["lfs"] = curve.lfs;
    if (!curve.closed) c["closed"] = false;
    curves.push_back(std::move(c));
  }
  out["curves"] = std::move(curves);
  auto samples = nlohmann::ordered_json::array();
  for (const auto& sample : truth.samples) {
    nlohmann::ordered_json s;
    if (sample.is_outlier()) {
      s["curve"] = "outlier";
    } else {
      s["curve"] = sample.curve;
      s["parameter"] = sample.parameter;
      s["lfs"] = sample.lfs;
    }
    samples.push_back(std::move(s));
  }
  out["samples"] = std::move(samples);
  out["edges"] = edges_to_json(truth.edges);
  out["medial_axis"]["vertices"] = points_to_json(truth.medial_axis.vertices);
  out["medial_axis"]["edges"] = edges_to_json(truth.medial_axis.edges);
  out["dominant_points"] = points_to_json(truth.dominant_points);
  return out;
}

GroundTruth ground_truth_from_json(const nlohmann::ordered_json& json, const std::string& name) {
  const Reader read{name};
  const auto& format = read.field(json, "format", "the file");
  if (!format.is_string() || format.get<std::string>() != kGroundTruthFormat) {
    read.fail(std::string("not a ground-truth file (\"format\" is not \"") + kGroundTruthFormat + "\")");
  }
  GroundTruth truth;
  if (json.contains("generator")) truth.generator = json.at("generator");

  const auto& curves = read.field(json, "curves", "the file");
  if (!curves.is_array()) read.fail("\"curves\" is not an array");
  for (size_t c = 0; c < curves.size(); ++c) {
    const std::string where = "curve " + std::to_string(c);
    GroundTruthCurve curve;
    curve.vertices = read.points(read.field(curves[c], "vertices", where), where + " vertices");
    for (const auto& v : read.field(curves[c], "lfs", where)) curve.lfs.push_back(read.number(v, where + " lfs"));
    if (curve.lfs.size() != curve.vertices.size()) read.fail(where + " has " + std::to_string(curve.lfs.size()) + " lfs values for " + std::to_string(curve.vertices.size()) + " vertices");
    if (curves[c].contains("closed")) {
      if (!curves[c]["closed"].is_boolean()) read.fail(where + ": \"closed\" is not true or false");
      curve.closed = curves[c]["closed"].get<bool>();
    }
    truth.curves.push_back(std::move(curve));
  }

  const auto& samples = read.field(json, "samples", "the file");
  if (!samples.is_array()) read.fail("\"samples\" is not an array");
  for (size_t i = 0; i < samples.size(); ++i) {
    const std::string where = "sample " + std::to_string(i);
    const auto& curve = read.field(samples[i], "curve", where);
    GroundTruthSample sample;
    if (curve.is_string() && curve.get<std::string>() == "outlier") {
      truth.samples.push_back(sample);
      continue;
    }
    if (!curve.is_number_integer() || curve.get<long long>() < 0 || curve.get<long long>() >= static_cast<long long>(truth.curves.size())) {
      read.fail(where + ": \"curve\" is neither a curve index nor \"outlier\"");
    }
    sample.curve = curve.get<int>();
    sample.parameter = read.number(read.field(samples[i], "parameter", where), where + " parameter");
    sample.lfs = read.number(read.field(samples[i], "lfs", where), where + " lfs");
    truth.samples.push_back(sample);
  }
  const auto& points = read.field(json, "points", "the file");
  if (!points.is_number_integer() || points.get<long long>() != static_cast<long long>(truth.samples.size())) {
    read.fail("\"points\" does not match the number of samples");
  }

  truth.edges = read.edges(read.field(json, "edges", "the file"), truth.samples.size(), "\"edges\"");
  const auto& medial_axis = read.field(json, "medial_axis", "the file");
  truth.medial_axis.vertices = read.points(read.field(medial_axis, "vertices", "\"medial_axis\""), "medial axis vertices");
  truth.medial_axis.edges = read.edges(read.field(medial_axis, "edges", "\"medial_axis\""), truth.medial_axis.vertices.size(), "medial axis edges");
  truth.dominant_points = read.points(read.field(json, "dominant_points", "the file"), "\"dominant_points\"");
  return truth;
}

GroundTruth read_ground_truth_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::ordered_json json;  // ordered: the generator settings keep their order
  try {
    json = nlohmann::ordered_json::parse(text.str());
  } catch (const nlohmann::ordered_json::parse_error& e) {
    throw std::runtime_error(path + ": not valid JSON (" + e.what() + ")");
  }
  return ground_truth_from_json(json, path);
}

}  // namespace curvebench
