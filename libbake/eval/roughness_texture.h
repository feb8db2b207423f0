// The intrinsic roughness sigma of the histogram effect at a surface point ([Shah24] Sec. 4.3.3): a constant, or a
// texture (`roughness_map`: an image whose first channel is sigma, looked up bilinearly at uv with the normal maps'
// tiling and texel conventions, libbake/image/texture_taps.h), clamped to [kMinLobeRoughness, 1]. Read at shading
// time, never baked: another roughness texture needs no rebake.
#pragma once

#include <memory>
#include <optional>

#include "libbake/core/eigen.h"
#include "libbake/image/image_io.h"

namespace mbk {

class RoughnessTexture {
 public:
  explicit RoughnessTexture(double constant) : constant_(constant) {}
  // Error(invalid_input) naming `where` when the image is empty or holds a non-finite value.
  RoughnessTexture(std::shared_ptr<const Image> image, const std::string& where);
  double at(const Vec2& uv) const;

 private:
  double constant_ = 0;
  std::shared_ptr<const Image> image_;
};

}  // namespace mbk
