// Curve input (libbake/crease/curve_set.h): JSON and the SVG subset, the viewBox mapping, and every error by
// name, each a one-line message naming the file and the element.
#include <gtest/gtest.h>

#include <cmath>

#include "formats/error.h"
#include "libbake/crease/curve_set.h"

namespace mbk {
namespace {

// Expects Error(invalid_input) whose message contains every fragment.
void expect_error(const std::function<void()>& f, std::initializer_list<const char*> fragments,
                  ExitCode code = ExitCode::invalid_input) {
  try {
    f();
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), code) << e.message();
    EXPECT_EQ(e.message().find('\n'), std::string::npos) << e.message();
    for (const char* f : fragments) EXPECT_NE(e.message().find(f), std::string::npos) << e.message() << " lacks " << f;
  }
}

TEST(JsonCurves, ReadsPolylinesAndClosed) {
  const CurveSet s = parse_json_curves(
      R"({"curves": [{"points": [[0, 0], [4, 2.5], [8, 8]]}, {"points": [[1, 1], [3, 1], [3, 3]], "closed": true}]})",
      "c.json", 8, 8);
  ASSERT_EQ(s.curves.size(), 2u);
  EXPECT_EQ(s.curves[0].points[1], Vec2(4, 2.5));
  EXPECT_FALSE(s.curves[0].closed);
  EXPECT_TRUE(s.curves[1].closed);
  const std::vector<CurveSegment> seg = curve_segments(s);
  ASSERT_EQ(seg.size(), 5u);  // 2 + 3 with the closing segment
  EXPECT_EQ(seg[4].a, Vec2(3, 3));
  EXPECT_EQ(seg[4].b, Vec2(1, 1));
}

TEST(JsonCurves, PointOutsideMapNamesCurveAndPoint) {
  expect_error([] { parse_json_curves(R"({"curves": [{"points": [[0, 0], [8.5, 1]]}]})", "c.json", 8, 8); },
               {"outside the 8x8 map", "c.json: curves[0], point 1"});
}

TEST(JsonCurves, MapBorderIsInside) {
  EXPECT_NO_THROW(parse_json_curves(R"({"curves": [{"points": [[0, 0], [8, 8], [0, 8]]}]})", "c.json", 8, 8));
}

TEST(JsonCurves, OverflowingNumberIsRefused) {
  // JSON text cannot spell NaN or infinity; a number that overflows double is refused by the parser.
  expect_error([] { parse_json_curves(R"({"curves": [{"points": [[0, 0], [1e999, 1]]}]})", "c.json", 8, 8); },
               {"malformed JSON", "overflow", "c.json"});
}

TEST(CheckCurves, NaNCoordinate) {
  CurveSet s;
  s.curves.push_back({{Vec2(0, 0), Vec2(std::nan(""), 1)}, false, "x.json: curves[0]"});
  expect_error([&] { check_curves(s, 8, 8); }, {"non-finite coordinate", "x.json: curves[0], point 1"});
}

TEST(JsonCurves, ZeroLengthSegment) {
  expect_error([] { parse_json_curves(R"({"curves": [{"points": [[0, 0], [2, 2], [2, 2]]}]})", "c.json", 8, 8); },
               {"zero-length segment", "c.json: curves[0], point 2"});
}

TEST(JsonCurves, SinglePointCurve) {
  expect_error([] { parse_json_curves(R"({"curves": [{"points": [[1, 1]]}]})", "c.json", 8, 8); },
               {"at least two points", "c.json: curves[0]"});
}

TEST(JsonCurves, NoCurves) {
  expect_error([] { parse_json_curves(R"({"curves": []})", "c.json", 8, 8); }, {"no curves", "c.json"});
}

TEST(JsonCurves, UnknownKeyNamesItsPath) {
  expect_error(
      [] { parse_json_curves(R"({"curves": [{"points": [[0, 0], [1, 1]], "closd": true}]})", "c.json", 8, 8); },
      {"unknown key 'closd'", "c.json: curves[0].closd"});
}

TEST(JsonCurves, DuplicateKeyNamesItsPath) {
  expect_error(
      [] {
        parse_json_curves(R"({"curves": [{"points": [[0, 0], [1, 1]], "points": [[2, 2], [3, 3]]}]})", "c.json", 8, 8);
      },
      {"duplicate key 'points'", "c.json: curves[0].points"});
}

TEST(JsonCurves, MalformedJson) {
  expect_error([] { parse_json_curves(R"({"curves": [)", "c.json", 8, 8); }, {"malformed JSON", "c.json"});
}

TEST(JsonCurves, PointNotAPair) {
  expect_error([] { parse_json_curves(R"({"curves": [{"points": [[0, 0], [1]]}]})", "c.json", 8, 8); },
               {"two numbers", "c.json: curves[0].points[1]"});
}

TEST(SvgCurves, PathAbsoluteAndRelativeCommands) {
  const CurveSet s = parse_svg_curves(
      R"(<?xml version="1.0"?><!-- drawn by hand -->
<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 16 16"><title>t</title>
  <path d="M1,1 L3 1 h2 v2 l-1-1 V1 H1 m0 4 4 0 z" />
</svg>)",
      "a.svg", 16, 16);
  ASSERT_EQ(s.curves.size(), 2u);
  const std::vector<Vec2> expected = {{1, 1}, {3, 1}, {5, 1}, {5, 3}, {4, 2}, {4, 1}, {1, 1}};
  EXPECT_EQ(s.curves[0].points, expected);
  EXPECT_FALSE(s.curves[0].closed);
  // "m0 4" is relative to the current point (1, 1); "4 0" is an implicit relative line-to; z closes.
  EXPECT_EQ(s.curves[1].points, (std::vector<Vec2>{{1, 5}, {5, 5}}));
  EXPECT_TRUE(s.curves[1].closed);
}

TEST(SvgCurves, LineToAfterCloseStartsAtSubpathStart) {
  const CurveSet s = parse_svg_curves(R"(<svg><path d="M1 1 L4 1 L4 4 Z L1 6"/></svg>)", "a.svg", 8, 8);
  ASSERT_EQ(s.curves.size(), 2u);
  EXPECT_TRUE(s.curves[0].closed);
  EXPECT_EQ(s.curves[1].points, (std::vector<Vec2>{{1, 1}, {1, 6}}));
}

TEST(SvgCurves, ViewBoxMapsToTexelGrid) {
  // viewBox 10 20 100 50 on a 32 x 16 map: x' = (x - 10) * 32 / 100, y' = (y - 20) * 16 / 50.
  const CurveSet s = parse_svg_curves(
      R"(<svg viewBox="10 20 100 50" width="400" height="200"><polyline points="10,20 110,70 60 45"/></svg>)", "a.svg",
      32, 16);
  ASSERT_EQ(s.curves.size(), 1u);
  EXPECT_EQ(s.curves[0].points, (std::vector<Vec2>{{0, 0}, {32, 16}, {16, 8}}));
}

TEST(SvgCurves, WidthHeightWithoutViewBoxScale) {
  const CurveSet s =
      parse_svg_curves(R"(<svg width="64px" height="32"><line x1="0" y1="0" x2="64" y2="32"/></svg>)", "a.svg", 16, 16);
  EXPECT_EQ(s.curves[0].points, (std::vector<Vec2>{{0, 0}, {16, 16}}));
}

TEST(SvgCurves, PolygonIsClosedAndRepeatedFirstPointAddsNoSegment) {
  const CurveSet s = parse_svg_curves(
      R"(<svg><g><polygon points="1 1 5 1 5 5 1 1"/></g><path d="M2 2 H6 V6 H2 Z"/></svg>)", "a.svg", 8, 8);
  ASSERT_EQ(s.curves.size(), 2u);
  EXPECT_EQ(curve_segments(s).size(), 3u + 4u);
}

TEST(SvgCurves, SkipsDefsAndEditorNamespaces) {
  const CurveSet s = parse_svg_curves(
      R"(<svg><defs><rect width="1" height="1"/></defs><sodipodi:namedview id="n"><inkscape:grid/></sodipodi:namedview>
<metadata><rdf:RDF/></metadata><path d="M0 0 L8 8"/></svg>)",
      "a.svg", 8, 8);
  EXPECT_EQ(s.curves.size(), 1u);
}

TEST(SvgCurves, UnsupportedElementNamesElementAndLine) {
  expect_error(
      [] { parse_svg_curves("<svg>\n<path d=\"M0 0 L1 1\"/>\n<circle id=\"c1\" r=\"2\"/></svg>", "a.svg", 8, 8); },
      {"unsupported SVG element <circle>", "a.svg: <circle id=\"c1\"> line 3"});
}

TEST(SvgCurves, UnsupportedCurveCommand) {
  expect_error([] { parse_svg_curves(R"(<svg><path d="M0 0 C1 1 2 2 3 3"/></svg>)", "a.svg", 8, 8); },
               {"unsupported SVG path command 'C'", "a.svg: <path> line 1"});
}

TEST(SvgCurves, UnsupportedTransform) {
  expect_error(
      [] { parse_svg_curves(R"svg(<svg><g transform="scale(2)"><path d="M0 0 L1 1"/></g></svg>)svg", "a.svg", 8, 8); },
      {"transform", "<g> line 1"});
}

TEST(SvgCurves, PointOutsideMapAfterViewBoxMapping) {
  expect_error(
      [] { parse_svg_curves(R"(<svg viewBox="0 0 10 10"><path id="p" d="M0 0 L11 5"/></svg>)", "a.svg", 8, 8); },
      {"outside the 8x8 map", "a.svg: <path id=\"p\"> line 1, point 1"});
}

TEST(SvgCurves, NaNCoordinate) {
  expect_error([] { parse_svg_curves(R"(<svg><polyline points="0 0 NaN 1"/></svg>)", "a.svg", 8, 8); },
               {"expected a number, found 'NaN'", "a.svg: <polyline> line 1 points"});
}

TEST(SvgCurves, OverflowingNumber) {
  expect_error([] { parse_svg_curves(R"(<svg><polyline points="0 0 1e999 1"/></svg>)", "a.svg", 8, 8); },
               {"non-finite number '1e999'", "<polyline> line 1"});
}

TEST(SvgCurves, ZeroLengthSegment) {
  expect_error([] { parse_svg_curves(R"(<svg><path d="M1 1 L2 2 l0 0"/></svg>)", "a.svg", 8, 8); },
               {"zero-length segment", "a.svg: <path> line 1, point 2"});
}

TEST(SvgCurves, OddPointCount) {
  expect_error([] { parse_svg_curves(R"(<svg><polyline points="0 0 1"/></svg>)", "a.svg", 8, 8); }, {"odd count"});
}

TEST(SvgCurves, MalformedTag) {
  expect_error([] { parse_svg_curves(R"(<svg><path d="M0 0 L1 1)", "a.svg", 8, 8); },
               {"malformed SVG", "a.svg: line 1"});
}

TEST(SvgCurves, RootMustBeSvg) {
  expect_error([] { parse_svg_curves(R"(<html><path d="M0 0 L1 1"/></html>)", "a.svg", 8, 8); },
               {"root element must be <svg>"});
}

TEST(SvgCurves, NoDrawnCurve) {
  expect_error([] { parse_svg_curves(R"(<svg><path d="M1 1"/></svg>)", "a.svg", 8, 8); }, {"no curves", "a.svg"});
}

TEST(LoadCurves, OtherExtensionIsACommandLineError) {
  expect_error([] { load_curves("curves.txt", 8, 8); }, {".json or .svg", "curves.txt"}, ExitCode::bad_command_line);
}

TEST(LoadCurves, MissingFile) {
  expect_error([] { load_curves("/nonexistent/c.json", 8, 8); }, {"c.json"}, ExitCode::io_failure);
}

}  // namespace
}  // namespace mbk
