// Reading discontinuity curves from JSON (format in curve_set.h): {"curves": [{"points": [[x, y], ...],
// "closed": bool}]}, unknown keys rejected with their JSON path.
#include <nlohmann/json.hpp>

#include "formats/error.h"
#include "libbake/crease/curve_set.h"
#include "libbake/scene/json_fields.h"

namespace mbk {

CurveSet parse_json_curves(const std::string& text, const std::string& file, uint32_t width, uint32_t height) {
  using nlohmann::json;
  const json doc = parse_json_strict(text, file);
  auto fail = [&](const std::string& what, const std::string& path) {
    throw Error(ExitCode::invalid_input, what, file + ": " + path);
  };
  if (!doc.is_object()) fail("expected an object {\"curves\": [...]}", "(root)");
  for (const auto& [key, value] : doc.items())
    if (key != "curves") fail("unknown key '" + key + "'", key);
  if (!doc.contains("curves") || !doc["curves"].is_array()) fail("expected an array of curves", "curves");
  CurveSet set;
  const json& curves = doc["curves"];
  for (size_t c = 0; c < curves.size(); ++c) {
    const std::string at = "curves[" + std::to_string(c) + "]";
    const json& curve = curves[c];
    if (!curve.is_object()) fail("expected an object {\"points\": [[x, y], ...]}", at);
    for (const auto& [key, value] : curve.items())
      if (key != "points" && key != "closed") fail("unknown key '" + key + "'", at + "." + key);
    if (!curve.contains("points") || !curve["points"].is_array()) fail("expected an array of points", at + ".points");
    CurvePolyline line;
    line.where = file + ": " + at;
    if (curve.contains("closed")) {
      if (!curve["closed"].is_boolean()) fail("expected true or false", at + ".closed");
      line.closed = curve["closed"].get<bool>();
    }
    const json& points = curve["points"];
    for (size_t i = 0; i < points.size(); ++i) {
      const json& p = points[i];
      if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
        fail("expected a point [x, y] of two numbers", at + ".points[" + std::to_string(i) + "]");
      line.points.emplace_back(p[0].get<double>(), p[1].get<double>());
    }
    set.curves.push_back(std::move(line));
  }
  if (set.curves.empty()) throw Error(ExitCode::invalid_input, "no curves in the file", file);
  check_curves(set, width, height);
  return set;
}

nlohmann::json curves_to_json(const CurveSet& curves) {
  nlohmann::json list = nlohmann::json::array();
  for (const CurvePolyline& c : curves.curves) {
    nlohmann::json points = nlohmann::json::array();
    for (const Vec2& p : c.points) points.push_back({p.x(), p.y()});
    list.push_back({{"points", points}, {"closed", c.closed}});
  }
  return {{"curves", list}};
}

}  // namespace mbk
