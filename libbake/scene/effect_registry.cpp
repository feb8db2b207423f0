// The effects materials may name, and the assets each needs (see effect_registry.h).
#include "libbake/scene/effect_registry.h"

namespace mbk {

std::span<const EffectInfo> effect_registry() {
  static const std::vector<EffectInfo> effects = {mip_effect(),           toksvig_effect(),  sh_effect(),
                                                  vmf_effect(),           glints_effect(),   histogram_effect(),
                                                  crease_effect(),        colormap_effect(), colormap_height_effect(),
                                                  colormap_slope_effect()};
  return effects;
}

const EffectInfo* find_effect(std::string_view name) {
  for (const auto& e : effect_registry())
    if (e.name == name) return &e;
  return nullptr;
}

std::string known_effect_names() {
  std::string names;
  for (const auto& e : effect_registry()) names += (names.empty() ? "" : ", ") + e.name;
  return names;
}

BakeInput normal_map_input(const Material& material) { return {material.normal_map->path, material.normal_map}; }

std::string effect_file_option(JsonObjectReader& r, const std::string& key, const std::filesystem::path& folder,
                               EffectUse& use) {
  Parameter declared;
  declared.name = key;
  declared.type = ParameterType::file;
  const std::string file = read_parameter(r, declared);
  const std::filesystem::path p(file);
  use.files[key] = p.is_absolute() ? p : folder / p;
  return file;
}

}  // namespace mbk
