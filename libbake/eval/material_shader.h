// How a material turns a visible surface point into radiance towards the viewer. Every material of a
// scene gets one MaterialShader, assembled by material_shaders.h from its normal map and its effects:
// the baseline is a NormalMappedShader (a normal per point, shaded by the scene's lights through the BRDF,
// scene_lighting.h), and each effect the material names may replace or wrap the shader built so far
// (effect_shaders.h). Shaders are immutable once built and called from many threads.
#pragma once

#include <functional>
#include <memory>

#include "libbake/eval/microfacet_brdf.h"
#include "libbake/eval/scene_lighting.h"
#include "libbake/eval/surface_frame.h"
#include "libbake/eval/uv_footprint.h"

namespace mbk {

struct ShadingContext {
  Vec3 position;
  Vec2 uv;
  UvFootprint footprint;  // the pixel's footprint in uv (filtering shaders use it; reference shaders ignore it)
  SurfaceFrame frame;     // tangent frame at the point; frame.N is the geometric normal, facing the viewer
  Vec3 to_viewer;         // unit
  const SceneLighting* lighting = nullptr;
};

class MaterialShader {
 public:
  virtual ~MaterialShader() = default;
  // Linear RGB radiance towards the viewer. `brdf` is the material's BRDF; a shader that changes the
  // material's colour passes a modified copy to the shader it wraps.
  virtual Vec3 radiance(const ShadingContext& c, const Brdf& brdf) const = 0;
  // Whether radiance() reads the footprint's normal steps (UvFootprint::dnormal_dx, dnormal_dy), which cost the
  // renderer two extra intersections per pixel step: only then does it compute them.
  virtual bool uses_normal_steps() const { return false; }
};

using ShaderPtr = std::shared_ptr<const MaterialShader>;

// A unit tangent-space normal (x = +u, y = +v, z = out) at uv for a pixel footprint.
using NormalLookup = std::function<Vec3(const Vec2& uv, const UvFootprint& footprint)>;

// Shades the normal from `lookup`, turned into world space by the frame and renormalised.
class NormalMappedShader : public MaterialShader {
 public:
  explicit NormalMappedShader(NormalLookup lookup) : lookup_(std::move(lookup)) {}
  Vec3 radiance(const ShadingContext& c, const Brdf& brdf) const override;

 private:
  NormalLookup lookup_;
};

}  // namespace mbk
