// Discontinuity curves for normal maps with discontinuities ([Parilov05] Sec. 4.1: "a collection of line
// segments representing discontinuities"): polylines in continuous texel coordinates, read from JSON or from
// the subset of SVG that vector tools write for lines.
//
// Coordinates: x to the right, y = row downwards, the map spanning [0, W] x [0, H] (texel (x, row) has its
// centre at (x + 0.5, row + 0.5)), as libbake/gen/panels.h. Points must lie in the closed map rectangle.
//
// JSON: {"curves": [{"points": [[x, y], ...], "closed": false}, ...]}; "closed" is optional (default false)
// and adds the segment from the last point back to the first. Unknown keys are errors.
//
// SVG (1.1 subset, read by svg_curves.cpp): <svg> with an optional viewBox (else width/height in user units,
// else user units are texels), mapped onto [0, W] x [0, H] by stretching each axis (preserveAspectRatio is
// ignored: as "none"); <g> groups; <path d> with the commands M L H V Z and their relative forms m l h v z
// (implicit repeated coordinates after M/m are line-tos); <polyline points>; <polygon points> (closed);
// <line x1 y1 x2 y2>. Ignored: <title>, <desc>, <metadata>, <defs>, <style> and their content, comments,
// the XML declaration, <!DOCTYPE>. Errors: any other element that draws (rect, circle, ellipse, text, use,
// image...), curve commands (C S Q T A), a transform attribute, and numbers that are not SVG numbers.
//
// Every error is one line naming the file and the element (JSON path, or SVG element and its line number):
// a point outside the map, a non-finite coordinate, a zero-length segment (two equal consecutive points;
// a closing Z or "closed" whose last point already equals the first adds no segment instead), a curve with
// fewer than two points, and a file with no curve at all.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "libbake/core/eigen.h"

namespace mbk {

// How deep SVG elements may nest (checked while reading, so that a hostile file fails fast).
inline constexpr size_t kMaxSvgNesting = 256;

struct CurvePolyline {
  std::vector<Vec2> points;  // texel coordinates; consecutive points differ
  bool closed = false;       // a segment joins the last point to the first
  std::string where;         // for error messages: "curves.json: curves[2]" or "art.svg: <path> line 7"
};

struct CurveSet {
  std::vector<CurvePolyline> curves;
};

struct CurveSegment {
  Vec2 a, b;  // directed: a -> b
};

// Reads curves from a .json or .svg file (by extension, case-insensitive) for a W x H map and checks them
// (check_curves). Throws Error: io_failure (missing/unreadable), invalid_input (syntax, the errors above),
// bad_command_line (another extension).
CurveSet load_curves(const std::filesystem::path& path, uint32_t width, uint32_t height);
CurveSet parse_json_curves(const std::string& text, const std::string& file, uint32_t width, uint32_t height);
CurveSet parse_svg_curves(const std::string& text, const std::string& file, uint32_t width, uint32_t height);

// Throws Error(invalid_input) naming the curve and point for: no curves, a curve with fewer than two points,
// a non-finite coordinate, a point outside [0, W] x [0, H], a zero-length segment.
void check_curves(const CurveSet& curves, uint32_t width, uint32_t height);

// The JSON form of a curve set (read back exactly by parse_json_curves: doubles round-trip).
nlohmann::json curves_to_json(const CurveSet& curves);

// Every segment of every curve, in file order (closing segments last in their curve).
std::vector<CurveSegment> curve_segments(const CurveSet& curves);

}  // namespace mbk
