// Crease profiles from JSON (see crease_profile_json.h).
#include "libbake/crease/crease_profile_json.h"

#include <cmath>

#include "formats/error.h"

namespace mbk {

CreaseProfile crease_profile_from_json(const nlohmann::json& object, const std::string& where) {
  auto fail = [&](const std::string& what, const std::string& key) {
    throw Error(ExitCode::invalid_input, what, where + (key.empty() ? "" : "." + key));
  };
  if (!object.is_object()) fail("a crease profile must be an object", "");
  for (const auto& [key, value] : object.items())
    if (key != "kind" && key != "depth" && key != "width" && key != "table" && key != "blend_start" &&
        key != "blend_end")
      fail("unknown key '" + key + "' (known here: blend_end, blend_start, depth, kind, table, width)", key);
  auto number = [&](const char* key, double fallback) {
    if (!object.contains(key)) return fallback;
    if (!object[key].is_number() || !std::isfinite(object[key].get<double>())) fail("must be a finite number", key);
    return object[key].get<double>();
  };
  CreaseProfile p;
  if (object.contains("kind")) {
    if (!object["kind"].is_string() || !parse_crease_profile_kind(object["kind"].get<std::string>(), p.kind))
      fail("kind must be one of " + crease_profile_kind_names(), "kind");
  }
  p.depth = number("depth", 1.0);
  p.width = number("width", 2.0);
  if (!(p.width > 0.0)) fail("must be > 0 texels", "width");
  p.blend_start = number("blend_start", 0.0);
  p.blend_end = number("blend_end", p.width);
  if (p.blend_start < 0.0 || p.blend_end < p.blend_start) fail("needs 0 <= blend_start <= blend_end", "blend_end");
  if (p.kind == CreaseProfileKind::table) {
    if (!object.contains("table") || !object["table"].is_array() || object["table"].size() < 2)
      fail("kind table needs an array of at least two heights", "table");
    for (const auto& h : object["table"]) {
      if (!h.is_number() || !std::isfinite(h.get<double>())) fail("heights must be finite numbers", "table");
      p.table.push_back(h.get<double>());
    }
  } else if (object.contains("table")) {
    fail("only kind table takes a table", "table");
  }
  return p;
}

nlohmann::json crease_profile_to_json(const CreaseProfile& profile) {
  nlohmann::json j = {{"kind", crease_profile_kind_name(profile.kind)},
                      {"depth", profile.depth},
                      {"width", profile.width},
                      {"blend_start", profile.blend_start},
                      {"blend_end", profile.blend_end}};
  if (profile.kind == CreaseProfileKind::table) j["table"] = profile.table;
  return j;
}

}  // namespace mbk
