// Outline import: rings text, GeoJSON and SVG path data, and the errors for bad files.
#include <gtest/gtest.h>

#include <cmath>

#include "generators/closed_curves.h"
#include "generators/outline_import.h"

namespace curvebench {
namespace {

std::string error_of(const std::function<void()>& parse) {
  try {
    parse();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(OutlineImport, RingsTextSplitsOnBlankLinesAnyLineEnd) {
  for (const std::string end : {"\n", "\r\n"}) {
    const std::string text = "# square with a hole" + end + "0 0" + end + "4,0" + end + "4\t4 extra" + end + "0 4" + end + end +
                             "  " + end + "1 1" + end + "# comment inside" + end + "1 3" + end + "3 3" + end + "3 1";
    const Rings rings = parse_rings_text(text, "f.rings");
    ASSERT_EQ(rings.size(), 2u);
    EXPECT_EQ(rings[0].size(), 4u);
    EXPECT_EQ(rings[1].size(), 4u);
    EXPECT_EQ(rings[0][2], (Point2{4, 4}));
  }
  EXPECT_EQ(error_of([] { parse_rings_text("0 0\n1 0\n1 x\n", "f.rings"); }), "f.rings:3: '1 x' is not a vertex 'x y'");
  EXPECT_EQ(error_of([] { parse_rings_text("# nothing\n\n", "f.rings"); }), "f.rings: no ring (closed outline) found");
}

TEST(OutlineImport, GeoJsonPolygonsWithHoles) {
  const std::string text = R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "geometry": {"type": "MultiPolygon", "coordinates": [
      [[[0, 0], [3, 0], [3, 2], [0, 2], [0, 0]], [[1, 0.5], [1, 1.5], [2, 1.5], [2, 0.5], [1, 0.5]]],
      [[[5, 0], [6, 0], [5.5, 1], [5, 0]]]]}},
    {"type": "Feature", "geometry": {"type": "Point", "coordinates": [9, 9]}}]})";
  const Rings rings = parse_geojson(text, "g.geojson");
  ASSERT_EQ(rings.size(), 3u);
  const Scene scene = polygon_scene("g", rings, 2000);
  EXPECT_EQ(scene.curves.size(), 3u);
  EXPECT_EQ(scene.curves[2].corners.size(), 3u);
  EXPECT_NE(error_of([] { parse_geojson(R"({"type": "Point", "coordinates": [0, 0]})", "p.json"); }).find("no ring"), std::string::npos);
  EXPECT_EQ(error_of([] { parse_geojson("{oops", "p.json"); }), "p.json: not valid JSON");
}

TEST(OutlineImport, SvgPathDataAllCommands) {
  // A square (absolute, H/V), a circle from two relative arcs, a closed cubic/quadratic shape.
  const Rings rings = parse_svg_paths(
      "M10 10 H 90 V 90 H 10 Z m 20 40 a 20 20 0 1 0 40 0 a 20 20 0 1 0 -40 0 z "
      "M120,10 C 150,0 180,40 150,80 S 130,100 125,90 Q 115,70 120,50 T 120 10 z",
      "p.svg");
  ASSERT_EQ(rings.size(), 3u);
  EXPECT_EQ(rings[0][1], (Point2{90, -10}));  // y flipped
  for (const Point2 p : rings[1]) EXPECT_NEAR(std::hypot(p.x - 50, p.y + 50), 20.0, 1e-9);
  const Scene scene = polygon_scene("p.svg", rings, 4000);
  EXPECT_EQ(scene.curves[0].corners.size(), 4u);
  EXPECT_TRUE(scene.curves[1].corners.empty());  // a flattened circle turns by under 10 degrees per vertex
  // An SVG document: the d attribute of each <path>.
  const Rings from_document = parse_svg_paths(R"(<svg xmlns="http://www.w3.org/2000/svg"><g><path fill="red" d="M0 0 L 4 0 L 2 3 z"/></g>
      <path d='M10 0 l4 0 l-2 3z' stroke="blue"/></svg>)", "d.svg");
  ASSERT_EQ(from_document.size(), 2u);
  EXPECT_EQ(from_document[1][1], (Point2{14, 0}));
  EXPECT_NE(error_of([] { parse_svg_paths("M 0 0 L 1 x", "b.svg"); }).find("expected a number"), std::string::npos);
  EXPECT_NE(error_of([] { parse_svg_paths("<svg></svg>", "b.svg"); }).find("no <path"), std::string::npos);
}

TEST(OutlineImport, SelfIntersectingPolygonIsRejected) {
  const Rings bowtie = parse_rings_text("0 0\n2 2\n2 0\n0 2\n", "bow.rings");
  EXPECT_NE(error_of([&] { polygon_scene("bow.rings", bowtie); }).find("not simple"), std::string::npos);
}

}  // namespace
}  // namespace curvebench
