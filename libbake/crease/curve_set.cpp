// Loading and checking discontinuity curves (see curve_set.h); the JSON and SVG readers are in
// json_curves.cpp and svg_curves.cpp.
#include "libbake/crease/curve_set.h"

#include <cmath>
#include <sstream>

#include "formats/atomic_file.h"
#include "formats/error.h"
#include "formats/file_extension.h"

namespace mbk {
namespace {

std::string point_text(const Vec2& p) {
  std::ostringstream s;
  s << "(" << p.x() << ", " << p.y() << ")";
  return s.str();
}

}  // namespace

CurveSet load_curves(const std::filesystem::path& path, uint32_t width, uint32_t height) {
  const std::string extension = lower_extension(path);
  if (extension != ".json" && extension != ".svg")
    throw Error(ExitCode::bad_command_line, "curves must be a .json or .svg file", path.string());
  const std::vector<uint8_t> bytes = read_file_bytes(path);
  const std::string text(bytes.begin(), bytes.end());
  return extension == ".json" ? parse_json_curves(text, path.string(), width, height)
                              : parse_svg_curves(text, path.string(), width, height);
}

void check_curves(const CurveSet& curves, uint32_t width, uint32_t height) {
  if (curves.curves.empty()) throw Error(ExitCode::invalid_input, "no curves in the file");
  for (const CurvePolyline& c : curves.curves) {
    if (c.points.size() < 2)
      throw Error(ExitCode::invalid_input,
                  "a curve needs at least two points, this one has " + std::to_string(c.points.size()), c.where);
    for (size_t i = 0; i < c.points.size(); ++i) {
      const Vec2& p = c.points[i];
      const std::string at = c.where + ", point " + std::to_string(i);
      if (!p.allFinite()) throw Error(ExitCode::invalid_input, "non-finite coordinate " + point_text(p), at);
      if (p.x() < 0.0 || p.y() < 0.0 || p.x() > width || p.y() > height)
        throw Error(ExitCode::invalid_input,
                    "point " + point_text(p) + " outside the " + std::to_string(width) + "x" + std::to_string(height) +
                        " map [0, " + std::to_string(width) + "] x [0, " + std::to_string(height) + "]",
                    at);
      if (i > 0 && p == c.points[i - 1])
        throw Error(ExitCode::invalid_input,
                    "zero-length segment: point " + point_text(p) + " repeats the previous one", at);
    }
  }
}

std::vector<CurveSegment> curve_segments(const CurveSet& curves) {
  std::vector<CurveSegment> out;
  for (const CurvePolyline& c : curves.curves) {
    for (size_t i = 0; i + 1 < c.points.size(); ++i) out.push_back({c.points[i], c.points[i + 1]});
    if (c.closed && c.points.size() > 2 && c.points.back() != c.points.front())
      out.push_back({c.points.back(), c.points.front()});
  }
  return out;
}

}  // namespace mbk
