#include "generators/outline_import.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <numbers>
#include <regex>
#include <stdexcept>

namespace curvebench {
namespace {

[[noreturn]] void fail(const std::string& name, const std::string& what) { throw std::invalid_argument(name + ": " + what); }

Rings require_rings(Rings rings, const std::string& name) {
  std::erase_if(rings, [](const auto& ring) { return ring.empty(); });
  if (rings.empty()) fail(name, "no ring (closed outline) found");
  return rings;
}

// ---- rings text ------------------------------------------------------------------------

bool parse_double(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  return error == std::errc() && end == token.data() + token.size() && std::isfinite(value);
}

}  // namespace

Rings parse_rings_text(std::string_view text, const std::string& name) {
  Rings rings(1);
  int line_number = 0;
  size_t position = 0;
  while (position <= text.size()) {
    size_t end = text.find_first_of("\r\n", position);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(position, end - position);
    ++line_number;
    position = end + (end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n' ? 2 : 1);
    if (const size_t hash = line.find('#'); hash != std::string_view::npos) {
      if (line.find_first_not_of(" \t", 0) == hash) continue;  // a comment line is not a blank line
      line = line.substr(0, hash);
    }
    std::vector<std::string_view> tokens;
    for (size_t i = 0; i < line.size();) {
      const size_t start = line.find_first_not_of(" \t,", i);
      if (start == std::string_view::npos) break;
      const size_t stop = std::min(line.find_first_of(" \t,", start), line.size());
      tokens.push_back(line.substr(start, stop - start));
      i = stop;
    }
    if (tokens.empty()) {
      if (!rings.back().empty()) rings.emplace_back();
      continue;
    }
    double x = 0, y = 0;
    if (tokens.size() < 2 || !parse_double(tokens[0], x) || !parse_double(tokens[1], y)) {
      std::string message = "'";
      message.append(line).append("' is not a vertex 'x y'");
      fail(name + ":" + std::to_string(line_number), message);
    }
    rings.back().push_back({x, y});
  }
  return require_rings(std::move(rings), name);
}

// ---- GeoJSON ---------------------------------------------------------------------------

namespace {

void collect_geojson(const nlohmann::json& node, Rings& rings, const std::string& name) {
  if (!node.is_object() || !node.contains("type") || !node["type"].is_string()) fail(name, "a GeoJSON object without a \"type\"");
  const std::string type = node["type"];
  auto polygon = [&](const nlohmann::json& coordinates) {
    if (!coordinates.is_array()) fail(name, "Polygon coordinates are not an array of rings");
    for (const auto& ring : coordinates) {
      if (!ring.is_array()) fail(name, "a ring is not an array of positions");
      auto& out = rings.emplace_back();
      for (const auto& position : ring) {
        if (!position.is_array() || position.size() < 2 || !position[0].is_number() || !position[1].is_number()) {
          fail(name, "a position is not [x, y]");
        }
        out.push_back({position[0].get<double>(), position[1].get<double>()});
      }
    }
  };
  if (type == "Polygon") {
    polygon(node.value("coordinates", nlohmann::json()));
  } else if (type == "MultiPolygon") {
    const auto& coordinates = node.value("coordinates", nlohmann::json());
    if (!coordinates.is_array()) fail(name, "MultiPolygon coordinates are not an array of polygons");
    for (const auto& p : coordinates) polygon(p);
  } else if (type == "Feature") {
    if (node.contains("geometry") && !node["geometry"].is_null()) collect_geojson(node["geometry"], rings, name);
  } else if (type == "FeatureCollection") {
    for (const auto& feature : node.value("features", nlohmann::json::array())) collect_geojson(feature, rings, name);
  } else if (type == "GeometryCollection") {
    for (const auto& geometry : node.value("geometries", nlohmann::json::array())) collect_geojson(geometry, rings, name);
  }
  // Points and lines bound no region: skipped.
}

}  // namespace

Rings parse_geojson(std::string_view text, const std::string& name) {
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error&) {
    fail(name, "not valid JSON");
  }
  Rings rings;
  collect_geojson(json, rings, name);
  return require_rings(std::move(rings), name + " (no Polygon or MultiPolygon)");
}

// ---- SVG path data ---------------------------------------------------------------------

namespace {

class PathReader {
 public:
  PathReader(std::string_view data, const std::string& name, int segments) : data_(data), name_(name), segments_(segments) {}

  Rings read() {
    char command = 0;
    skip_separators();
    while (position_ < data_.size()) {
      if (std::isalpha(static_cast<unsigned char>(data_[position_]))) {
        command = data_[position_++];
      } else if (command == 0) {
        fail(name_, "path data must start with a command");
      } else if (command == 'M') {
        command = 'L';  // further pairs after a moveto are linetos
      } else if (command == 'm') {
        command = 'l';
      }
      apply(command);
      skip_separators();
    }
    close_subpath();
    return rings_;
  }

 private:
  void apply(char command) {
    const bool relative = std::islower(static_cast<unsigned char>(command));
    const Point2 origin = relative ? current_ : Point2{0, 0};
    switch (std::toupper(static_cast<unsigned char>(command))) {
      case 'M': {
        close_subpath();
        current_ = start_ = origin + point();
        rings_.emplace_back().push_back(current_);
        previous_control_ = current_;
        return;
      }
      case 'L': line_to(origin + point()); return;
      case 'H': line_to({(relative ? current_.x : 0) + number(), current_.y}); return;
      case 'V': line_to({current_.x, (relative ? current_.y : 0) + number()}); return;
      case 'C': {
        const Point2 c1 = origin + point(), c2 = origin + point(), end = origin + point();
        cubic(c1, c2, end);
        return;
      }
      case 'S': {
        const Point2 c1 = reflected_control(last_was_cubic_), c2 = origin + point(), end = origin + point();
        cubic(c1, c2, end);
        return;
      }
      case 'Q': {
        const Point2 c = origin + point(), end = origin + point();
        quadratic(c, end);
        return;
      }
      case 'T': {
        const Point2 c = reflected_control(last_was_quadratic_), end = origin + point();
        quadratic(c, end);
        return;
      }
      case 'A': {
        const double rx = number(), ry = number(), rotation = number();
        const bool large = flag(), sweep = flag();
        arc(rx, ry, rotation, large, sweep, origin + point());
        return;
      }
      case 'Z': {
        current_ = start_;
        close_subpath();
        return;
      }
      default: fail(name_, std::string("unknown path command '") + command + "'");
    }
  }

  void ensure_open_subpath() {
    if (!open_) {
      rings_.emplace_back().push_back(current_);
      open_ = true;
    }
  }
  void add(Point2 p) {
    ensure_open_subpath();
    rings_.back().push_back(p);
    current_ = p;
  }
  void line_to(Point2 p) {
    add(p);
    previous_control_ = p, last_was_cubic_ = last_was_quadratic_ = false;
  }
  void cubic(Point2 c1, Point2 c2, Point2 end) {
    const Point2 p0 = current_;
    for (int i = 1; i <= segments_; ++i) {
      const double t = static_cast<double>(i) / segments_, s = 1 - t;
      add(s * s * s * p0 + 3 * s * s * t * c1 + 3 * s * t * t * c2 + t * t * t * end);
    }
    previous_control_ = c2, last_was_cubic_ = true, last_was_quadratic_ = false;
  }
  void quadratic(Point2 c, Point2 end) {
    const Point2 p0 = current_;
    for (int i = 1; i <= segments_; ++i) {
      const double t = static_cast<double>(i) / segments_, s = 1 - t;
      add(s * s * p0 + 2 * s * t * c + t * t * end);
    }
    previous_control_ = c, last_was_quadratic_ = true, last_was_cubic_ = false;
  }
  Point2 reflected_control(bool same_kind) const { return same_kind ? 2 * current_ - previous_control_ : current_; }

  // Endpoint to centre parametrisation, SVG 1.1 appendix F.6.5.
  void arc(double rx, double ry, double rotation_degrees, bool large, bool sweep, Point2 end) {
    const Point2 start = current_;
    rx = std::abs(rx), ry = std::abs(ry);
    if (rx == 0 || ry == 0 || start == end) {
      line_to(end);
      return;
    }
    const double phi = rotation_degrees * std::numbers::pi / 180, c = std::cos(phi), s = std::sin(phi);
    const Point2 half = 0.5 * (start - end);
    const Point2 p{c * half.x + s * half.y, -s * half.x + c * half.y};
    const double lambda = (p.x * p.x) / (rx * rx) + (p.y * p.y) / (ry * ry);
    if (lambda > 1) rx *= std::sqrt(lambda), ry *= std::sqrt(lambda);
    const double numerator = rx * rx * ry * ry - rx * rx * p.y * p.y - ry * ry * p.x * p.x;
    const double denominator = rx * rx * p.y * p.y + ry * ry * p.x * p.x;
    double factor = std::sqrt(std::max(0.0, numerator / denominator));
    if (large == sweep) factor = -factor;
    const Point2 center_rotated{factor * rx * p.y / ry, -factor * ry * p.x / rx};
    const Point2 middle = 0.5 * (start + end);
    const Point2 center{c * center_rotated.x - s * center_rotated.y + middle.x, s * center_rotated.x + c * center_rotated.y + middle.y};
    auto angle = [](Point2 u, Point2 v) { return std::atan2(cross(u, v), dot(u, v)); };
    const Point2 u{(p.x - center_rotated.x) / rx, (p.y - center_rotated.y) / ry};
    const Point2 v{(-p.x - center_rotated.x) / rx, (-p.y - center_rotated.y) / ry};
    const double theta = angle({1, 0}, u);
    double delta = angle(u, v);
    if (!sweep && delta > 0) delta -= 2 * std::numbers::pi;
    if (sweep && delta < 0) delta += 2 * std::numbers::pi;
    for (int i = 1; i <= segments_; ++i) {
      const double t = theta + delta * i / segments_;
      const Point2 q{rx * std::cos(t), ry * std::sin(t)};
      add(i == segments_ ? end : Point2{c * q.x - s * q.y + center.x, s * q.x + c * q.y + center.y});
    }
    previous_control_ = current_, last_was_cubic_ = last_was_quadratic_ = false;
  }

  void close_subpath() { open_ = false; }

  void skip_separators() {
    while (position_ < data_.size() && (std::isspace(static_cast<unsigned char>(data_[position_])) || data_[position_] == ',')) ++position_;
  }
  double number() {
    skip_separators();
    // A number: sign, digits, point, digits, exponent ("1.5.5" is two numbers, as SVG says).
    size_t end = position_;
    if (end < data_.size() && (data_[end] == '+' || data_[end] == '-')) ++end;
    bool point = false;
    while (end < data_.size() && (std::isdigit(static_cast<unsigned char>(data_[end])) || (data_[end] == '.' && !point))) {
      point |= data_[end] == '.';
      ++end;
    }
    if (end < data_.size() && (data_[end] == 'e' || data_[end] == 'E')) {
      size_t exponent = end + 1;
      if (exponent < data_.size() && (data_[exponent] == '+' || data_[exponent] == '-')) ++exponent;
      if (exponent < data_.size() && std::isdigit(static_cast<unsigned char>(data_[exponent]))) {
        end = exponent;
        while (end < data_.size() && std::isdigit(static_cast<unsigned char>(data_[end]))) ++end;
      }
    }
    double value = 0;
    if (!parse_double(data_.substr(position_, end - position_), value)) {
      fail(name_, "path data: expected a number at offset " + std::to_string(position_));
    }
    position_ = end;
    skip_separators();
    return value;
  }
  bool flag() {
    skip_separators();
    if (position_ >= data_.size() || (data_[position_] != '0' && data_[position_] != '1')) {
      fail(name_, "path data: expected an arc flag 0 or 1 at offset " + std::to_string(position_));
    }
    return data_[position_++] == '1';
  }
  Point2 point() {
    const double x = number();
    return {x, number()};
  }

  std::string_view data_;
  const std::string& name_;
  int segments_;
  size_t position_ = 0;
  Rings rings_;
  Point2 current_, start_, previous_control_;
  bool open_ = false, last_was_cubic_ = false, last_was_quadratic_ = false;
};

}  // namespace

Rings parse_svg_paths(std::string_view text, const std::string& name, int segments_per_curve) {
  std::vector<std::string> path_data;
  if (text.find('<') == std::string_view::npos) {
    path_data.emplace_back(text);
  } else {
    // The d attribute of every <path> element; enough of SVG for outlines, not a full parser.
    static const std::regex path_element(R"(<path\b[^>]*?\sd\s*=\s*(["'])([^"']*)\1)", std::regex::icase);
    const std::string document(text);
    for (auto it = std::sregex_iterator(document.begin(), document.end(), path_element); it != std::sregex_iterator(); ++it) {
      path_data.push_back((*it)[2].str());
    }
    if (path_data.empty()) fail(name, "no <path d=\"...\"> element");
  }
  Rings rings;
  for (const auto& data : path_data) {
    for (auto& ring : PathReader(data, name, segments_per_curve).read()) {
      for (Point2& p : ring) p.y = -p.y;
      rings.push_back(std::move(ring));
    }
  }
  // A subpath of one point (a bare moveto) bounds nothing.
  std::erase_if(rings, [](const auto& ring) { return ring.size() < 2; });
  return require_rings(std::move(rings), name);
}

}  // namespace curvebench
