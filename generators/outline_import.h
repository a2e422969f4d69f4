// Closed outlines from files, as rings for polygon_scene (closed_curves.h).
//
// In: the text of a file and a name for messages. Out: rings (closed polygons, the last
// vertex joining the first; a repeated closing vertex is allowed). Holes are rings like any
// other: the region is the even-odd fill. Throws std::invalid_argument "<name>: <what>"
// (with a line number for the rings format) if the text is malformed or holds no ring.
//
// parse_rings_text  one vertex "x y" per line (spaces, tabs or commas; further columns
//                   ignored; # comments); a blank line ends a ring.
// parse_geojson     Polygon and MultiPolygon geometries, bare or inside Features,
//                   FeatureCollections and GeometryCollections; every ring, holes included.
// parse_svg_paths   SVG path data (M L H V C S Q T A Z, absolute and relative), either bare
//                   or the d attributes of the <path> elements of an SVG file. Curves are
//                   flattened into `segments_per_curve` segments; y is flipped (SVG's y points
//                   down) so that outlines appear upright. Every subpath is one ring.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/point.h"

namespace curvebench {

using Rings = std::vector<std::vector<Point2>>;

Rings parse_rings_text(std::string_view text, const std::string& name);
Rings parse_geojson(std::string_view text, const std::string& name);
Rings parse_svg_paths(std::string_view text, const std::string& name, int segments_per_curve = 64);

}  // namespace curvebench
