// The crease shaders (see crease_effect.h).
#include "libbake/eval/crease_effect.h"

#include <cmath>
#include <optional>

#include "formats/asset.h"
#include "formats/crease_field.h"
#include "formats/error.h"
#include "libbake/crease/crease_profile_json.h"
#include "libbake/eval/exact_crease_normals.h"
#include "libbake/image/texture_taps.h"

namespace mbk {

ShaderPtr crease_effect_shader(const EffectShaderRequest& request) {
  const std::string where = "materials." + request.material.name + ": crease";
  const nlohmann::json& options = request.use.options;
  std::optional<CreaseProfile> profile;
  if (options.contains("profile")) profile = crease_profile_from_json(options.at("profile"), where + ".profile");

  if (request.mode == EvalMode::reference) {
    const NormalMapRef& ref = *request.material.normal_map;
    const std::filesystem::path curves = request.use.files.at("curves");
    const std::string key = "exact crease|" + ref.path.string() + "|" + convention_request_name(ref.convention) +
                            (ref.repair ? "|repair|" : "|error|") + curves.string() + "|" +
                            options.value("profile", nlohmann::json()).dump();
    const auto exact = request.cache.get<ExactCreaseNormals>(key, [&] {
      LoadedNormalMap loaded = load_normal_map(ref.path, ref.load_options());
      const CurveSet set = load_curves(curves, loaded.map.width, loaded.map.height);
      return ExactCreaseNormals(std::move(loaded.map), curve_segments(set), profile);
    });
    const uint32_t w = exact->width(), h = exact->height();
    return std::make_shared<NormalMappedShader>(
        [exact, w, h](const Vec2& uv, const UvFootprint&) { return exact->normal(texel_coordinates(uv, w, h)); });
  }

  const std::filesystem::path& file = request.assets.at(0);
  const auto field = request.cache.get<CreaseField>("crease asset|" + file.string(), [&] {
    const Asset asset = Asset::open(file);
    if (asset.kind().name != "crease")
      throw Error(ExitCode::invalid_input, "expected a 'crease' asset, found '" + std::string(asset.kind().name) + "'",
                  file.string());
    return read_crease_field(asset);
  });
  return std::make_shared<NormalMappedShader>([field, profile](const Vec2& uv, const UvFootprint&) {
    const Vec2 p = texel_coordinates(uv, field->width, field->height);
    const CreaseSample s = reconstruct_crease(*field, p.x(), p.y());
    double n[3] = {s.normal[0], s.normal[1], s.normal[2]};
    if (profile) crease_normal(s, *profile, n);
    return Vec3(n[0], n[1], n[2]);
  });
}

}  // namespace mbk
