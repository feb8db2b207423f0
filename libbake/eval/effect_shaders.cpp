// The table of effect shaders (see effect_shaders.h).
#include "libbake/eval/effect_shaders.h"

#include "libbake/eval/glints_effect.h"
#include "libbake/eval/colormap_effect.h"
#include "libbake/eval/crease_effect.h"
#include "libbake/eval/histogram_effect.h"
#include "libbake/eval/mip_effect.h"
#include "libbake/eval/sh_effect.h"
#include "libbake/eval/toksvig_effect.h"
#include "libbake/eval/vmf_effect.h"

namespace mbk {

std::span<const EffectShaderEntry> effect_shaders() {
  static const std::vector<EffectShaderEntry> shaders = {
      {"mip", mip_effect_shader},
      {"toksvig", toksvig_effect_shader},
      {"sh", sh_effect_shader},
      {"vmf", vmf_effect_shader},
      {"glints", glints_effect_shader},
      {"histogram", histogram_effect_shader},
      {"colormap", colormap_effect_shader},
      {"colormap-height", colormap_height_effect_shader},
      {"colormap-slope", colormap_slope_effect_shader},
      {"crease", crease_effect_shader},
  };
  return shaders;
}

const EffectShaderFactory* find_effect_shader(std::string_view effect) {
  for (const auto& s : effect_shaders())
    if (s.effect == effect) return &s.make;
  return nullptr;
}

}  // namespace mbk
