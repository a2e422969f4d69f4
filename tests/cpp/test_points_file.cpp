// The points-file format (harness/README.md): separators, comments, line ends, and one-line errors
// that name the file and the line.
#include <gtest/gtest.h>

#include "io/points_file.h"

namespace curvebench {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_points(text, "pts.xy");
  } catch (const PointsFileError& e) {
    return e.what();
  }
  return "";
}

TEST(PointsFile, AcceptsSpacesTabsCommasAndExtraColumns) {
  const auto points = parse_points("1 2\n3\t4\n5,6\n7 , 8 , 9 extra\n  -1e3   +2.5  \n", "f");
  ASSERT_EQ(points.size(), 5u);
  EXPECT_EQ(points[2], (Point2{5, 6}));
  EXPECT_EQ(points[3], (Point2{7, 8}));
  EXPECT_EQ(points[4], (Point2{-1000, 2.5}));
}

TEST(PointsFile, CommentsAndBlankLinesAreSkipped) {
  const auto points = parse_points("# header\n\n1 2 # trailing\n   \n#3 4\n5 6", "f");
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[1], (Point2{5, 6}));
}

TEST(PointsFile, AllLineEndingsGiveTheSamePointsAndLineNumbers) {
  for (const std::string end : {"\n", "\r\n", "\r"}) {
    const std::string text = "1 2" + end + end + "3 4" + end + "5 6" + end;
    EXPECT_EQ(parse_points(text, "f").size(), 3u) << "line end " << (end == "\r" ? "CR" : end == "\n" ? "LF" : "CRLF");
    EXPECT_EQ(error_of("1 2" + end + end + "3 x" + end), "pts.xy:3: 'x' is not a number");
  }
}

TEST(PointsFile, BadLinesNameFileAndLine) {
  EXPECT_EQ(error_of("1 2\n3\n"), "pts.xy:2: expected two coordinates 'x y', found one");
  EXPECT_EQ(error_of("1 2\nabc def\n"), "pts.xy:2: 'abc' is not a number");
  EXPECT_EQ(error_of("1 nan\n"), "pts.xy:1: coordinate 'nan' is not finite");
  EXPECT_EQ(error_of("inf 1\n"), "pts.xy:1: coordinate 'inf' is not finite");
  EXPECT_EQ(error_of("1e999 1\n"), "pts.xy:1: coordinate '1e999' is out of range");
  EXPECT_EQ(error_of("1.5.2 1\n"), "pts.xy:1: '1.5.2' is not a number");
  EXPECT_EQ(error_of("0x10 1\n"), "pts.xy:1: '0x10' is not a number");
}

TEST(PointsFile, EmptyInputHasNoPoints) {
  EXPECT_TRUE(parse_points("", "f").empty());
  EXPECT_TRUE(parse_points("# only a comment\r\n", "f").empty());
}

TEST(PointsFile, MissingFileIsAnError) {
  EXPECT_THROW(read_points_file("/nonexistent/curvebench.xy"), PointsFileError);
}

}  // namespace
}  // namespace curvebench
