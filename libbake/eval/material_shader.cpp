// The normal-mapped shader (see material_shader.h).
#include "libbake/eval/material_shader.h"

namespace mbk {

Vec3 NormalMappedShader::radiance(const ShadingContext& c, const Brdf& brdf) const {
  const Vec3 tangent_normal = lookup_(c.uv, c.footprint);
  const ShadingPoint point{c.position, c.frame.N, c.frame.to_world(tangent_normal).normalized(), c.to_viewer};
  return shade(*c.lighting, brdf, point);
}

}  // namespace mbk
