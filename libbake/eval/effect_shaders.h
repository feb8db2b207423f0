// The evaluator side of the effects (libbake/scene/effect_registry.h is the bake side): for every effect a
// factory that builds the shader of a material naming it. A material's shader is built in the order its
// effects are listed, starting from the baseline (material_shaders.h); each factory receives the shader
// built so far as `base` and returns the material's new shader: it may ignore `base` (an effect that
// supplies its own normals, such as `mip`), wrap it (an effect that changes the colour and delegates the
// rest), or replace how light is reflected (an effect that filters the NDF).
//
// Two modes, as in renderer.h:
//   filtered   `assets` holds the effect's asset files in the order of its recipes, each already checked to
//              exist and to match its inputs; the shader filters over the pixel's footprint.
//   reference  `assets` is empty (the reference reads no assets); the shader evaluates the effect's ground
//              truth at the exact point, unfiltered (the pixel is resolved by many rays). An effect whose
//              ground truth is the raw normal map returns `base`, which is already that.
// Adding an effect: a factory <name>_effect_shader() in libbake/eval/<name>_effect.{h,cpp} and one row in
// effect_shaders() (effect_shaders.cpp). The test EffectShaders.EveryRegisteredEffectHasAShader keeps the
// two registries in step.
#pragma once

#include <filesystem>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "libbake/eval/load_cache.h"
#include "libbake/eval/material_shader.h"
#include "libbake/scene/scene.h"

namespace mbk {

enum class EvalMode { filtered, reference };

struct EffectShaderRequest {
  const Scene& scene;
  const Material& material;
  const EffectUse& use;
  EvalMode mode;
  std::vector<std::filesystem::path> assets;
  ShaderPtr base;
  LoadCache& cache;
};

using EffectShaderFactory = std::function<ShaderPtr(const EffectShaderRequest&)>;

struct EffectShaderEntry {
  std::string_view effect;
  EffectShaderFactory make;
};

std::span<const EffectShaderEntry> effect_shaders();
// nullptr when no shader is registered for the effect.
const EffectShaderFactory* find_effect_shader(std::string_view effect);

}  // namespace mbk
