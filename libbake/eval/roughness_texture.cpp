// Constant or textured roughness (see roughness_texture.h).
#include "libbake/eval/roughness_texture.h"

#include <algorithm>
#include <cmath>

#include "formats/error.h"
#include "libbake/histogram/roughness_lobe.h"
#include "libbake/image/texture_taps.h"

namespace mbk {

RoughnessTexture::RoughnessTexture(std::shared_ptr<const Image> image, const std::string& where)
    : image_(std::move(image)) {
  if (image_->width == 0 || image_->height == 0 || image_->channels == 0)
    throw Error(ExitCode::invalid_input, "the roughness map is empty", where);
  for (uint32_t row = 0; row < image_->height; ++row)
    for (uint32_t x = 0; x < image_->width; ++x)
      if (!std::isfinite(image_->at(x, row, 0)))
        throw Error(ExitCode::invalid_input, "the roughness map holds a non-finite value",
                    where + ", texel (" + std::to_string(x) + ", " + std::to_string(row) + ")");
}

double RoughnessTexture::at(const Vec2& uv) const {
  double sigma = constant_;
  if (image_ && uv.allFinite()) {
    sigma = 0.0;
    for (const TextureTap& t : bilinear_taps(image_->width, image_->height, uv))
      sigma += t.weight * image_->at(t.x, t.row, 0);
  }
  return std::clamp(sigma, kMinLobeRoughness, 1.0);
}

}  // namespace mbk
