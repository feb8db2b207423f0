// Loading a baked `mip` asset into the pyramid the evaluator samples (see mip_effect.h).
#include "libbake/eval/mip_effect.h"

#include "formats/asset.h"
#include "formats/error.h"
#include "formats/mip_levels.h"
#include "libbake/eval/material_normals.h"

namespace mbk {

NormalPyramid load_mip_asset(const std::filesystem::path& file) {
  const Asset asset = Asset::open(file);
  if (asset.kind().name != "mip")
    throw Error(ExitCode::invalid_input, "expected a 'mip' asset, found '" + std::string(asset.kind().name) + "'",
                file.string());
  std::vector<LevelSize> sizes;
  if (std::string problem = parse_mip_parameters(asset.metadata()["parameters"], sizes); !problem.empty())
    throw Error(ExitCode::invalid_input, "invalid mip asset: " + problem, file.string());
  NormalPyramid pyramid;
  for (size_t k = 0; k < sizes.size(); ++k) {
    const std::string name = "level_" + std::to_string(k);
    const SectionInfo& s = asset.section(name);
    if (s.type != ElementType::f32 || s.shape != std::vector<uint64_t>{sizes[k].height, sizes[k].width, 3})
      throw Error(ExitCode::invalid_input,
                  "section '" + name + "' should be f32 [" + std::to_string(sizes[k].height) + ", " +
                      std::to_string(sizes[k].width) + ", 3]",
                  file.string());
    const std::vector<float> values = asset.read<float>(name);
    NormalMap level;
    level.width = sizes[k].width;
    level.height = sizes[k].height;
    level.texels.resize(size_t(level.width) * level.height);
    for (size_t i = 0; i < level.texels.size(); ++i)
      level.texels[i] = Vec3f(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
    pyramid.levels.push_back(std::move(level));
  }
  return pyramid;
}

ShaderPtr mip_effect_shader(const EffectShaderRequest& request) {
  if (request.mode == EvalMode::reference) return request.base;
  const std::filesystem::path& file = request.assets.at(0);
  MaterialNormals normals;
  normals.filter = NormalFilter::trilinear;
  normals.pyramid =
      request.cache.get<NormalPyramid>("mip asset|" + file.string(), [&] { return load_mip_asset(file); });
  return std::make_shared<NormalMappedShader>(
      [normals](const Vec2& uv, const UvFootprint& f) { return normals.lookup(uv, f); });
}

}  // namespace mbk
