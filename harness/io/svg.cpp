#include "io/svg.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <limits>

namespace curvebench {
namespace {

// printf-style append (GCC 12 has no <format>).
[[gnu::format(printf, 2, 3)]] void append(std::string& out, const char* format, ...) {
  char buffer[512];
  va_list args;
  va_start(args, format);
  const int n = std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  if (n > 0) out.append(buffer, static_cast<size_t>(std::min<int>(n, sizeof buffer - 1)));
}

std::string escape_xml(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<') out += "&lt;"; else if (c == '>') out += "&gt;"; else if (c == '&') out += "&amp;"; else out += c;
  }
  return out;
}

}  // namespace

std::string reconstruction_svg(std::span<const Point2> points, const Reconstruction& result, const std::string& title) {
  double min_x = std::numeric_limits<double>::max(), min_y = min_x;
  double max_x = std::numeric_limits<double>::lowest(), max_y = max_x;
  auto extend = [&](Point2 p) {
    min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
    min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
  };
  for (const auto& p : points) extend(p);
  const auto curve = curve_view(result, points);
  if (curve) for (const auto& p : curve->vertices) extend(p);
  if (points.empty() && !(curve && !curve->vertices.empty())) min_x = min_y = 0, max_x = max_y = 1;
  const double size = std::max({max_x - min_x, max_y - min_y, 1e-300});
  const double margin = 0.05 * size;
  const double canvas = 800.0;
  const double scale = canvas / (size + 2 * margin);
  const int legend_rows = 1 + (curve ? 1 : 0) + (result.medial_axis ? 1 : 0) + (result.dominant_points ? 1 : 0);
  const double legend_height = 16.0 * legend_rows + 8.0;  // a band above the drawing
  const double width = (max_x - min_x + 2 * margin) * scale;
  const double height = (max_y - min_y + 2 * margin) * scale + legend_height;
  auto X = [&](Point2 p) { return (p.x - min_x + margin) * scale; };
  auto Y = [&](Point2 p) { return legend_height + (max_y - p.y + margin) * scale; };  // y up
  const double point_radius = std::clamp(300.0 / std::max<double>(1.0, static_cast<double>(points.size())), 0.6, 3.0);

  std::string svg;
  append(svg, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.2f %.2f\">\n",
         width, height, width, height);
  svg += "<title>" + escape_xml(title) + "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  auto polyline_group = [&](std::span<const Edge> edges, std::span<const Point2> vertices, const char* colour,
                            double stroke) {
    append(svg, "<g stroke=\"%s\" stroke-width=\"%.1f\" stroke-linecap=\"round\">\n", colour, stroke);
    for (const auto& e : edges) {
      append(svg, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n", X(vertices[e[0]]), Y(vertices[e[0]]),
             X(vertices[e[1]]), Y(vertices[e[1]]));
    }
    svg += "</g>\n";
  };
  if (result.medial_axis) polyline_group(result.medial_axis->edges, result.medial_axis->vertices, "#1f77b4", 1.0);
  if (curve) polyline_group(curve->edges, curve->vertices, "black", 1.5);
  svg += "<g fill=\"#777\">\n";
  for (const auto& p : points) append(svg, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\"/>\n", X(p), Y(p), point_radius);
  svg += "</g>\n";
  if (result.dominant_points) {
    svg += "<g fill=\"none\" stroke=\"#d62728\" stroke-width=\"2\">\n";
    for (int i : *result.dominant_points) {
      append(svg, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\"/>\n", X(points[i]), Y(points[i]), 3 * point_radius + 3);
    }
    svg += "</g>\n";
  }
  // Legend: one line per layer present, in the band at the top.
  double legend_y = 16;
  auto legend = [&](const char* swatch, const char* label) {
    append(svg, "<g transform=\"translate(8 %.0f)\">%s<text x=\"22\" y=\"4\" font-family=\"sans-serif\" font-size=\"12\">%s</text></g>\n",
           legend_y, swatch, label);
    legend_y += 16;
  };
  legend("<circle cx=\"8\" cy=\"0\" r=\"2.5\" fill=\"#777\"/>", "input points");
  if (curve) legend("<line x1=\"0\" y1=\"0\" x2=\"16\" y2=\"0\" stroke=\"black\" stroke-width=\"1.5\"/>", "curve");
  if (result.medial_axis) legend("<line x1=\"0\" y1=\"0\" x2=\"16\" y2=\"0\" stroke=\"#1f77b4\"/>", "interior medial axis");
  if (result.dominant_points) legend("<circle cx=\"8\" cy=\"0\" r=\"5\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"2\"/>", "dominant points");
  svg += "</svg>\n";
  return svg;
}

}  // namespace curvebench
